#include "octree/EmbreePeers.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace dropscope::bench {

namespace {

constexpr float kFloatInfinity = std::numeric_limits<float>::infinity();

// An RTCRayHit for rtcIntersect1 along the double ray, from tnear on. The mask must be all ones:
// Debian builds Embree with ray masks on, and a zero mask hits nothing.
RTCRayHit embreeRay(const Ray& ray, float tnear) {
    RTCRayHit rayHit{};
    rayHit.ray.org_x = static_cast<float>(ray.origin.x());
    rayHit.ray.org_y = static_cast<float>(ray.origin.y());
    rayHit.ray.org_z = static_cast<float>(ray.origin.z());
    rayHit.ray.dir_x = static_cast<float>(ray.direction.x());
    rayHit.ray.dir_y = static_cast<float>(ray.direction.y());
    rayHit.ray.dir_z = static_cast<float>(ray.direction.z());
    rayHit.ray.tnear = tnear;
    rayHit.ray.tfar = kFloatInfinity;
    rayHit.ray.mask = 0xFFFFFFFFu;
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rayHit;
}

}  // namespace

// --- EmbreeDevice ---------------------------------------------------------------------------------

EmbreeDevice::EmbreeDevice() : device_(rtcNewDevice("threads=1")) {
    if (device_ == nullptr) throw std::runtime_error("Embree: rtcNewDevice(\"threads=1\") failed");
    rtcSetDeviceErrorFunction(device_, &EmbreeDevice::onError, this);
    rtcSetDeviceMemoryMonitorFunction(device_, &EmbreeDevice::monitor, this);
}

EmbreeDevice::~EmbreeDevice() { rtcReleaseDevice(device_); }

// Called once per allocation (bytes > 0) and once per release (bytes < 0); never refuses.
bool EmbreeDevice::monitor(void* self, ssize_t bytes, bool /*post*/) {
    static_cast<EmbreeDevice*>(self)->bytes_ += static_cast<std::int64_t>(bytes);
    return true;
}

void EmbreeDevice::onError(void* self, RTCError code, const char* message) {
    auto& device = *static_cast<EmbreeDevice*>(self);
    if (device.error_.empty())
        device.error_ = "error " + std::to_string(static_cast<int>(code)) + ": " + (message ? message : "");
}

void EmbreeDevice::check(const char* step) {
    if (error_.empty()) return;
    throw std::runtime_error(std::string("Embree ") + step + ": " + std::exchange(error_, {}));
}

// --- EmbreeFloatSpheres ---------------------------------------------------------------------------

EmbreeFloatSpheres::EmbreeFloatSpheres(EmbreeDevice& device, const std::vector<Droplet>& droplets)
    : scene_(rtcNewScene(device.handle())) {
    RTCGeometry geometry = rtcNewGeometry(device.handle(), RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                                 4 * sizeof(float), droplets.size()));
    device.check("vertex buffer");
    for (const Droplet& droplet : droplets) {
        *vertices++ = static_cast<float>(droplet.center.x());
        *vertices++ = static_cast<float>(droplet.center.y());
        *vertices++ = static_cast<float>(droplet.center.z());
        *vertices++ = static_cast<float>(droplet.radius);
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);  // geometry id 0; primitive ids are droplet indices
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene_);
    device.check("float sphere scene");
}

EmbreeFloatSpheres::~EmbreeFloatSpheres() { rtcReleaseScene(scene_); }

RayHit EmbreeFloatSpheres::firstHit(const Ray& ray, float tnear) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rayHit = embreeRay(ray, tnear);
    rtcIntersect1(scene_, &context, &rayHit);
    RayHit hit;
    if (rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
        hit.shape = rayHit.hit.primID;
        hit.distance = rayHit.ray.tfar;
    }
    return hit;
}

// --- EmbreeUserSpheres ----------------------------------------------------------------------------

// Embree hands our context back to the callbacks; the double ray and the exact best hit ride along.
// RTCIntersectContext must stay the first member (the callback casts back to Context).
struct EmbreeUserSpheres::Context {
    RTCIntersectContext embree;
    const Ray* ray;
    RayHit best;
    std::size_t sphereTests;
};

EmbreeUserSpheres::EmbreeUserSpheres(EmbreeDevice& device, std::vector<SphereGeometry> spheres, double boundsPad)
    : spheres_(std::move(spheres)), boundsPad_(boundsPad), scene_(rtcNewScene(device.handle())) {
    RTCGeometry geometry = rtcNewGeometry(device.handle(), RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned int>(spheres_.size()));
    rtcSetGeometryUserData(geometry, this);
    rtcSetGeometryBoundsFunction(geometry, &EmbreeUserSpheres::bounds, nullptr);
    rtcSetGeometryIntersectFunction(geometry, &EmbreeUserSpheres::intersect);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene_);
    device.check("user sphere scene");
}

EmbreeUserSpheres::~EmbreeUserSpheres() { rtcReleaseScene(scene_); }

void EmbreeUserSpheres::bounds(const RTCBoundsFunctionArguments* args) {
    const auto& self = *static_cast<const EmbreeUserSpheres*>(args->geometryUserPtr);
    const SphereGeometry& sphere = self.spheres_[args->primID];
    const double reach = sphere.radius + self.boundsPad_;
    RTCBounds* box = args->bounds_o;
    box->lower_x = static_cast<float>(sphere.center.x() - reach);
    box->lower_y = static_cast<float>(sphere.center.y() - reach);
    box->lower_z = static_cast<float>(sphere.center.z() - reach);
    box->upper_x = static_cast<float>(sphere.center.x() + reach);
    box->upper_y = static_cast<float>(sphere.center.y() + reach);
    box->upper_z = static_cast<float>(sphere.center.z() + reach);
}

void EmbreeUserSpheres::intersect(const RTCIntersectFunctionNArguments* args) {
    if (args->valid[0] == 0) return;  // rtcIntersect1: N == 1
    auto* context = reinterpret_cast<Context*>(args->context);
    const auto& self = *static_cast<const EmbreeUserSpheres*>(args->geometryUserPtr);
    const Ray& ray = *context->ray;
    ++context->sphereTests;
    const double t = self.spheres_[args->primID].distanceToSurface(ray.origin, ray.direction);
    const ShapeId before = context->best.shape;
    const double beforeDistance = context->best.distance;
    context->best.offer(args->primID, t);
    if (context->best.shape == before && context->best.distance == beforeDistance) return;
    // Shrink the float search interval to just beyond the exact hit: farther boxes are culled, any
    // sphere reaching as near (a tie the lower id may win) still has its padded box inside it.
    auto* rayHit = reinterpret_cast<RTCRayHit*>(args->rayhit);
    rayHit->ray.tfar = std::nextafter(static_cast<float>(t), kFloatInfinity);
    rayHit->hit.geomID = args->geomID;
    rayHit->hit.primID = args->primID;
}

RayHit EmbreeUserSpheres::firstHit(const Ray& ray) const {
    Context context{{}, &ray, {}, 0};
    rtcInitIntersectContext(&context.embree);
    RTCRayHit rayHit = embreeRay(ray, 0.0f);  // t == 0 (leaving a surface) is refused by RayHit::offer
    rtcIntersect1(scene_, &context.embree, &rayHit);
    sphereTests_ += context.sphereTests;
    return context.best;
}

}  // namespace dropscope::bench
