#include "scene/Source.hpp"

#include "optics/OpticsTolerance.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace dropscope {

std::string_view sourceTypeName(SourceType type) {
    switch (type) {
    case SourceType::Beam: return "beam";
    case SourceType::Ray: return "ray";
    case SourceType::PointSource: return "point";
    }
    return "unknown";
}

StokesVector SourcePolarisation::unitStokes() const {
    switch (kind) {
    case PolarisationKind::Unpolarised: return unpolarisedStokes();
    case PolarisationKind::Linear: {
        const double twice = 2.0 * linearDeg * (std::numbers::pi / 180.0);
        return {1.0, std::cos(twice), std::sin(twice), 0.0};
    }
    case PolarisationKind::Stokes: {
        StokesVector unit = stokes / stokes[0];
        // Within the slack checkPolarisation allows, a state just outside the sphere is put on it.
        const double degree = unit.tail<3>().norm();
        if (degree > 1.0) unit.tail<3>() /= degree;
        return unit;
    }
    }
    return unpolarisedStokes();
}

namespace {

std::string shortText(double value) {
    std::ostringstream text;
    text.precision(3);
    text << value;
    return text.str();
}

}  // namespace

void checkPolarisationReference(const Eigen::Vector3d& reference, const Direction& direction) {
    const Direction unit(reference);  // normalised without overflow or underflow; invalid for zero or non-finite
    if (!unit) throw std::invalid_argument("must be a finite, non-zero vector");
    const double cosine = std::abs(unit.dot(direction.vector()));
    if (cosine > tolerance::kReferencePerpendicularCosine) {
        throw std::invalid_argument("must be perpendicular to the direction (their cosine is " + shortText(cosine) +
                                    ")");
    }
}

void checkPolarisationStokes(const StokesVector& stokes) {
    if (!stokes.allFinite()) throw std::invalid_argument("must be four finite numbers [I, Q, U, V]");
    if (!(stokes[0] > 0.0)) throw std::invalid_argument("I must be > 0");
    // (Q/I)^2 + (U/I)^2 + (V/I)^2 <= 1: scaled first, so that no square overflows or underflows.
    const double degreeSquared = (stokes.tail<3>() / stokes[0]).squaredNorm();
    if (!(degreeSquared <= 1.0 + tolerance::kStokesDegreeSlack)) {
        throw std::invalid_argument("Q^2 + U^2 + V^2 must not exceed I^2 (the degree of polarisation is " +
                                    shortText(std::sqrt(degreeSquared)) + ")");
    }
}

void checkPolarisation(const Source& source) {
    const SourcePolarisation& polarisation = source.polarisation;
    if (polarisation.kind == PolarisationKind::Unpolarised) return;
    if (source.type == SourceType::PointSource) throw std::invalid_argument("a point source is unpolarised only");
    if (polarisation.kind == PolarisationKind::Linear && !std::isfinite(polarisation.linearDeg)) {
        throw std::invalid_argument("polarisation linear_deg must be finite");
    }
    try {
        if (polarisation.kind == PolarisationKind::Stokes) checkPolarisationStokes(polarisation.stokes);
    } catch (const std::invalid_argument& error) {
        throw std::invalid_argument(std::string("polarisation stokes: ") + error.what());
    }
    try {
        checkPolarisationReference(polarisation.reference, source.direction);
    } catch (const std::invalid_argument& error) {
        throw std::invalid_argument(std::string("polarisation reference: ") + error.what());
    }
}

Spectrum sourceSpectrum(const Source& source, double sceneWavelengthNm) {
    return source.spectrum ? *source.spectrum : Spectrum::line(sceneWavelengthNm);
}

std::pair<double, double> wavelengthRangeNm(const std::vector<Source>& sources, double sceneWavelengthNm) {
    const std::pair sceneLine{sceneWavelengthNm, sceneWavelengthNm};
    std::optional<std::pair<double, double>> range;
    for (const Source& source : sources) {
        const auto [lo, hi] = source.spectrum ? source.spectrum->rangeNm() : sceneLine;
        range = range ? std::pair{std::min(range->first, lo), std::max(range->second, hi)} : std::pair{lo, hi};
    }
    return range.value_or(sceneLine);
}

void checkDivergence(const Source& source) {
    const double divergence = source.divergenceDeg;
    if (!std::isfinite(divergence) || divergence < 0.0) {
        throw std::invalid_argument("a divergence must be a finite angle >= 0 degrees");
    }
    if (divergence >= kMaxDivergenceDeg) throw std::invalid_argument("a divergence must be less than 90 degrees");
    if (divergence > 0.0 && source.type == SourceType::PointSource) {
        throw std::invalid_argument("a point source already sends light in every direction: it takes no divergence");
    }
}

}  // namespace dropscope
