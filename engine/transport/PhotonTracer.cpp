#include "transport/PhotonTracer.hpp"

#include "transport/PolarisedCrossing.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace dropscope {

namespace {
// Draws of a diffracted direction before one into the droplet is kept: at x = 1 about half the pattern points into
// it from the ring's inner edge, so 64 tries fail with probability ~1e-19.
constexpr int kMaxDiffractionDraws = 64;
}  // namespace

std::string_view photonFateName(PhotonFate fate) {
    switch (fate) {
    case PhotonFate::Escaped: return "escaped";
    case PhotonFate::Absorbed: return "absorbed";
    case PhotonFate::Lost: return "lost";
    case PhotonFate::Detected: return "detected";
    }
    return "?";
}

PhotonOutcome tracePhoton(const OpticalScene& scene, const Ray& emitted, PhotonRandom& random,
                          const TransportSettings& settings, PhotonObserver* observer,
                          const std::optional<Polarisation>& polarisation, std::optional<double> wavelengthNm,
                          const std::optional<Direction>& axis) {
    const bool flights = observer && observer->wantsFlights();
    PhotonOutcome outcome;
    PhotonState state{emitted, axis.value_or(emitted.direction)};
    state.wavelengthNm = wavelengthNm.value_or(scene.wavelengthNm());
    // The media at this photon's wavelength, in a buffer each thread reuses.
    thread_local std::vector<MediumOptics> ownWavelength;
    std::span<const MediumOptics> optics = scene.sceneOptics();
    if (state.wavelengthNm != scene.wavelengthNm()) {
        scene.opticsAt(state.wavelengthNm, ownWavelength);
        optics = ownWavelength;
    }
    Point position = emitted.origin;
    Direction direction = emitted.direction;
    ShapeId region = scene.regionAt(position, direction);
    state.region = region;
    std::optional<Polarisation> light;
    if (settings.polarisation == PolarisationModel::Stokes)
        light = polarisation ? *polarisation : unpolarisedLight(direction);
    const auto observe = [&](const Event& event) {
        if (observer) observer->event(event, state);
    };
    const auto here = [&](EventType type) {
        const MediumId medium = scene.mediumIdOf(region);
        Event event{type, position, direction, OpticalScene::kAmbient, medium, medium};
        event.polarisation = light;
        return event;
    };
    // Moves the photon `length` ahead (an infinite length leaves it where it is: the escape ray).
    const auto fly = [&](double length) {
        if (flights) {
            observer->flight({position, direction, length, scene.mediumIdOf(region), light ? &*light : nullptr}, state);
        }
        if (!std::isfinite(length)) return;
        position += length * direction.vector();
        state.pathLength += length;
    };
    // `at`: the surface the photon was at, or the shape it was inside, when there is one.
    const auto lose = [&](LostReason reason, ShapeId at) {
        outcome.fate = PhotonFate::Lost;
        outcome.lostReason = reason;
        if (observer) {
            Event event = here(EventType::Lost);
            event.lostReason = reason;
            event.lostAt = at;
            observe(event);
        }
        return outcome;
    };
    // Draws an absorption distance in the current medium; when it is shorter than `distance` the
    // photon flies there and is absorbed.
    const auto absorbedWithin = [&](double distance) {
        const double sigma = optics[scene.mediumIdOf(region)].absorptionPerUnit;
        if (sigma <= 0.0) return false;
        const double freePath = -std::log(random.uniform()) / sigma;
        if (freePath >= distance) return false;
        fly(freePath);
        ++outcome.events.absorb;
        outcome.fate = PhotonFate::Absorbed;
        observe(here(EventType::Absorb));
        return true;
    };
    // Ends the photon on the absorbing plane detector its flight reaches.
    const auto detect = [&](const OpticalScene::PlaneHit& detector) {
        fly(detector.distance);
        outcome.fate = PhotonFate::Detected;
        if (observer) {
            Event event = here(EventType::Detect);
            event.detector = detector.plane->detector;
            observe(event);
        }
        return outcome;
    };
    const bool diffraction = settings.diffraction == DiffractionModel::Fraunhofer;
    if (diffraction && !scene.hasHaloes()) throw std::logic_error("tracePhoton: diffraction needs a scene with haloes");
    observe(here(EventType::Emit));

    // From a distant source, cross the empty ambient up to the scene first, so that hit points are
    // computed from nearby and stay within the surface bands (docs/transport.md).
    if (region == OpticalScene::kAmbient) {
        const double approach = scene.approachDistance(position, direction, diffraction);
        if (approach > 0.0) {
            const auto detector = scene.firstAbsorbingPlane(position, direction, approach);
            if (absorbedWithin(detector ? detector->distance : approach)) return outcome;
            if (detector) return detect(*detector);
            fly(approach);
        }
    }

    // Turns the photon by diffraction at the droplet it passes (OpticalScene::firstHaloPass).
    const auto diffract = [&](ShapeId dropletId) {
        const Shape& droplet = *scene.octree().shape(dropletId);
        const double wavelength = wavelengthInUnits(state.wavelengthNm, scene.unitInMetres());
        const double wavenumber = 2.0 * std::numbers::pi * optics[scene.mediumIdOf(region)].n / wavelength;
        const ProjectedEllipse outline = *projectedOutline(droplet, direction);
        const auto draw = [&] { return random.uniform(); };
        // A turn into the droplet it passes is drawn again (docs/transport.md: wider than acos(r / b), so only for
        // small droplets or the ring's inner edge); after kMaxDiffractionDraws the last one stands.
        Direction turned = diffractedDirection(direction, outline, wavenumber, draw);
        for (int redraw = 1; redraw < kMaxDiffractionDraws && !std::isnan(droplet.distanceToSurface(position, turned));
             ++redraw) {
            turned = diffractedDirection(direction, outline, wavenumber, draw);
        }
        if (light) light->reference = turnedReference(light->reference, direction, turned);
        direction = turned;
        outcome.metSurface = state.metSurface = true;
        ++outcome.events.diffract;
        if (observer) {
            Event event = here(EventType::Diffract);
            event.shape = dropletId;
            observe(event);
        }
    };

    for (;;) {
        const RayHit hit = scene.nextSurface(region, position, direction);
        double reach = hit ? hit.distance : std::numeric_limits<double>::infinity();
        const auto halo = diffraction ? scene.firstHaloPass(position, direction, reach, region) : std::nullopt;
        if (halo) reach = halo->distance;
        // A photon inside a shape with no surface ahead is lost below, never detected beyond it.
        const auto detector = hit || halo || region == OpticalScene::kAmbient
                                  ? scene.firstAbsorbingPlane(position, direction, reach)
                                  : std::nullopt;
        if (detector) reach = detector->distance;
        if (absorbedWithin(reach)) return outcome;
        if (detector) return detect(*detector);
        if (halo) {
            const OpticalScene::HaloPass pass = *halo;
            fly(pass.distance);
            if (++state.interfaceEvents > settings.maxEvents) return lose(LostReason::EventCap, pass.droplet);
            diffract(pass.droplet);
            continue;
        }
        if (!hit) {
            if (region != OpticalScene::kAmbient) return lose(LostReason::NoExit, region);
            fly(std::numeric_limits<double>::infinity());
            outcome.fate = PhotonFate::Escaped;
            outcome.finalDirection = direction;
            observe(here(EventType::Escape));
            return outcome;
        }

        fly(hit.distance);
        outcome.metSurface = state.metSurface = true;
        if (++state.interfaceEvents > settings.maxEvents) return lose(LostReason::EventCap, hit.shape);
        const SurfaceCrossing crossing =
            crossSurface(scene, region, hit.shape, position, direction, settings.fresnel, !light, optics);
        if (crossing.kind == SurfaceCrossing::Kind::Lost) return lose(crossing.lostReason, hit.shape);
        if (crossing.kind == SurfaceCrossing::Kind::Tangent) continue;  // goes on unchanged (seed 000 ch. 4)

        double reflectance = crossing.reflectance;
        std::optional<PolarisedCrossing> polarised;
        if (light) {
            polarised.emplace(*light, crossing);
            reflectance = polarised->reflectance();
        }
        EventType type = EventType::Refract;
        if (crossing.totalInternalReflection) {
            type = EventType::Tir;
            ++outcome.events.tir;
        } else if (random.uniform() < reflectance) {
            type = EventType::Reflect;
            ++outcome.events.reflect;
        } else {
            ++outcome.events.refract;
        }
        if (type == EventType::Refract) {
            direction = crossing.transmitted;
            region = state.region = crossing.regionBeyond;
            if (light) light = withUnitPower(polarised->transmitted());
        } else {
            direction = crossing.reflected();
            if (light) light = withUnitPower(polarised->reflected());
        }
        if (observer) {
            Event event{type, position, direction, hit.shape, crossing.from, crossing.to, reflectance, 1.0};
            event.polarisation = light;
            observe(event);
        }
    }
}

}  // namespace dropscope
