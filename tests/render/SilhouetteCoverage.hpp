#pragma once

// Pixel coverage of a drawn shape against where its silhouette should be: the exact coverage of its
// eye rays (pixelRay, distanceToSurface) or a closed form, pixel by pixel with a band along the edge.
#include "geometry/Shape.hpp"
#include "render/Camera.hpp"
#include "snapshot/Image.hpp"

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace dropscope::test {

// A scene of one shape, as buildShapeInstances and uploadScene take it.
std::vector<std::unique_ptr<Shape>> oneShape(std::unique_ptr<Shape> shape);

// How many pixels of the image are not background.
int coveredPixels(const snapshot::Image& image);

// Whether the eye ray through each pixel centre meets the shape (its distanceToSurface is a number).
class ExactCoverage {
public:
    ExactCoverage(const Shape& shape, const render::Camera& camera, int width, int height);
    // Whether the ray meets any of the shapes (each tried only where its bounds meet the ray).
    ExactCoverage(const std::vector<std::unique_ptr<Shape>>& shapes, const render::Camera& camera, int width,
                  int height);

    bool hit(int x, int y) const { return hit_[index(x, y)] != 0; }
    // Within one pixel of the exact silhouette: some 8-neighbour is classified the other way, by the union
    // of the shapes or (with several) by one shape alone.
    bool onBoundary(int x, int y) const;
    int hits() const;
    int width() const { return width_; }
    int height() const { return height_; }

private:
    std::size_t index(int x, int y) const { return static_cast<std::size_t>(y * width_ + x); }

    int width_;
    int height_;
    std::vector<char> hit_;
    std::vector<char> silhouette_;  // with several shapes: on some shape's own silhouette (onBoundary)
};

// How a drawing's coverage agrees with the expected one.
struct CoverageAgreement {
    int outsideBand = 0;     // pixels away from the silhouette decided the other way
    int band = 0;            // pixels along the silhouette
    int bandMismatches = 0;  // of those, the ones decided the other way
};

// Every pixel of `image`, covered or background, against `expected(x, y)`. A pixel for which `inBand(x, y)`
// (along the expected silhouette) counts into band and bandMismatches; elsewhere a mismatch counts into
// outsideBand, and the first five are reported as test failures, followed by `note(x, y)`.
CoverageAgreement compareCoverage(const snapshot::Image& image, const std::function<bool(int, int)>& expected,
                                  const std::function<bool(int, int)>& inBand,
                                  const std::function<std::string(int, int)>& note);

// The same against a shape's exact coverage, its band the one-pixel boundary (ExactCoverage::onBoundary).
CoverageAgreement compareCoverage(const snapshot::Image& image, const ExactCoverage& coverage);

// Expects the drawing to cover exactly the pixels whose rays meet the shape, but for at most kBandMismatchShare
// of the one-pixel band along its silhouette.
void expectCoversExactly(const snapshot::Image& image, const ExactCoverage& coverage);

}  // namespace dropscope::test
