#include "render/SilhouetteCoverage.hpp"

#include "render/RenderHarness.hpp"
#include "render/RenderTolerances.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace dropscope::test {

std::vector<std::unique_ptr<Shape>> oneShape(std::unique_ptr<Shape> shape) {
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::move(shape));
    return shapes;
}

int coveredPixels(const snapshot::Image& image) {
    int covered = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) covered += isBlack(image, x, y) ? 0 : 1;
    }
    return covered;
}

ExactCoverage::ExactCoverage(const Shape& shape, const render::Camera& camera, int width, int height)
    : width_(width), height_(height), hit_(static_cast<std::size_t>(width * height)) {
    const Point eye(camera.eye.x, camera.eye.y, camera.eye.z);
    for (int y = 0; y < height_; ++y) {
        for (int x = 0; x < width_; ++x) {
            const double t = shape.distanceToSurface(eye, pixelRay(camera, x, y, width_, height_));
            hit_[index(x, y)] = std::isnan(t) ? 0 : 1;
        }
    }
}

ExactCoverage::ExactCoverage(const std::vector<std::unique_ptr<Shape>>& shapes, const render::Camera& camera, int width,
                             int height)
    : width_(width),
      height_(height),
      hit_(static_cast<std::size_t>(width * height)),
      silhouette_(static_cast<std::size_t>(width * height)) {
    const Point eye(camera.eye.x, camera.eye.y, camera.eye.z);
    constexpr double kMiss = std::numeric_limits<double>::infinity();
    // Each shape tried only where its bounds (grown by `slack`) meet the ray.
    const auto distance = [&](const Shape& shape, const Direction& ray, double slack) {
        const Eigen::AlignedBox3d box = shape.bounds();
        if (Eigen::ParametrizedLine<double, 3>(eye, ray).distance(box.center()) > 0.5 * box.diagonal().norm() + slack)
            return kMiss;
        const double t = shape.distanceToSurface(eye, ray);
        return std::isnan(t) ? kMiss : t;
    };
    // The nearest hit through every pixel and the ring of pixels around the image.
    const int paddedWidth = width_ + 2;
    std::vector<double> nearest(static_cast<std::size_t>(paddedWidth * (height_ + 2)), kMiss);
    const auto nearestAt = [&](int x, int y) -> double& {
        return nearest[static_cast<std::size_t>((y + 1) * paddedWidth + x + 1)];
    };
    for (int y = -1; y <= height_; ++y) {
        for (int x = -1; x <= width_; ++x) {
            const Direction ray = pixelRay(camera, x, y, width_, height_);
            for (const auto& shape : shapes) nearestAt(x, y) = std::min(nearestAt(x, y), distance(*shape, ray, 0.0));
            if (x >= 0 && x < width_ && y >= 0 && y < height_) hit_[index(x, y)] = nearestAt(x, y) < kMiss ? 1 : 0;
        }
    }
    // A shape's own silhouette through this pixel, where it is in front: its rays here and at some 8-neighbour
    // meet it differently, and it is the nearest shape on the side that meets it. Where shapes overlap on
    // screen the union's boundary misses such a pixel, and a ray that grazes a shape is a coin toss for any
    // rasteriser; outlines hidden behind nearer shapes stay outside the band.
    for (int y = 0; y < height_; ++y) {
        for (int x = 0; x < width_; ++x) {
            std::array<Direction, 9> rays;  // this pixel's (4) and its neighbours'
            for (int k = 0; k < 9; ++k) rays[k] = pixelRay(camera, x + k % 3 - 1, y + k / 3 - 1, width_, height_);
            // The sine of the angle between the rays of diagonal neighbours, twice: at a shape's distance, a
            // neighbour's ray passes within that times the distance of this pixel's.
            const double spread = 2.0 * rays[4].vector().cross(rays[8].vector()).norm();
            const Eigen::ParametrizedLine<double, 3> line(eye, rays[4]);
            for (const auto& shape : shapes) {
                const Eigen::AlignedBox3d box = shape->bounds();
                const double slack = spread * (box.center() - eye).norm();
                if (line.distance(box.center()) > 0.5 * box.diagonal().norm() + slack) continue;
                const double here = distance(*shape, rays[4], slack);
                for (int k = 0; k < 9; ++k) {
                    const double there = distance(*shape, rays[k], slack);
                    if ((here < kMiss) == (there < kMiss)) continue;
                    if (here < kMiss ? here == nearestAt(x, y) : there == nearestAt(x + k % 3 - 1, y + k / 3 - 1)) {
                        silhouette_[index(x, y)] = 1;
                        break;
                    }
                }
                if (silhouette_[index(x, y)]) break;
            }
        }
    }
}

bool ExactCoverage::onBoundary(int x, int y) const {
    if (!silhouette_.empty() && silhouette_[index(x, y)]) return true;
    const char here = hit_[index(x, y)];
    for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, height_ - 1); ++ny) {
        for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, width_ - 1); ++nx) {
            if (hit_[index(nx, ny)] != here) return true;
        }
    }
    return false;
}

int ExactCoverage::hits() const { return static_cast<int>(std::count(hit_.begin(), hit_.end(), 1)); }

CoverageAgreement compareCoverage(const snapshot::Image& image, const std::function<bool(int, int)>& expected,
                                  const std::function<bool(int, int)>& inBand,
                                  const std::function<std::string(int, int)>& note) {
    constexpr int kReportedMismatches = 5;  // enough to see the pattern, not a page per wrong pixel
    CoverageAgreement agreement;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const bool covered = !isBlack(image, x, y);
            const bool mismatch = covered != expected(x, y);
            if (!inBand(x, y)) {
                agreement.outsideBand += mismatch ? 1 : 0;
                EXPECT_FALSE(mismatch && agreement.outsideBand <= kReportedMismatches)
                    << "pixel (" << x << ", " << y << ") is " << (covered ? "covered" : "background") << ", expected "
                    << (covered ? "background" : "covered") << note(x, y);
            } else {
                ++agreement.band;
                agreement.bandMismatches += mismatch ? 1 : 0;
            }
        }
    }
    return agreement;
}

CoverageAgreement compareCoverage(const snapshot::Image& image, const ExactCoverage& coverage) {
    if (image.width != coverage.width() || image.height != coverage.height()) {
        ADD_FAILURE() << "a " << image.width << " x " << image.height << " image against a " << coverage.width()
                      << " x " << coverage.height() << " coverage";
        return {};
    }
    return compareCoverage(
        image, [&](int x, int y) { return coverage.hit(x, y); },
        [&](int x, int y) { return coverage.onBoundary(x, y); },
        [](int, int) { return std::string(" (by the shape's exact ray test)"); });
}

void expectCoversExactly(const snapshot::Image& image, const ExactCoverage& coverage) {
    const CoverageAgreement agreement = compareCoverage(image, coverage);
    EXPECT_EQ(agreement.outsideBand, 0) << "pixels away from the silhouette where the drawing and the shape disagree";
    EXPECT_LE(agreement.bandMismatches, kBandMismatchShare * agreement.band)
        << "of " << agreement.band << " pixels along the silhouette";
}

}  // namespace dropscope::test
