#include "results/TraceFiles.hpp"

#include "results/AtomicFile.hpp"
#include "results/ImagePng.hpp"
#include "results/PathsJsonl.hpp"
#include "results/ResultsHdf5.hpp"
#include "results/SummaryJson.hpp"
#include "results/TableCsv.hpp"
#include "results/Version.hpp"

namespace dropscope {

std::string_view fresnelModelName(FresnelModel model) { return model == FresnelModel::Schlick ? "schlick" : "exact"; }

ResultReport traceReport(const TraceResult& result, const TraceRunInfo& info) {
    ResultReport report;
    report.set({"photons"}, result.photons);
    report.set({"seed"}, info.settings.seed);
    report.set({"ranks"}, static_cast<std::uint64_t>(result.ranks));
    report.set({"threads"}, static_cast<std::uint64_t>(result.threads));
    report.set({"seconds"}, result.seconds);
    report.set({"photons_requested"}, result.requested);
    report.set({"partial"}, result.partial);
    report.set({"scene"}, info.scenePath);
    report.set({"fresnel"}, std::string(fresnelModelName(info.settings.transport.fresnel)));
    report.set({"polarisation"}, std::string(polarisationModelName(info.settings.transport.polarisation)));
    report.set({"diffraction"}, std::string(diffractionModelName(info.settings.transport.diffraction)));
    report.set({"max_events"}, static_cast<std::uint64_t>(info.settings.transport.maxEvents));
    report.set({"paths"}, static_cast<std::uint64_t>(result.paths.size()));
    report.set({"max_lost"}, info.maxLost ? SummaryValue(*info.maxLost) : SummaryValue(nullptr));
    report.set({"sources"}, static_cast<std::uint64_t>(info.sourceCount));
    report.set({"version"}, std::string(dropscopeVersion()));
    if (info.sceneWavelengthNm > 0.0) report.set({"wavelength_nm"}, info.sceneWavelengthNm);
    for (std::size_t i = 0; i < info.sources.size(); ++i) {
        const Source& source = info.sources[i];
        const Spectrum spectrum = sourceSpectrum(source, info.sceneWavelengthNm);
        const std::string key = std::to_string(i);
        const auto [lo, hi] = spectrum.rangeNm();
        report.set({"spectra", key, "spectrum"},
                   std::string(source.spectrum ? spectrumKindName(spectrum.kind()) : "scene"));
        report.set({"spectra", key, "lo_nm"}, lo);
        report.set({"spectra", key, "hi_nm"}, hi);
        if (spectrum.kind() == Spectrum::Kind::Lines) {
            report.set({"spectra", key, "lines"}, static_cast<std::uint64_t>(spectrum.pointsNm().size()));
        }
        if (spectrum.kind() == Spectrum::Kind::Blackbody || spectrum.kind() == Spectrum::Kind::Sun) {
            report.set({"spectra", key, "kelvin"}, spectrum.kelvin());
        }
        report.set({"spectra", key, "divergence_deg"}, source.divergenceDeg);
    }
    result.tallies.report(report);
    return report;
}

void writeTraceSummary(const ResultReport& report, std::ostream& out) {
    // docs/cli.md's order: scripts that diff summaries across versions see the same file.
    static const std::vector<std::string_view> kKeyOrder{"photons",
                                                         "seed",
                                                         "ranks",
                                                         "threads",
                                                         "seconds",
                                                         "fractions",
                                                         "events",
                                                         "photons_requested",
                                                         "partial",
                                                         "scene",
                                                         "bins",
                                                         "fresnel",
                                                         "polarisation",
                                                         "diffraction",
                                                         "max_events",
                                                         "paths",
                                                         "counts",
                                                         "lost_reasons",
                                                         "lost_warning",
                                                         "first_lost",
                                                         "max_lost",
                                                         "sources",
                                                         "wavelength_nm",
                                                         "wavelength_bins",
                                                         "spectra",
                                                         "single_scattering",
                                                         "multiple_scattering",
                                                         "budget",
                                                         "version",
                                                         "detectors"};
    writeSummaryJson(report, kKeyOrder, out);
}

std::vector<std::string> traceFileNames(const TallySet& tallies) {
    ResultReport report;
    tallies.emptyCopy().report(report);
    std::vector<std::string> names{"summary.json"};
    for (const ResultTable& table : report.tables()) names.push_back(table.name + ".csv");
    for (const ResultImage& image : report.images()) names.push_back(image.name + ".png");
    names.push_back("paths.jsonl");
    names.push_back("results.h5");
    return names;
}

void writeTraceFiles(const std::filesystem::path& directory, const TraceResult& result, const TraceRunInfo& info,
                     const std::vector<Medium>& media) {
    const ResultReport report = traceReport(result, info);
    std::vector<FileToWrite> files;
    for (const ResultTable& table : report.tables()) {
        files.push_back({directory / (table.name + ".csv"), [&](std::ostream& out) { writeTableCsv(table, out); }});
    }
    for (const ResultImage& image : report.images()) {
        files.push_back({directory / (image.name + ".png"), [&](std::ostream& out) { writeImagePng(image, out); }});
    }
    files.push_back({directory / "paths.jsonl", [&](std::ostream& out) { writePathsJsonl(result.paths, media, out); }});
    files.push_back({directory / "results.h5", [&](std::ostream& out) {
                         writeResultsHdf5(report, {std::string(dropscopeVersion()), info.sceneJson}, out);
                     }});
    // Renamed last: a summary.json is only ever beside the files of its own run.
    files.push_back({directory / "summary.json", [&](std::ostream& out) { writeTraceSummary(report, out); }});
    writeFilesAtomically(files);
}

}  // namespace dropscope
