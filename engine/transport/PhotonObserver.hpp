#pragma once

#include "transport/Emission.hpp"
#include "transport/Event.hpp"

#include <cstdint>
#include <vector>

namespace dropscope {

// What the tracer knows about the photon it is following, passed with every observation.
struct PhotonState {
    Ray emitted;                         // where and in which direction it left its source
    Direction axis = emitted.direction;  // what scattering angles are measured from: its source's axis
    bool metSurface = false;             // it has reached a surface (tangent passes included)
    std::uint64_t interfaceEvents = 0;   // surfaces reached so far (reflect, refract, tir, tangent)
    double wavelengthNm = 0.0;           // its vacuum wavelength
    ShapeId region = RayHit::kNone;      // the region it is in (RayHit::kNone: the ambient medium)
    double pathLength = 0.0;             // how far it has flown since its emission
};

// One straight stretch of a photon's path: from `origin` along `direction` for `length` (infinite for
// the escape ray) through the medium `medium`. Every point a photon passes lies on one flight.
struct Flight {
    Point origin = Point::Zero();
    Direction direction;
    double length = 0.0;
    MediumId medium = 0;
    const Polarisation* polarisation = nullptr;  // the light's along it, when polarisation is traced
};

// Told everything that happens to one photon, in order: every event (emit first; escape, absorb or
// lost last) and every flight between them. The tracer calls flight() only when wantsFlights().
class PhotonObserver {
public:
    virtual void event(const Event& event, const PhotonState& photon) = 0;
    virtual void flight(const Flight&, const PhotonState&) {}
    virtual bool wantsFlights() const { return false; }

protected:
    ~PhotonObserver() = default;
};

// Appends every event to a vector: a recorded path.
class EventRecorder final : public PhotonObserver {
public:
    explicit EventRecorder(std::vector<Event>& events) : events_(events) {}
    void event(const Event& event, const PhotonState&) override { events_.push_back(event); }

private:
    std::vector<Event>& events_;
};

}  // namespace dropscope
