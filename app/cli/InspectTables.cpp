#include "cli/InspectReport.hpp"
#include "cli/TextTable.hpp"
#include "geometry/GeneralShape.hpp"

#include <algorithm>
#include <iterator>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace dropscope {

namespace {

using Align = TextTable::Align;

std::string optionalNumber(const std::optional<double>& value) { return value ? formatNumber(*value) : "-"; }

void writeSettings(const Scene& scene, std::ostream& out) {
    const std::string& unit = scene.unit;
    out << "scene       " << scene.origin << '\n'
        << "format      " << scene.formatVersion << '\n'
        << "unit        " << unit << '\n'
        << "wavelength  " << formatNumber(scene.wavelengthNm)
        << " nm = " << formatNumber(scene.wavelengthInSceneUnits()) << ' ' << unit << '\n'
        << "ambient     " << scene.media.at(scene.ambient).name << '\n';
}

void writeMedia(const Scene& scene, std::ostream& out) {
    TextTable table({{"id", Align::Right},
                     {"name"},
                     {"n", Align::Right},
                     {"kappa", Align::Right},
                     {"sigma", Align::Right},
                     {"absorption [1/" + scene.unit + "]", Align::Right},
                     {"dispersion"}});
    bool dispersive = false;
    for (std::size_t id = 0; id < scene.media.size(); ++id) {
        const Medium& medium = scene.media[id];
        std::string models;
        const auto add = [&](const char* key, const std::optional<SpectralFunction>& model) {
            if (model) models += (models.empty() ? "" : ", ") + std::string(key) + ": " + spectralModelText(model);
        };
        add("n", medium.nModel);
        add("kappa", medium.kappaModel);
        add("sigma", medium.sigmaModel);
        dispersive |= medium.dispersive();
        table.addRow({std::to_string(id), medium.name, formatNumber(medium.n), optionalNumber(medium.kappa),
                      optionalNumber(medium.sigma), formatNumber(medium.absorptionPerUnit),
                      models.empty() ? "-" : models});
    }
    out << "\nmedia (at " << formatNumber(scene.wavelengthNm) << " nm)\n";
    table.write(out);
    if (!dispersive) return;

    TextTable dispersion({{"medium"},
                          {"wavelength [nm]", Align::Right},
                          {"n", Align::Right},
                          {"absorption [1/" + scene.unit + "]", Align::Right}});
    for (const Medium& medium : scene.media) {
        if (!medium.dispersive()) continue;
        for (const auto& [wavelength, optics] : dispersionSamples(scene, medium)) {
            dispersion.addRow({medium.name, formatNumber(wavelength), optics ? formatNumber(optics->n) : "-",
                               optics ? formatNumber(optics->absorptionPerUnit) : "-"});
        }
    }
    out << "\ndispersive media\n";
    dispersion.write(out);
}

void writeShapes(const Scene& scene, std::ostream& out) {
    const std::string& unit = scene.unit;
    TextTable table({{"id", Align::Right},
                     {"type"},
                     {"name"},
                     {"medium"},
                     {"x [" + unit + "]"},
                     {"y [" + unit + "]"},
                     {"z [" + unit + "]"},
                     {"volume [" + unit + "^3]", Align::Right},
                     {"area [" + unit + "^2]", Align::Right}});
    for (std::size_t id = 0; id < scene.shapes.size(); ++id) {
        const Shape& shape = *scene.shapes[id];
        const Eigen::AlignedBox3d bounds = shape.bounds();
        table.addRow({std::to_string(id), shapeTypeLabel(shape),
                      scene.shapeNames[id].empty() ? "-" : scene.shapeNames[id], scene.mediumOf(shape).name,
                      formatRange(bounds.min().x(), bounds.max().x()), formatRange(bounds.min().y(), bounds.max().y()),
                      formatRange(bounds.min().z(), bounds.max().z()), formatNumber(shape.volume()),
                      formatNumber(shape.surfaceArea())});
    }
    out << "\nshapes\n";
    table.write(out);
}

void writeTotals(const Scene& scene, const SceneSummary& summary, std::ostream& out) {
    const std::string& unit = scene.unit;
    std::string byType;
    for (const auto& [type, count] : summary.shapesByType) {
        if (count == 0) continue;
        byType += (byType.empty() ? "" : ", ") + std::to_string(count) + " " + type;
    }
    out << "\ntotals\n"
        << "  shapes        " << scene.shapes.size() << (byType.empty() ? "" : " (" + byType + ")") << '\n'
        << "  volume        " << formatNumber(summary.totalVolume) << ' ' << unit << "^3\n"
        << "  surface area  " << formatNumber(summary.totalSurfaceArea) << ' ' << unit << "^2\n"
        << "  bounds        ";
    if (const auto& bounds = summary.bounds) {
        out << "x " << formatRange(bounds->min().x(), bounds->max().x()) << ", y "
            << formatRange(bounds->min().y(), bounds->max().y()) << ", z "
            << formatRange(bounds->min().z(), bounds->max().z()) << ' ' << unit << '\n';
    } else {
        out << "-\n";
    }
}

// "unpolarised", "linear 30 deg from (0, 1, 0)", "stokes [1, 0, 0, 1] in (1, 0, 0)".
std::string polarisationText(const SourcePolarisation& polarisation) {
    switch (polarisation.kind) {
    case PolarisationKind::Unpolarised: return "unpolarised";
    case PolarisationKind::Linear:
        return "linear " + formatNumber(polarisation.linearDeg) + " deg from " + formatVector(polarisation.reference);
    case PolarisationKind::Stokes: {
        const StokesVector& s = polarisation.stokes;
        return "stokes [" + formatNumber(s[0]) + ", " + formatNumber(s[1]) + ", " + formatNumber(s[2]) + ", " +
               formatNumber(s[3]) + "] in " + formatVector(polarisation.reference);
    }
    }
    return "?";
}

void writeSources(const Scene& scene, std::ostream& out) {
    TextTable table({{"id", Align::Right},
                     {"type"},
                     {"origin"},
                     {"direction"},
                     {"radius [" + scene.unit + "]", Align::Right},
                     {"polarisation"},
                     {"spectrum"}});
    for (std::size_t id = 0; id < scene.sources.size(); ++id) {
        const Source& source = scene.sources[id];
        table.addRow({std::to_string(id), std::string(sourceTypeName(source.type)), formatVector(source.origin),
                      source.type == SourceType::PointSource ? "-" : formatVector(source.direction),
                      source.type == SourceType::Beam ? formatNumber(source.radius) : "-",
                      polarisationText(source.polarisation), spectrumText(source)});
    }
    out << "\nsources\n";
    table.write(out);
}

// "0:12 1:40 2:7": leaves by the number of shapes they hold, empty buckets left out.
std::string histogram(const std::vector<std::size_t>& counts) {
    std::ostringstream text;
    for (std::size_t k = 0; k < counts.size(); ++k) {
        if (counts[k] == 0) continue;
        if (text.tellp() > 0) text << ' ';
        text << k << ':' << counts[k];
    }
    return text.tellp() > 0 ? text.str() : "-";
}

void writeOctree(const SceneSummary& summary, std::ostream& out) {
    const OctreeSummary& octree = summary.octree;
    out << "\noctree (max_depth " << octree.settings.maxDepth << ", max_shapes_per_leaf "
        << octree.settings.maxShapesPerLeaf << ")\n"
        << "  root          x " << formatRange(octree.root.min().x(), octree.root.max().x()) << ", y "
        << formatRange(octree.root.min().y(), octree.root.max().y()) << ", z "
        << formatRange(octree.root.min().z(), octree.root.max().z()) << '\n'
        << "  cell margin   " << formatNumber(octree.margin) << '\n'
        << "  bytes         " << octree.bytes << '\n';
    TextTable table({{"level", Align::Right},
                     {"cells", Align::Right},
                     {"leaves", Align::Right},
                     {"shapes stored", Align::Right},
                     {"bytes", Align::Right},
                     {"leaves by shape count"}});
    for (const LevelStatistics& level : octree.levels) {
        table.addRow({std::to_string(level.level), std::to_string(level.cells), std::to_string(level.leaves),
                      std::to_string(level.shapesStored), std::to_string(level.bytes), histogram(level.shapesPerLeaf)});
    }
    table.write(out);
}

}  // namespace

std::vector<double> inspectWavelengthsNm(const Scene& scene) {
    std::vector<double> wavelengths;
    for (const Source& source : scene.sources) {
        if (!source.spectrum || source.spectrum->kind() != Spectrum::Kind::Lines) continue;
        for (const auto& line : source.spectrum->pointsNm()) wavelengths.push_back(line.first);
    }
    if (wavelengths.empty()) return {std::begin(kInspectWavelengthsNm), std::end(kInspectWavelengthsNm)};
    std::sort(wavelengths.begin(), wavelengths.end());
    wavelengths.erase(std::unique(wavelengths.begin(), wavelengths.end()), wavelengths.end());
    return wavelengths;
}

std::vector<DispersionSample> dispersionSamples(const Scene& scene, const Medium& medium) {
    std::vector<DispersionSample> samples;
    for (const double wavelength : inspectWavelengthsNm(scene)) {
        DispersionSample sample{wavelength, std::nullopt};
        try {
            sample.optics = mediumOpticsAt(medium, wavelength, scene.unitInMetres);
        } catch (const std::logic_error&) {  // outside a model's range: no values
        }
        samples.push_back(sample);
    }
    return samples;
}

std::string spectralModelText(const std::optional<SpectralFunction>& model) {
    if (!model) return "-";
    switch (model->kind()) {
    case SpectralFunction::Kind::Constant: return formatNumber(model->constantValue());
    case SpectralFunction::Kind::Table: return "table (" + std::to_string(model->tablePointsNm().size()) + " points)";
    case SpectralFunction::Kind::Cauchy: return "cauchy (" + std::to_string(model->coefficients().size()) + " terms)";
    case SpectralFunction::Kind::Sellmeier:
        return "sellmeier (" + std::to_string(model->coefficients().size()) + " terms)";
    case SpectralFunction::Kind::Builtin:
        return "builtin " + materialName(model->material()) +
               (model->material() == Material::Water && model->quantity() == OpticalQuantity::N
                    ? " (" + formatNumber(model->temperatureC()) + " C)"
                    : "");
    }
    return "?";
}

std::string spectrumText(const Source& source) {
    std::string text = "scene line";
    if (source.spectrum) {
        const Spectrum& spectrum = *source.spectrum;
        const auto [lo, hi] = spectrum.rangeNm();
        text = std::string(spectrumKindName(spectrum.kind()));
        text += ' ';
        text += formatNumber(lo);
        if (lo != hi) text += '-' + formatNumber(hi);
        text += " nm";
        if (spectrum.kind() == Spectrum::Kind::Lines) text += " (" + std::to_string(spectrum.pointsNm().size()) + ")";
        if (spectrum.kind() == Spectrum::Kind::Blackbody) text += " at " + formatNumber(spectrum.kelvin()) + " K";
    }
    if (source.divergenceDeg > 0.0) text += ", divergence " + formatNumber(source.divergenceDeg) + " deg";
    return text;
}

void writeInspectTables(const Scene& scene, const SceneSummary& summary, std::ostream& out) {
    writeSettings(scene, out);
    writeMedia(scene, out);
    writeShapes(scene, out);
    writeTotals(scene, summary, out);
    writeSources(scene, out);
    writeOctree(summary, out);
}

}  // namespace dropscope
