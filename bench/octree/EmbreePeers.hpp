#pragma once

#include "geometry/SphereGeometry.hpp"
#include "octree/Rays.hpp"
#include "octree/SphereCloud.hpp"
#include "tree/RayHit.hpp"

#include <embree3/rtcore.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace dropscope::bench {

// One Embree 3 device for one thread ("threads=1"). Counts the bytes Embree allocates through its
// memory monitor, and turns errors reported by the error callback into exceptions at check().
class EmbreeDevice {
public:
    EmbreeDevice();
    ~EmbreeDevice();
    EmbreeDevice(const EmbreeDevice&) = delete;
    EmbreeDevice& operator=(const EmbreeDevice&) = delete;

    RTCDevice handle() const { return device_; }
    std::int64_t bytesInUse() const { return bytes_; }
    // Throws std::runtime_error naming `step` if Embree reported an error since the last check.
    void check(const char* step);

private:
    static bool monitor(void* self, ssize_t bytes, bool post);
    static void onError(void* self, RTCError code, const char* message);

    RTCDevice device_;
    std::int64_t bytes_ = 0;
    std::string error_;
};

// Embree's own float sphere primitive (RTC_GEOMETRY_TYPE_SPHERE_POINT, float4 x y z r).
class EmbreeFloatSpheres {
public:
    EmbreeFloatSpheres(EmbreeDevice& device, const std::vector<Droplet>& droplets);
    ~EmbreeFloatSpheres();
    EmbreeFloatSpheres(const EmbreeFloatSpheres&) = delete;
    EmbreeFloatSpheres& operator=(const EmbreeFloatSpheres&) = delete;

    // The nearest sphere hit at t in [tnear, inf), t in float; primitive ids are shape ids.
    RayHit firstHit(const Ray& ray, float tnear) const;

private:
    RTCScene scene_;
};

// Embree's BVH over user primitives whose intersect callback runs dropscope's double-precision
// SphereGeometry::distanceToSurface on the double ray: the same arithmetic as the octree, so the
// hits can be compared exactly. Callbacks may come in any order; the best one is kept with
// RayHit::offer (t > 0 only, ties to the lower id) and Embree's float tfar is shrunk to a value
// just above it, so the BVH still culls everything farther.
class EmbreeUserSpheres {
public:
    // `boundsPad` inflates each primitive's float box so that float rounding of the ray (and of the
    // box) can never hide a sphere the double ray reaches.
    EmbreeUserSpheres(EmbreeDevice& device, std::vector<SphereGeometry> spheres, double boundsPad);
    ~EmbreeUserSpheres();
    EmbreeUserSpheres(const EmbreeUserSpheres&) = delete;
    EmbreeUserSpheres& operator=(const EmbreeUserSpheres&) = delete;

    RayHit firstHit(const Ray& ray) const;
    // Intersect callbacks run so far (sphere tests).
    std::size_t sphereTests() const { return sphereTests_; }
    // The packed spheres the callbacks read, which Embree does not count.
    std::size_t bytesOwned() const { return spheres_.capacity() * sizeof(SphereGeometry); }

private:
    struct Context;
    static void bounds(const RTCBoundsFunctionArguments* args);
    static void intersect(const RTCIntersectFunctionNArguments* args);

    std::vector<SphereGeometry> spheres_;
    double boundsPad_;
    RTCScene scene_;
    mutable std::size_t sphereTests_ = 0;
};

}  // namespace dropscope::bench
