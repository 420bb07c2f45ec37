#include "scene/Source.hpp"

#include "optics/OpticsTolerance.hpp"

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
    if (!reference.allFinite() || reference.isZero(0.0)) {
        throw std::invalid_argument("must be a finite, non-zero vector");
    }
    const double cosine = std::abs(reference.normalized().dot(direction.vector()));
    if (cosine > tolerance::kReferencePerpendicularCosine) {
        throw std::invalid_argument("must be perpendicular to the direction (their cosine is " + shortText(cosine) +
                                    ")");
    }
}

void checkPolarisationStokes(const StokesVector& stokes) {
    if (!stokes.allFinite()) throw std::invalid_argument("must be four finite numbers [I, Q, U, V]");
    if (!(stokes[0] > 0.0)) throw std::invalid_argument("I must be > 0");
    const double polarised = stokes.tail<3>().squaredNorm();
    const double power = stokes[0] * stokes[0];
    if (polarised > power * (1.0 + tolerance::kStokesDegreeSlack)) {
        throw std::invalid_argument("Q^2 + U^2 + V^2 must not exceed I^2 (the degree of polarisation is " +
                                    shortText(std::sqrt(polarised / power)) + ")");
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

}  // namespace dropscope
