#include "render/DetectorGlyphs.hpp"

#include "render/Colour.hpp"
#include "tally/DetectorTallies.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dropscope::render {

namespace {

constexpr double kHeadLength = 0.2;    // of the arrow
constexpr double kHeadWidth = 0.08;    // of the arrow, each side
constexpr int kHatchLines = 9;         // across an absorbing plane
constexpr double kUpTick = 0.25;       // of the frustum's height
constexpr double kArrowOfSide = 0.25;  // a plane's arrow, of its shorter side at least

void addArrow(LineBatch& lines, const Point& origin, const Eigen::Vector3d& direction, const Eigen::Vector3d& side,
              double length) {
    const Point tip = origin + length * direction;
    lines.add(origin, tip, kDetectorColour);
    const Point base = tip - kHeadLength * length * direction;
    lines.add(tip, base + kHeadWidth * length * side, kDetectorColour);
    lines.add(tip, base - kHeadWidth * length * side, kDetectorColour);
}

// The rectangle's point at (s, t) in [-1, 1]^2 along u and v.
struct Rectangle {
    Point center;
    Eigen::Vector3d halfU, halfV;
    Point at(double s, double t) const { return center + s * halfU + t * halfV; }
};

// Diagonal lines s - t = c across the rectangle.
void addHatching(LineBatch& lines, const Rectangle& rect) {
    for (int k = 1; k <= kHatchLines; ++k) {
        const double c = -2.0 + 4.0 * k / (kHatchLines + 1);
        const double from = std::max(-1.0, c - 1.0);
        const double to = std::min(1.0, c + 1.0);
        lines.add(rect.at(from, from - c), rect.at(to, to - c), kDetectorColour);
    }
}

// The image summed into blocks of at most kMaxDrawnImageSide a side, each block one flat quad.
void addImage(TriangleBatch& surfaces, const Rectangle& rect, const DetectorImage& image) {
    const int nx = image.pixels.nx;
    const int ny = image.pixels.ny;
    const int bx = (nx + kMaxDrawnImageSide - 1) / kMaxDrawnImageSide;  // pixels a block, along u and v
    const int by = (ny + kMaxDrawnImageSide - 1) / kMaxDrawnImageSide;
    const int cx = (nx + bx - 1) / bx;
    const int cy = (ny + by - 1) / by;
    std::vector<double> cells(static_cast<std::size_t>(cx) * static_cast<std::size_t>(cy), 0.0);
    for (int iy = 0; iy < ny; ++iy) {
        for (int ix = 0; ix < nx; ++ix) {
            cells[static_cast<std::size_t>(iy / by) * static_cast<std::size_t>(cx) +
                  static_cast<std::size_t>(ix / bx)] += image.values[image.pixels.index(ix, iy)];
        }
    }
    const double peak = *std::max_element(cells.begin(), cells.end());
    const auto s = [&](int column) { return -1.0 + 2.0 * std::min(column * bx, nx) / nx; };
    const auto t = [&](int row) { return -1.0 + 2.0 * std::min(row * by, ny) / ny; };
    for (int row = 0; row < cy; ++row) {
        for (int column = 0; column < cx; ++column) {
            const double value =
                cells[static_cast<std::size_t>(row) * static_cast<std::size_t>(cx) + static_cast<std::size_t>(column)];
            const Colour colour = viridis(peak > 0.0 ? value / peak : 0.0);
            surfaces.addQuad(rect.at(s(column), t(row)), rect.at(s(column + 1), t(row)),
                             rect.at(s(column + 1), t(row + 1)), rect.at(s(column), t(row + 1)), colour);
        }
    }
}

const DetectorImage* imageOf(const Detector& detector, const std::vector<DetectorImage>& images) {
    for (const DetectorImage& image : images) {
        if (image.name == detector.name && image.pixels.nx == detector.pixels.nx &&
            image.pixels.ny == detector.pixels.ny && image.values.size() == image.pixels.count()) {
            return &image;
        }
    }
    return nullptr;
}

void addPlane(LineBatch& lines, TriangleBatch& surfaces, const Detector& plane, const DetectorImage* image,
              double size) {
    const PlaneFrame frame = planeFrame(plane);
    const Rectangle rect{plane.center, 0.5 * plane.size[0] * frame.u, 0.5 * plane.size[1] * frame.v};
    const Point corners[4] = {rect.at(-1, -1), rect.at(1, -1), rect.at(1, 1), rect.at(-1, 1)};
    for (int k = 0; k < 4; ++k) lines.add(corners[k], corners[(k + 1) % 4], kDetectorColour);
    lines.add(plane.center, rect.at(1, 0), kDetectorAxisU);
    lines.add(plane.center, rect.at(0, 1), kDetectorAxisV);
    const double arrow = planeArrowLength(plane, size);
    if (plane.side != DetectorSide::Back) addArrow(lines, plane.center, frame.n, frame.u, arrow);
    if (plane.side != DetectorSide::Front) addArrow(lines, plane.center, -frame.n, frame.u, arrow);
    if (plane.absorbing) addHatching(lines, rect);
    if (image) {
        addImage(surfaces, rect, *image);
    } else if (plane.absorbing) {
        surfaces.addQuad(corners[0], corners[1], corners[2], corners[3], kAbsorbingFill);
    }
}

void addFarField(LineBatch& lines, const Detector& camera, const Eigen::AlignedBox3d& bounds, double size) {
    const FarFieldCamera frame(camera);
    const Point eye = farFieldGlyphEye(camera, bounds, size);
    const double halfAngle = 0.5 * std::min(camera.fovDeg, kMaxDrawnFovDeg) * std::numbers::pi / 180.0;
    const double halfWidth = size * std::tan(halfAngle);
    const double halfHeight = halfWidth * camera.pixels.ny / camera.pixels.nx;
    const Point middle = eye + size * frame.look();
    const Eigen::Vector3d right = halfWidth * frame.right();
    const Eigen::Vector3d up = halfHeight * frame.upAxis();
    const Point corners[4] = {middle - right - up, middle + right - up, middle + right + up, middle - right + up};
    for (int k = 0; k < 4; ++k) {
        lines.add(eye, corners[k], kDetectorColour);
        lines.add(corners[k], corners[(k + 1) % 4], kDetectorColour);
    }
    // The up tick: a small triangle over the top edge.
    const Point peak = middle + (1.0 + kUpTick) * up;
    lines.add(middle - kUpTick * right + up, peak, kDetectorAxisV);
    lines.add(peak, middle + kUpTick * right + up, kDetectorAxisV);
}

}  // namespace

std::vector<DetectorImage> planeDetectorImages(const ResultReport& report, const std::vector<Detector>& detectors) {
    std::vector<DetectorImage> images;
    for (const Detector& detector : detectors) {
        if (detector.type != DetectorType::Plane) continue;
        const ResultTable* table = report.table(detectorTableName(detector));
        if (!table || table->rows() != detector.pixels.count()) continue;
        const ResultColumn* fraction = table->column("fraction");
        const auto* values = fraction ? std::get_if<std::vector<double>>(&fraction->values) : nullptr;
        if (values) images.push_back({detector.name, detector.pixels, *values});
    }
    return images;
}

double planeArrowLength(const Detector& plane, double size) {
    return std::max(size, kArrowOfSide * std::min(plane.size[0], plane.size[1]));
}

Point farFieldGlyphEye(const Detector& camera, const Eigen::AlignedBox3d& bounds, double size) {
    return bounds.center() - (0.5 * bounds.diagonal().norm() + size) * camera.look.vector();
}

Eigen::AlignedBox3d withDetectorGlyphs(Eigen::AlignedBox3d box, const std::vector<Detector>& detectors,
                                       const Eigen::AlignedBox3d& bounds, double size) {
    for (const Detector& detector : detectors) {
        if (detector.type == DetectorType::Plane) {
            const PlaneFrame frame = planeFrame(detector);
            const Rectangle rect{detector.center, 0.5 * detector.size[0] * frame.u, 0.5 * detector.size[1] * frame.v};
            for (const double s : {-1.0, 1.0}) {
                for (const double t : {-1.0, 1.0}) box.extend(rect.at(s, t));
            }
        } else if (detector.type == DetectorType::FarField) {
            box.extend(farFieldGlyphEye(detector, bounds, size));
        }
    }
    return box;
}

void addDetectorGlyphs(LineBatch& lines, TriangleBatch& surfaces, const std::vector<Detector>& detectors,
                       const std::vector<DetectorImage>& images, const Eigen::AlignedBox3d& bounds, double size) {
    for (const Detector& detector : detectors) {
        switch (detector.type) {
        case DetectorType::Plane: addPlane(lines, surfaces, detector, imageOf(detector, images), size); break;
        case DetectorType::FarField: addFarField(lines, detector, bounds, size); break;
        case DetectorType::ShapeAbsorption: break;
        }
    }
}

}  // namespace dropscope::render
