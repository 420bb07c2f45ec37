#pragma once

#include "geometry/Vector.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dropscope {

enum class DetectorType { Plane, FarField, ShapeAbsorption };
// Which crossings of a plane detector count: both directions, or only light arriving on the side the normal
// points to (front: travelling against the normal), or only on the other side (back).
enum class DetectorSide { Both, Front, Back };
enum class FarFieldProjection { Equidistant, EqualArea, Perspective };

std::string_view detectorTypeName(DetectorType type);            // "plane", "far_field", "shape_absorption"
std::string_view detectorSideName(DetectorSide side);            // "both", "front", "back"
std::string_view projectionName(FarFieldProjection projection);  // "equidistant", "equal_area", "perspective"

// An image's pixel grid: nx columns (ix, along u) by ny rows (iy, along v, row 0 at the lowest v); pixel
// (ix, iy) is number iy * nx + ix, the order the CSV files list them in.
struct PixelGrid {
    int nx = 1;
    int ny = 1;
    std::size_t count() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
    std::size_t index(int ix, int iy) const {
        return static_cast<std::size_t>(iy) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(ix);
    }
};

// What a detector counts (docs/detectors.md; scene key "detectors", docs/scene-format.md).
//  plane: a w x h rectangle at `center` facing `normal`; v is `up` projected into the plane, u = v x normal;
//    counts every crossing of a photon path through it on the sides `side` admits; `absorbing` ends the
//    photons it counts (fate detected).
//  far_field: a camera at infinity looking along `look` with `up`; a photon escaping along d is seen from -d.
//    `fovDeg` is the full angle across the image's width (u); pixels are square.
//  shape_absorption: the power absorbed in each shape.
// Any detector may keep its first `record` hits (by photon index, then order within the photon).
struct Detector {
    std::string name;
    DetectorType type = DetectorType::Plane;
    // plane
    Point center = Point::Zero();
    Direction normal{0.0, 0.0, 1.0};
    std::array<double, 2> size{1.0, 1.0};
    DetectorSide side = DetectorSide::Both;
    bool absorbing = false;
    // plane and far_field
    Eigen::Vector3d up{0.0, 1.0, 0.0};
    PixelGrid pixels{};
    // far_field
    Direction look{0.0, 0.0, -1.0};
    FarFieldProjection projection = FarFieldProjection::Equidistant;
    double fovDeg = 90.0;
    std::uint64_t record = 0;
};

// Limits the loader enforces (and the app's editors): a detector name is 1 to kMaxDetectorNameLength of
// letters, digits, '_' and '-'; an image has at most kMaxDetectorPixels pixels; a far-field view is at most
// 360 degrees wide (perspective: less than 180).
inline constexpr std::size_t kMaxDetectorNameLength = 64;
inline constexpr std::size_t kMaxDetectorPixels = 1'048'576;  // 1024 x 1024: ~100 bytes each per thread
inline constexpr std::uint64_t kMaxDetectorRecords = 10'000'000;
// An `up` must be further than this sine from the normal (or look) direction: closer, its projection into
// the image plane is mostly rounding and the image would spin with the last bits of the input.
inline constexpr double kDetectorUpSine = 1e-6;

// Throws std::invalid_argument naming what is wrong (not where): a name that is empty, too long or has other
// characters; a non-finite or non-positive size or fov; pixels below 1 or too many; an `up` that is zero or
// (nearly) along the normal or look direction (kDetectorUpSine); a fov out of its projection's range.
void checkDetector(const Detector& detector);
bool isDetectorName(std::string_view name);

// A plane detector's frame: unit u, v in the plane, the unit normal n.
struct PlaneFrame {
    Eigen::Vector3d u, v, n;
};
PlaneFrame planeFrame(const Detector& plane);

// Where a path segment from `origin` along unit `direction` crosses a plane detector.
struct PlaneCrossing {
    double distance = 0.0;    // along the direction
    double u = 0.0, v = 0.0;  // in the detector's frame, relative to its centre
    std::size_t pixel = 0;
};
// The crossing of the segment (0, length] (length may be infinite) through the rectangle on a side the
// detector admits; none when the segment is parallel to the plane, misses the rectangle or crosses on a
// side it does not count.
std::optional<PlaneCrossing> crossPlane(const Detector& plane, const PlaneFrame& frame, const Point& origin,
                                        const Direction& direction, double length);
// The pixel of a point (u, v) of the rectangle (the far edges belong to the last pixels).
std::size_t planePixel(const Detector& plane, double u, double v);
// Pixel (ix, iy)'s centre in the detector's frame.
std::array<double, 2> planePixelCentre(const Detector& plane, int ix, int iy);
double planePixelArea(const Detector& plane);

// A far-field camera: its frame (right = look x up, up' = up made perpendicular to look) and image plane.
class FarFieldCamera {
public:
    explicit FarFieldCamera(const Detector& camera);
    // The pixel that views `viewing` (a unit direction from the observer), if it is in the image.
    std::optional<std::size_t> pixelOf(const Eigen::Vector3d& viewing) const;
    // The viewing direction through pixel (ix, iy)'s centre; for a pixel the projection's domain edge cuts with
    // its centre beyond it, the edge point in line with the centre; none for a pixel wholly beyond the edge.
    std::optional<Eigen::Vector3d> viewingDirection(int ix, int iy) const;
    // Pixel (ix, iy)'s solid angle in steradians (0 outside the projection's domain).
    double pixelSolidAngle(int ix, int iy) const;
    const Eigen::Vector3d& right() const { return right_; }
    const Eigen::Vector3d& upAxis() const { return up_; }
    const Eigen::Vector3d& look() const { return look_; }
    const PixelGrid& pixels() const { return pixels_; }

private:
    // The viewing direction of image-plane point (x, y); none beyond the projection's domain.
    std::optional<Eigen::Vector3d> unproject(double x, double y) const;
    // The image-plane coordinates of pixel corner (ix, iy).
    double cornerX(int ix) const;
    double cornerY(int iy) const;

    FarFieldProjection projection_;
    Eigen::Vector3d look_, right_, up_;
    PixelGrid pixels_;
    double pixelSize_;  // in image-plane units
};

}  // namespace dropscope
