#include "render/ApartSpheres.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dropscope::render {

namespace {

// A sphere goes into every cell its bounding box, grown by this fraction of a cell, meets: a contact's cells
// found in double precision then cannot miss it by a rounding at a cell's face.
constexpr double kCellGrowth = 1e-4;

float squaredDistanceToSegment(const glm::vec3& c, const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 ab = b - a;
    const float length2 = glm::dot(ab, ab);
    const float t = length2 > 0.0f ? std::clamp(glm::dot(c - a, ab) / length2, 0.0f, 1.0f) : 0.0f;
    const glm::vec3 off = a + t * ab - c;
    return glm::dot(off, off);
}

float squaredDistanceToBox(const glm::vec3& c, const glm::vec3& low, const glm::vec3& high) {
    const glm::vec3 off = glm::max(glm::max(low - c, c - high), glm::vec3(0.0f));
    return glm::dot(off, off);
}

// Reaches deeper than kApartReach of `radius` into a sphere: closer to its centre than that.
bool within(float squaredDistance, float radius) {
    const float reach = radius * (1.0f - kApartReach);
    return squaredDistance < reach * reach;
}

}  // namespace

ApartSpheres::Ball ApartSpheres::boundingBall(const ShapeInstance& rounded) {
    float largest = 0.0f;
    for (std::size_t column = 0; column < 3; ++column) {
        const float* v = &rounded.linear[3 * column];
        largest = std::max(largest, glm::length(glm::vec3(v[0], v[1], v[2])));
    }
    return {glm::vec3(rounded.center[0], rounded.center[1], rounded.center[2]), largest};
}

void ApartSpheres::setShapes(const std::vector<ShapeInstance>& rounded, const std::vector<Ball>& otherShapes) {
    spheres_.clear();
    spheres_.reserve(rounded.size());
    shapeBalls_ = otherShapes;
    for (const ShapeInstance& shape : rounded) {
        const glm::vec3 centre(shape.center[0], shape.center[1], shape.center[2]);
        if (isSphereInstance(shape)) {
            spheres_.push_back({centre, glm::length(glm::vec3(shape.linear[0], shape.linear[1], shape.linear[2]))});
            continue;
        }
        spheres_.push_back({centre, -1.0f});
        shapeBalls_.push_back(boundingBall(shape));
    }
    gridDirty_ = true;  // built when first asked for (compute)
    shapesDirty_ = true;
    dirty_ = true;
}

void ApartSpheres::setSegments(const std::vector<LineVertex>& segments) {
    segments_.clear();
    segments_.reserve(segments.size());
    for (const LineVertex& vertex : segments) {
        segments_.emplace_back(vertex.position[0], vertex.position[1], vertex.position[2]);
    }
    dirty_ = true;
}

void ApartSpheres::setMarkers(const std::vector<ShapeInstance>& markers) {
    markers_.clear();
    for (const ShapeInstance& marker : markers) markers_.push_back(boundingBall(marker));
    dirty_ = true;
}

void ApartSpheres::setTriangles(const std::vector<LineVertex>& triangles) {
    boxes_.clear();
    for (std::size_t k = 0; k + 2 < triangles.size(); k += 3) {
        glm::vec3 low(std::numeric_limits<float>::max());
        glm::vec3 high(std::numeric_limits<float>::lowest());
        for (std::size_t corner = k; corner < k + 3; ++corner) {
            const glm::vec3 p(triangles[corner].position[0], triangles[corner].position[1],
                              triangles[corner].position[2]);
            low = glm::min(low, p);
            high = glm::max(high, p);
        }
        boxes_.push_back({low, high});
    }
    dirty_ = true;
}

const std::vector<std::uint8_t>& ApartSpheres::apart() {
    if (dirty_) compute();
    return apart_;
}

bool ApartSpheres::takeChanged() {
    if (dirty_) compute();
    const bool changed = changed_;
    changed_ = false;
    return changed;
}

void ApartSpheres::buildGrid() {
    cellStart_.clear();
    cellSpheres_.clear();
    dims_ = {0, 0, 0};
    std::vector<float> radii;
    glm::vec3 low(std::numeric_limits<float>::max());
    glm::vec3 high(std::numeric_limits<float>::lowest());
    for (const Ball& sphere : spheres_) {
        if (sphere.radius < 0.0f) continue;
        radii.push_back(sphere.radius);
        low = glm::min(low, sphere.centre - sphere.radius);
        high = glm::max(high, sphere.centre + sphere.radius);
    }
    if (radii.empty()) return;
    const std::size_t count = radii.size();
    // Cells about as many as the spheres and at least as wide as nine in ten of them, so most spheres meet at
    // most eight; wider while the cells or the references they would need are many more than the spheres.
    const auto tenth = radii.begin() + static_cast<std::ptrdiff_t>(9 * (count - 1) / 10);
    std::nth_element(radii.begin(), tenth, radii.end());
    const glm::vec3 extent = high - low;
    const double volume = std::max(static_cast<double>(extent.x), 1e-30) *
                          std::max(static_cast<double>(extent.y), 1e-30) *
                          std::max(static_cast<double>(extent.z), 1e-30);
    double side = std::max({2.0 * static_cast<double>(*tenth), std::cbrt(volume / static_cast<double>(count)), 1e-30});
    low_ = low;
    for (;;) {
        double cells = 1.0;
        for (int axis = 0; axis < 3; ++axis) cells *= std::floor(static_cast<double>(extent[axis]) / side) + 1.0;
        if (cells <= 4.0 * static_cast<double>(count) + 64.0 && makeGrid(static_cast<float>(side))) return;
        side *= 1.5;
    }
}

bool ApartSpheres::makeGrid(float side) {
    side_ = side;
    glm::vec3 high(std::numeric_limits<float>::lowest());
    for (const Ball& sphere : spheres_) {
        if (sphere.radius >= 0.0f) high = glm::max(high, sphere.centre + sphere.radius);
    }
    for (std::size_t axis = 0; axis < 3; ++axis) {
        dims_[axis] = static_cast<int>(std::floor((static_cast<double>(high[static_cast<int>(axis)]) -
                                                   static_cast<double>(low_[static_cast<int>(axis)])) /
                                                  static_cast<double>(side))) +
                      1;
    }
    const std::size_t cells =
        static_cast<std::size_t>(dims_[0]) * static_cast<std::size_t>(dims_[1]) * static_cast<std::size_t>(dims_[2]);
    const auto cellRange = [&](const Ball& sphere) {
        const glm::vec3 grow(static_cast<float>(kCellGrowth) * side);
        return std::pair{cellOf(sphere.centre - sphere.radius - grow), cellOf(sphere.centre + sphere.radius + grow)};
    };
    // Counted, then placed: each sphere in every cell its grown box meets.
    std::vector<std::uint32_t> start(cells + 1, 0);
    std::size_t references = 0;
    const std::size_t mostReferences = 16 * spheres_.size() + 1024;
    for (const Ball& sphere : spheres_) {
        if (sphere.radius < 0.0f) continue;
        const auto [from, to] = cellRange(sphere);
        references += static_cast<std::size_t>(to[0] - from[0] + 1) * static_cast<std::size_t>(to[1] - from[1] + 1) *
                      static_cast<std::size_t>(to[2] - from[2] + 1);
        if (references > mostReferences) return false;
        for (int z = from[2]; z <= to[2]; ++z)
            for (int y = from[1]; y <= to[1]; ++y)
                for (int x = from[0]; x <= to[0]; ++x) ++start[slot({x, y, z}) + 1];
    }
    for (std::size_t k = 0; k < cells; ++k) start[k + 1] += start[k];
    cellSpheres_.assign(references, 0);
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < spheres_.size(); ++i) {
        if (spheres_[i].radius < 0.0f) continue;
        const auto [from, to] = cellRange(spheres_[i]);
        for (int z = from[2]; z <= to[2]; ++z)
            for (int y = from[1]; y <= to[1]; ++y)
                for (int x = from[0]; x <= to[0]; ++x)
                    cellSpheres_[next[slot({x, y, z})]++] = static_cast<std::uint32_t>(i);
    }
    cellStart_ = std::move(start);
    return true;
}

std::size_t ApartSpheres::slot(const Cell& cell) const {
    return (static_cast<std::size_t>(cell[2]) * static_cast<std::size_t>(dims_[1]) +
            static_cast<std::size_t>(cell[1])) *
               static_cast<std::size_t>(dims_[0]) +
           static_cast<std::size_t>(cell[0]);
}

ApartSpheres::Cell ApartSpheres::cellOf(const glm::vec3& p) const {
    Cell cell;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        const int a = static_cast<int>(axis);
        const double at =
            std::floor((static_cast<double>(p[a]) - static_cast<double>(low_[a])) / static_cast<double>(side_));
        cell[axis] = static_cast<int>(std::clamp(at, 0.0, static_cast<double>(dims_[axis] - 1)));
    }
    return cell;
}

template <class F>
void ApartSpheres::forEachSphereInBox(const glm::vec3& low, const glm::vec3& high, F&& f) const {
    if (cellStart_.empty()) return;
    const glm::vec3 gridHigh = low_ + side_ * glm::vec3(dims_[0], dims_[1], dims_[2]);
    if (glm::any(glm::greaterThan(low, gridHigh)) || glm::any(glm::lessThan(high, low_))) return;
    const Cell from = cellOf(low);
    const Cell to = cellOf(high);
    for (int z = from[2]; z <= to[2]; ++z)
        for (int y = from[1]; y <= to[1]; ++y)
            for (int x = from[0]; x <= to[0]; ++x) {
                const std::size_t k = slot({x, y, z});
                for (std::uint32_t r = cellStart_[k]; r < cellStart_[k + 1]; ++r) f(cellSpheres_[r]);
            }
}

// The cells the segment passes through, one after the next (a 3D DDA in double precision), clipped to the grid.
template <class F>
void ApartSpheres::forEachSphereOnSegment(const glm::vec3& a, const glm::vec3& b, F&& f) const {
    if (cellStart_.empty()) return;
    const glm::dvec3 from(a);
    const glm::dvec3 d = glm::dvec3(b) - from;
    const glm::dvec3 low(low_);
    const glm::dvec3 high = low + static_cast<double>(side_) * glm::dvec3(dims_[0], dims_[1], dims_[2]);
    double t0 = 0.0;
    double t1 = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0.0) {
            if (from[axis] < low[axis] || from[axis] > high[axis]) return;
            continue;
        }
        const double u = (low[axis] - from[axis]) / d[axis];
        const double v = (high[axis] - from[axis]) / d[axis];
        t0 = std::max(t0, std::min(u, v));
        t1 = std::min(t1, std::max(u, v));
    }
    if (t0 > t1) return;
    const double side = side_;
    Cell cell = cellOf(glm::vec3(from + t0 * d));
    int step[3];
    double next[3];
    double delta[3];
    for (std::size_t axis = 0; axis < 3; ++axis) {
        const int i = static_cast<int>(axis);
        step[axis] = d[i] > 0.0 ? 1 : d[i] < 0.0 ? -1 : 0;
        if (step[axis] == 0) {
            next[axis] = std::numeric_limits<double>::infinity();
            delta[axis] = std::numeric_limits<double>::infinity();
        } else {
            const double plane = low[i] + side * (cell[axis] + (step[axis] > 0 ? 1 : 0));
            next[axis] = (plane - from[i]) / d[i];
            delta[axis] = side / std::abs(d[i]);
        }
    }
    for (;;) {
        const std::size_t k = slot(cell);
        for (std::uint32_t r = cellStart_[k]; r < cellStart_[k + 1]; ++r) f(cellSpheres_[r]);
        const std::size_t axis = next[0] <= next[1] ? (next[0] <= next[2] ? 0 : 2) : (next[1] <= next[2] ? 1 : 2);
        if (next[axis] > t1) return;
        cell[axis] += step[axis];
        if (cell[axis] < 0 || cell[axis] >= dims_[axis]) return;
        next[axis] += delta[axis];
    }
}

void ApartSpheres::touchByBalls(const std::vector<Ball>& balls, std::vector<std::uint8_t>& flags) const {
    // A ball reaches into a sphere when the two overlap; the pair meets in a cell both are in.
    for (const Ball& ball : balls) {
        if (ball.radius < 0.0f) continue;  // an ellipsoid's place in spheres_
        forEachSphereInBox(ball.centre - ball.radius, ball.centre + ball.radius, [&](std::uint32_t i) {
            const glm::vec3 off = spheres_[i].centre - ball.centre;
            const float reach = (spheres_[i].radius + ball.radius) * (1.0f - kApartReach);
            if (glm::dot(off, off) < reach * reach) flags[i] = 0;
        });
    }
}

void ApartSpheres::compute() {
    if (gridDirty_) {
        buildGrid();
        gridDirty_ = false;
    }
    if (shapesDirty_) {
        shapesApart_.assign(spheres_.size(), 0);
        for (std::size_t i = 0; i < spheres_.size(); ++i) shapesApart_[i] = spheres_[i].radius >= 0.0f ? 1 : 0;
        touchByBalls(shapeBalls_, shapesApart_);
        // Two spheres that overlap share a cell (a point of both their boxes): each cell's pairs.
        for (std::size_t k = 0; k + 1 < cellStart_.size(); ++k) {
            for (std::uint32_t r = cellStart_[k]; r < cellStart_[k + 1]; ++r) {
                const Ball& a = spheres_[cellSpheres_[r]];
                for (std::uint32_t q = r + 1; q < cellStart_[k + 1]; ++q) {
                    const Ball& b = spheres_[cellSpheres_[q]];
                    const glm::vec3 off = b.centre - a.centre;
                    const float reach = (a.radius + b.radius) * (1.0f - kApartReach);
                    if (glm::dot(off, off) < reach * reach) {
                        shapesApart_[cellSpheres_[r]] = 0;
                        shapesApart_[cellSpheres_[q]] = 0;
                    }
                }
            }
        }
        shapesDirty_ = false;
    }
    apart_ = shapesApart_;
    touchByBalls(markers_, apart_);
    const auto touch = [&](std::uint32_t i, float squaredDistance) {
        if (within(squaredDistance, spheres_[i].radius)) apart_[i] = 0;
    };
    for (std::size_t k = 0; k + 1 < segments_.size(); k += 2) {
        const glm::vec3& a = segments_[k];
        const glm::vec3& b = segments_[k + 1];
        forEachSphereOnSegment(a, b,
                               [&](std::uint32_t i) { touch(i, squaredDistanceToSegment(spheres_[i].centre, a, b)); });
    }
    for (const auto& [low, high] : boxes_) {
        forEachSphereInBox(low, high,
                           [&](std::uint32_t i) { touch(i, squaredDistanceToBox(spheres_[i].centre, low, high)); });
    }
    dirty_ = false;
    changed_ = true;
}

}  // namespace dropscope::render
