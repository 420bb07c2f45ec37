#pragma once

#include "geometry/Shape.hpp"
#include "geometry/Vector.hpp"
#include "optics/Polarisation.hpp"
#include "tree/RayHit.hpp"

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>

namespace dropscope {

// What happened to a photon (or a ray-tree branch). `Detect`: it ended on an absorbing detector. `Diffract`: it
// passed a droplet and was turned by diffraction where it left it (--diffraction fraunhofer). `Truncated` only
// occurs in the ray tree: a branch whose weight fell below the minimum or whose depth reached the maximum.
enum class EventType { Emit, Reflect, Refract, Tir, Absorb, Escape, Lost, Detect, Truncated, Diffract };

// Why a photon was lost: every photon ends escaped, absorbed or lost, and a lost one says why.
enum class LostReason {
    EventCap,         // more interface events than TransportSettings::maxEvents (e.g. trapped by TIR)
    UndefinedNormal,  // hit a box edge or vertex, where no normal exists
    MediumMismatch,   // the surface crossed does not bound the region the photon is in (touching shapes)
    NoExit,           // inside a shape but no surface ahead: rounding put the photon outside it
};
inline constexpr std::size_t kLostReasonCount = 4;

std::string_view eventTypeName(EventType type);
std::string_view lostReasonName(LostReason reason);
// What a reason means, for warnings: "at box edges or vertices".
std::string_view lostReasonMeaning(LostReason reason);

// One recorded event. The direction is the one the photon leaves the event with (the incoming one
// for absorb, escape and lost); `from`/`to` are the media on the incident and the far side of the
// surface (both the current medium away from surfaces). `reflectance` is the Fresnel R used, NaN
// where no surface is involved. `polarisation` is the light's after the event, when polarisation is
// traced (I is then the weight).
struct Event {
    EventType type = EventType::Emit;
    Point position = Point::Zero();
    Direction direction;
    ShapeId shape = RayHit::kNone;
    MediumId from = 0;
    MediumId to = 0;
    double reflectance = std::numeric_limits<double>::quiet_NaN();
    double weight = 1.0;
    LostReason lostReason = LostReason::EventCap;  // meaningful only for EventType::Lost
    // For EventType::Lost: the surface the photon was at or the shape it was inside, if any. Not `shape`,
    // which paths.jsonl has always written as null for a loss.
    ShapeId lostAt = RayHit::kNone;
    std::size_t detector = 0;  // for EventType::Detect: its index in the scene's detectors
    std::optional<Polarisation> polarisation = std::nullopt;
};

// Interface and absorption events of a set of photons, as summary.json reports them.
struct EventCounts {
    std::uint64_t reflect = 0;
    std::uint64_t refract = 0;
    std::uint64_t tir = 0;
    std::uint64_t absorb = 0;
    std::uint64_t diffract = 0;

    EventCounts& operator+=(const EventCounts& other) {
        reflect += other.reflect;
        refract += other.refract;
        tir += other.tir;
        absorb += other.absorb;
        diffract += other.diffract;
        return *this;
    }
    friend bool operator==(const EventCounts&, const EventCounts&) = default;
};

}  // namespace dropscope
