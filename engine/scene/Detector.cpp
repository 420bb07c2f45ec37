#include "scene/Detector.hpp"

#include "spectrum/Decimal.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace dropscope {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// The unit component of `up` perpendicular to `axis`; throws when up is (nearly) along the axis or zero.
Eigen::Vector3d perpendicularUp(const Eigen::Vector3d& up, const Eigen::Vector3d& axis, const char* axisName) {
    if (!up.allFinite() || up.norm() == 0.0) throw std::invalid_argument("up must be a non-zero vector");
    const Eigen::Vector3d across = up - up.dot(axis) * axis;
    if (across.norm() <= kDetectorUpSine * up.norm()) {
        throw std::invalid_argument(std::string("up must not be along the ") + axisName);
    }
    return across.normalized();
}

// r(theta) of each projection, and its inverse; the projections' largest theta.
double radiusOf(FarFieldProjection projection, double theta) {
    switch (projection) {
    case FarFieldProjection::Equidistant: return theta;
    case FarFieldProjection::EqualArea: return 2.0 * std::sin(theta / 2.0);
    case FarFieldProjection::Perspective: return std::tan(theta);
    }
    return theta;
}
double maxRadius(FarFieldProjection projection) {
    switch (projection) {
    case FarFieldProjection::Equidistant: return std::numbers::pi;
    case FarFieldProjection::EqualArea: return 2.0;
    case FarFieldProjection::Perspective: return std::numeric_limits<double>::infinity();
    }
    return 0.0;
}
double thetaOf(FarFieldProjection projection, double r) {
    switch (projection) {
    case FarFieldProjection::Equidistant: return r;
    case FarFieldProjection::EqualArea: return 2.0 * std::asin(std::min(r / 2.0, 1.0));
    case FarFieldProjection::Perspective: return std::atan(r);
    }
    return r;
}
// Solid angle per unit image-plane area at radius r (inside the domain).
double solidAngleDensity(FarFieldProjection projection, double r) {
    switch (projection) {
    case FarFieldProjection::Equidistant: return r > 0.0 ? std::sin(r) / r : 1.0;
    case FarFieldProjection::EqualArea: return 1.0;
    case FarFieldProjection::Perspective: return 1.0 / std::pow(1.0 + r * r, 1.5);
    }
    return 0.0;
}

// The perspective projection's solid angle of the image-plane rectangle [0, x] x [0, y] (signed).
double perspectiveCornerSolidAngle(double x, double y) { return std::atan(x * y / std::sqrt(1.0 + x * x + y * y)); }

// 8-point Gauss-Legendre nodes and weights on [-1, 1] (Abramowitz and Stegun, table 25.4).
constexpr std::array<double, 4> kGaussNodes{0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                            0.9602898564975363};
constexpr std::array<double, 4> kGaussWeights{0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                              0.1012285362903763};
// A pixel the domain's edge cuts is integrated by the midpoint rule on this many points a side.
constexpr int kCutPixelSamples = 64;

}  // namespace

std::string_view detectorTypeName(DetectorType type) {
    switch (type) {
    case DetectorType::Plane: return "plane";
    case DetectorType::FarField: return "far_field";
    case DetectorType::ShapeAbsorption: return "shape_absorption";
    }
    return "?";
}

std::string_view detectorSideName(DetectorSide side) {
    switch (side) {
    case DetectorSide::Both: return "both";
    case DetectorSide::Front: return "front";
    case DetectorSide::Back: return "back";
    }
    return "?";
}

std::string_view projectionName(FarFieldProjection projection) {
    switch (projection) {
    case FarFieldProjection::Equidistant: return "equidistant";
    case FarFieldProjection::EqualArea: return "equal_area";
    case FarFieldProjection::Perspective: return "perspective";
    }
    return "?";
}

bool isDetectorName(std::string_view name) {
    if (name.empty() || name.size() > kMaxDetectorNameLength) return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    });
}

void checkDetector(const Detector& detector) {
    if (!isDetectorName(detector.name)) {
        throw std::invalid_argument("a detector name is 1 to " + std::to_string(kMaxDetectorNameLength) +
                                    " letters, digits, '_' or '-'");
    }
    if (detector.record > kMaxDetectorRecords) {
        throw std::invalid_argument("record must be at most " + std::to_string(kMaxDetectorRecords));
    }
    if (detector.type == DetectorType::ShapeAbsorption) return;
    if (detector.pixels.nx < 1 || detector.pixels.ny < 1) throw std::invalid_argument("pixels must be at least 1");
    if (detector.pixels.count() > kMaxDetectorPixels) {
        throw std::invalid_argument("at most " + std::to_string(kMaxDetectorPixels) + " pixels");
    }
    if (detector.type == DetectorType::Plane) {
        if (!detector.center.allFinite()) throw std::invalid_argument("center must be finite");
        for (double side : detector.size) {
            if (!(std::isfinite(side) && side > 0.0)) throw std::invalid_argument("size must be two numbers > 0");
        }
        perpendicularUp(detector.up, detector.normal.vector(), "normal");
        return;
    }
    perpendicularUp(detector.up, detector.look.vector(), "look direction");
    const double fov = detector.fovDeg;
    const double limit = detector.projection == FarFieldProjection::Perspective ? 180.0 : 360.0;
    const bool open = detector.projection == FarFieldProjection::Perspective;
    if (!std::isfinite(fov) || fov <= 0.0 || (open ? fov >= limit : fov > limit)) {
        throw std::invalid_argument("fov_deg must be > 0 and " + std::string(open ? "< " : "<= ") +
                                    shortestDecimal(limit) + " for the " +
                                    std::string(projectionName(detector.projection)) + " projection");
    }
}

PlaneFrame planeFrame(const Detector& plane) {
    PlaneFrame frame;
    frame.n = plane.normal.vector();
    frame.v = perpendicularUp(plane.up, frame.n, "normal");
    frame.u = frame.v.cross(frame.n);
    return frame;
}

std::optional<PlaneCrossing> crossPlane(const Detector& plane, const PlaneFrame& frame, const Point& origin,
                                        const Direction& direction, double length) {
    const double approach = direction.vector().dot(frame.n);
    if (approach == 0.0) return std::nullopt;
    if (plane.side == DetectorSide::Front && approach > 0.0) return std::nullopt;
    if (plane.side == DetectorSide::Back && approach < 0.0) return std::nullopt;
    const double distance = (plane.center - origin).dot(frame.n) / approach;
    if (!(distance > 0.0 && distance <= length)) return std::nullopt;
    const Eigen::Vector3d offset = origin + distance * direction.vector() - plane.center;
    const double u = offset.dot(frame.u);
    const double v = offset.dot(frame.v);
    const double halfW = plane.size[0] / 2.0;
    const double halfH = plane.size[1] / 2.0;
    if (!(std::abs(u) <= halfW && std::abs(v) <= halfH)) return std::nullopt;
    return PlaneCrossing{distance, u, v, planePixel(plane, u, v)};
}

std::size_t planePixel(const Detector& plane, double u, double v) {
    const auto cell = [](double offsetFromEdge, double extent, int count) {
        const auto index = static_cast<int>(offsetFromEdge / extent * count);
        return std::clamp(index, 0, count - 1);  // the far edge belongs to the last pixel
    };
    return plane.pixels.index(cell(u + plane.size[0] / 2.0, plane.size[0], plane.pixels.nx),
                              cell(v + plane.size[1] / 2.0, plane.size[1], plane.pixels.ny));
}

std::array<double, 2> planePixelCentre(const Detector& plane, int ix, int iy) {
    const double du = plane.size[0] / plane.pixels.nx;
    const double dv = plane.size[1] / plane.pixels.ny;
    return {-plane.size[0] / 2.0 + (ix + 0.5) * du, -plane.size[1] / 2.0 + (iy + 0.5) * dv};
}

double planePixelArea(const Detector& plane) {
    return plane.size[0] / plane.pixels.nx * (plane.size[1] / plane.pixels.ny);
}

FarFieldCamera::FarFieldCamera(const Detector& camera)
    : projection_(camera.projection), look_(camera.look.vector()), pixels_(camera.pixels) {
    up_ = perpendicularUp(camera.up, look_, "look direction");
    right_ = look_.cross(up_);
    const double halfWidth = radiusOf(projection_, camera.fovDeg * kDegree / 2.0);
    pixelSize_ = 2.0 * halfWidth / pixels_.nx;
}

double FarFieldCamera::cornerX(int ix) const { return (ix - pixels_.nx / 2.0) * pixelSize_; }
double FarFieldCamera::cornerY(int iy) const { return (iy - pixels_.ny / 2.0) * pixelSize_; }

std::optional<std::size_t> FarFieldCamera::pixelOf(const Eigen::Vector3d& viewing) const {
    const double theta = std::acos(std::clamp(viewing.dot(look_), -1.0, 1.0));
    if (projection_ == FarFieldProjection::Perspective && theta >= std::numbers::pi / 2.0) return std::nullopt;
    const double r = radiusOf(projection_, theta);
    const double azimuth = std::atan2(viewing.dot(up_), viewing.dot(right_));
    const double ix = std::floor(r * std::cos(azimuth) / pixelSize_ + pixels_.nx / 2.0);
    const double iy = std::floor(r * std::sin(azimuth) / pixelSize_ + pixels_.ny / 2.0);
    if (!(ix >= 0.0 && ix < pixels_.nx && iy >= 0.0 && iy < pixels_.ny)) return std::nullopt;
    return pixels_.index(static_cast<int>(ix), static_cast<int>(iy));
}

std::optional<Eigen::Vector3d> FarFieldCamera::unproject(double x, double y) const {
    const double r = std::hypot(x, y);
    if (r > maxRadius(projection_)) return std::nullopt;
    const double theta = thetaOf(projection_, r);
    const double azimuth = r > 0.0 ? std::atan2(y, x) : 0.0;
    return Eigen::Vector3d(std::cos(theta) * look_ +
                           std::sin(theta) * (std::cos(azimuth) * right_ + std::sin(azimuth) * up_));
}

std::optional<Eigen::Vector3d> FarFieldCamera::viewingDirection(int ix, int iy) const {
    const double x = cornerX(ix) + pixelSize_ / 2.0;
    const double y = cornerY(iy) + pixelSize_ / 2.0;
    const double rMax = maxRadius(projection_);
    const double r = std::hypot(x, y);
    if (r <= rMax) return unproject(x, y);
    // A pixel the domain's edge cuts sees light through its part inside: it views the edge point in line with
    // its centre. One wholly beyond the edge views nothing.
    const double nearX = std::clamp(0.0, cornerX(ix), cornerX(ix + 1));
    const double nearY = std::clamp(0.0, cornerY(iy), cornerY(iy + 1));
    if (std::hypot(nearX, nearY) >= rMax) return std::nullopt;
    return unproject(x * rMax / r, y * rMax / r);
}

double FarFieldCamera::pixelSolidAngle(int ix, int iy) const {
    const double x0 = cornerX(ix), x1 = cornerX(ix + 1);
    const double y0 = cornerY(iy), y1 = cornerY(iy + 1);
    if (projection_ == FarFieldProjection::Perspective) {
        return perspectiveCornerSolidAngle(x1, y1) - perspectiveCornerSolidAngle(x0, y1) -
               perspectiveCornerSolidAngle(x1, y0) + perspectiveCornerSolidAngle(x0, y0);
    }
    const double rMax = maxRadius(projection_);
    const double farthest = std::hypot(std::max(std::abs(x0), std::abs(x1)), std::max(std::abs(y0), std::abs(y1)));
    double sum = 0.0;
    if (farthest <= rMax) {
        // Wholly inside the domain: the smooth density by Gauss-Legendre, 8 x 8 points.
        const double cx = (x0 + x1) / 2.0, cy = (y0 + y1) / 2.0, h = pixelSize_ / 2.0;
        for (std::size_t i = 0; i < 8; ++i) {
            const double x = cx + (i < 4 ? -1.0 : 1.0) * h * kGaussNodes[i % 4];
            for (std::size_t j = 0; j < 8; ++j) {
                const double y = cy + (j < 4 ? -1.0 : 1.0) * h * kGaussNodes[j % 4];
                sum += kGaussWeights[i % 4] * kGaussWeights[j % 4] * solidAngleDensity(projection_, std::hypot(x, y));
            }
        }
        return sum * h * h;
    }
    // Cut by the domain's edge (r = pi or 2): the density is 0 beyond it; midpoint rule.
    const double step = pixelSize_ / kCutPixelSamples;
    for (int i = 0; i < kCutPixelSamples; ++i) {
        for (int j = 0; j < kCutPixelSamples; ++j) {
            const double r = std::hypot(x0 + (i + 0.5) * step, y0 + (j + 0.5) * step);
            if (r <= rMax) sum += solidAngleDensity(projection_, r);
        }
    }
    return sum * step * step;
}

}  // namespace dropscope
