#include "render/ApartSpheres.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dropscope::render {

namespace {

// A sphere goes into every cell its bounding box, grown by this fraction of a cell, meets: a contact's cells
// found in double precision then cannot miss it by a rounding at a cell's face.
constexpr double kCellGrowth = 1e-4;

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool isFiniteBall(const ApartSpheres::Ball& ball) { return isFinite(ball.centre) && std::isfinite(ball.radius); }

float squaredDistanceToSegment(const glm::vec3& c, const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 ab = b - a;
    const float length2 = glm::dot(ab, ab);
    const float t = length2 > 0.0f ? std::clamp(glm::dot(c - a, ab) / length2, 0.0f, 1.0f) : 0.0f;
    const glm::vec3 off = a + t * ab - c;
    return glm::dot(off, off);
}

// The nearest point of triangle abc to p, by which of its regions (corner, edge, face) p projects into
// (Ericson, Real-Time Collision Detection, 5.1.5); a triangle without area is its three edges.
float squaredDistanceToTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const auto squared = [&](const glm::vec3& q) { return glm::dot(q - p, q - p); };
    const glm::vec3 ab = b - a;
    const glm::vec3 ac = c - a;
    const float d1 = glm::dot(ab, p - a);
    const float d2 = glm::dot(ac, p - a);
    if (d1 <= 0.0f && d2 <= 0.0f) return squared(a);
    const float d3 = glm::dot(ab, p - b);
    const float d4 = glm::dot(ac, p - b);
    if (d3 >= 0.0f && d4 <= d3) return squared(b);
    const float d5 = glm::dot(ab, p - c);
    const float d6 = glm::dot(ac, p - c);
    if (d6 >= 0.0f && d5 <= d6) return squared(c);
    const float vc = d1 * d4 - d3 * d2;
    const float vb = d5 * d2 - d1 * d6;
    const float va = d3 * d6 - d5 * d4;
    if (!(va + vb + vc > 0.0f)) {
        return std::min(
            {squaredDistanceToSegment(p, a, b), squaredDistanceToSegment(p, b, c), squaredDistanceToSegment(p, c, a)});
    }
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return squared(a + d1 / (d1 - d3) * ab);
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return squared(a + d2 / (d2 - d6) * ac);
    if (va <= 0.0f && d4 - d3 >= 0.0f && d5 - d6 >= 0.0f) {
        return squared(b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b));
    }
    const float inverse = 1.0f / (va + vb + vc);
    return squared(a + ab * (vb * inverse) + ac * (vc * inverse));
}

// Reaches deeper than kApartReach of `radius` into a sphere: closer to its centre than that.
bool within(float squaredDistance, float radius) {
    const float reach = radius * (1.0f - kApartReach);
    return squaredDistance < reach * reach;
}

// Two balls that overlap by more than kApartReach of the smaller one's radius.
bool overlap(const ApartSpheres::Ball& a, const ApartSpheres::Ball& b) {
    const glm::vec3 off = b.centre - a.centre;
    const float reach = a.radius + b.radius - kApartReach * std::min(a.radius, b.radius);
    return glm::dot(off, off) < reach * reach;
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
        const Ball ball = boundingBall(shape);
        if (isSphereInstance(shape)) {
            spheres_.push_back(ball);
        } else {
            spheres_.push_back({ball.centre, -1.0f});
            shapeBalls_.push_back(ball);
        }
    }
    finiteShapes_ = std::all_of(shapeBalls_.begin(), shapeBalls_.end(), isFiniteBall) &&
                    std::all_of(spheres_.begin(), spheres_.end(), isFiniteBall);
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
    finiteSegments_ = std::all_of(segments_.begin(), segments_.end(), isFinite);
    dirty_ = true;
}

void ApartSpheres::setMarkers(const std::vector<ShapeInstance>& markers) {
    markers_.clear();
    for (const ShapeInstance& marker : markers) markers_.push_back(boundingBall(marker));
    finiteMarkers_ = std::all_of(markers_.begin(), markers_.end(), isFiniteBall);
    dirty_ = true;
}

void ApartSpheres::setTriangles(const std::vector<LineVertex>& triangles) {
    triangles_.clear();
    for (std::size_t k = 0; k + 2 < triangles.size(); k += 3) {
        for (std::size_t corner = k; corner < k + 3; ++corner) {
            const auto& p = triangles[corner].position;
            triangles_.emplace_back(p[0], p[1], p[2]);
        }
    }
    finiteTriangles_ = std::all_of(triangles_.begin(), triangles_.end(), isFinite);
    dirty_ = true;
}

const std::vector<std::uint8_t>& ApartSpheres::apart() {
    if (dirty_) compute();
    return apart_;
}

bool ApartSpheres::takeUpdated() {
    if (dirty_) compute();
    const bool updated = updated_;
    updated_ = false;
    return updated;
}

bool ApartSpheres::buildGrid() {
    cellStart_.clear();
    cellSpheres_.clear();
    dims_ = {0, 0, 0};
    std::vector<double> radii;
    glm::dvec3 low(std::numeric_limits<double>::max());
    glm::dvec3 high(std::numeric_limits<double>::lowest());
    for (const Ball& sphere : spheres_) {
        if (sphere.radius < 0.0f) continue;
        radii.push_back(sphere.radius);
        low = glm::min(low, glm::dvec3(sphere.centre) - static_cast<double>(sphere.radius));
        high = glm::max(high, glm::dvec3(sphere.centre) + static_cast<double>(sphere.radius));
    }
    if (radii.empty()) return true;
    const double count = static_cast<double>(radii.size());
    // Cells about as many as the spheres and at least as wide as nine in ten of them, so most spheres meet at
    // most eight; wider while the cells or the references they would need are many more than the spheres. The
    // coordinates are finite floats, so the extent is a finite double.
    const auto tenth = radii.begin() + static_cast<std::ptrdiff_t>(9 * (radii.size() - 1) / 10);
    std::nth_element(radii.begin(), tenth, radii.end());
    const glm::dvec3 extent = high - low;
    constexpr double kLeast = 1e-30;
    const double volume = std::max(extent.x, kLeast) * std::max(extent.y, kLeast) * std::max(extent.z, kLeast);
    double side = std::max({2.0 * *tenth, std::cbrt(volume / count), kLeast});
    for (int attempt = 0; attempt < 200; ++attempt, side *= 1.5) {
        double cells = 1.0;
        for (int axis = 0; axis < 3; ++axis) cells *= std::floor(extent[axis] / side) + 1.0;
        if (cells <= 4.0 * count + 64.0 && makeGrid(low, high, side)) return true;
    }
    return false;
}

bool ApartSpheres::makeGrid(const glm::dvec3& low, const glm::dvec3& high, double side) {
    low_ = low;
    side_ = side;
    for (int axis = 0; axis < 3; ++axis)
        dims_[static_cast<std::size_t>(axis)] = static_cast<int>(std::floor((high[axis] - low[axis]) / side)) + 1;
    const std::size_t cells =
        static_cast<std::size_t>(dims_[0]) * static_cast<std::size_t>(dims_[1]) * static_cast<std::size_t>(dims_[2]);
    const auto cellRange = [&](const Ball& sphere) {
        const auto grow = static_cast<float>(kCellGrowth * side);
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
        const double at = std::floor((static_cast<double>(p[a]) - low_[a]) / side_);
        cell[axis] = static_cast<int>(std::clamp(at, 0.0, static_cast<double>(dims_[axis] - 1)));
    }
    return cell;
}

template <class F>
void ApartSpheres::forEachSphereInBox(const glm::vec3& low, const glm::vec3& high, F&& f) const {
    if (cellStart_.empty()) return;
    const glm::dvec3 gridHigh = low_ + side_ * glm::dvec3(dims_[0], dims_[1], dims_[2]);
    if (glm::any(glm::greaterThan(glm::dvec3(low), gridHigh)) || glm::any(glm::lessThan(glm::dvec3(high), low_)))
        return;
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
    const glm::dvec3 high = low_ + side_ * glm::dvec3(dims_[0], dims_[1], dims_[2]);
    double t0 = 0.0;
    double t1 = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0.0) {
            if (from[axis] < low_[axis] || from[axis] > high[axis]) return;
            continue;
        }
        const double u = (low_[axis] - from[axis]) / d[axis];
        const double v = (high[axis] - from[axis]) / d[axis];
        t0 = std::max(t0, std::min(u, v));
        t1 = std::min(t1, std::max(u, v));
    }
    if (t0 > t1) return;
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
            const double plane = low_[i] + side_ * (cell[axis] + (step[axis] > 0 ? 1 : 0));
            next[axis] = (plane - from[i]) / d[i];
            delta[axis] = side_ / std::abs(d[i]);
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

void ApartSpheres::touchByBalls(const std::vector<Ball>& balls, std::vector<std::uint8_t>& flags) {
    // A ball reaches into a sphere when the two overlap; the pair meets in a cell both are in.
    for (const Ball& ball : balls) {
        if (work_ > budget_) return;
        forEachSphereInBox(ball.centre - ball.radius, ball.centre + ball.radius, [&](std::uint32_t i) {
            ++work_;
            if (overlap(spheres_[i], ball)) flags[i] = 0;
        });
    }
}

bool ApartSpheres::computeShapes() {
    shapesApart_.assign(spheres_.size(), 0);
    if (!finiteShapes_ || !gridBuilt_) return false;
    for (std::size_t i = 0; i < spheres_.size(); ++i) shapesApart_[i] = spheres_[i].radius >= 0.0f ? 1 : 0;
    touchByBalls(shapeBalls_, shapesApart_);
    // Two spheres that overlap share a cell (a point of both their boxes): each cell's pairs.
    for (std::size_t k = 0; k + 1 < cellStart_.size(); ++k) {
        const std::size_t count = cellStart_[k + 1] - cellStart_[k];
        work_ += count * count / 2;
        if (work_ > budget_) break;
        for (std::uint32_t r = cellStart_[k]; r < cellStart_[k + 1]; ++r) {
            for (std::uint32_t q = r + 1; q < cellStart_[k + 1]; ++q) {
                if (overlap(spheres_[cellSpheres_[r]], spheres_[cellSpheres_[q]])) {
                    shapesApart_[cellSpheres_[r]] = 0;
                    shapesApart_[cellSpheres_[q]] = 0;
                }
            }
        }
    }
    return work_ <= budget_;
}

bool ApartSpheres::computeLayers() {
    if (!finiteSegments_ || !finiteMarkers_ || !finiteTriangles_) return false;
    touchByBalls(markers_, apart_);
    const auto touch = [&](std::uint32_t i, float squaredDistance) {
        ++work_;
        if (within(squaredDistance, spheres_[i].radius)) apart_[i] = 0;
    };
    for (std::size_t k = 0; k + 1 < segments_.size() && work_ <= budget_; k += 2) {
        const glm::vec3& a = segments_[k];
        const glm::vec3& b = segments_[k + 1];
        forEachSphereOnSegment(a, b,
                               [&](std::uint32_t i) { touch(i, squaredDistanceToSegment(spheres_[i].centre, a, b)); });
    }
    for (std::size_t k = 0; k + 2 < triangles_.size() && work_ <= budget_; k += 3) {
        const glm::vec3& a = triangles_[k];
        const glm::vec3& b = triangles_[k + 1];
        const glm::vec3& c = triangles_[k + 2];
        forEachSphereInBox(glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c)),
                           [&](std::uint32_t i) { touch(i, squaredDistanceToTriangle(spheres_[i].centre, a, b, c)); });
    }
    return work_ <= budget_;
}

void ApartSpheres::compute() {
    if (gridDirty_ && finiteShapes_) {
        gridBuilt_ = buildGrid();
        gridDirty_ = false;
    }
    const std::size_t contacts = shapeBalls_.size() + markers_.size() + segments_.size() / 2 + triangles_.size() / 3;
    budget_ = kApartWork * (spheres_.size() + contacts);
    if (shapesDirty_) {
        work_ = 0;
        if (!computeShapes()) std::fill(shapesApart_.begin(), shapesApart_.end(), std::uint8_t{0});
        shapesDirty_ = false;
    }
    work_ = 0;
    apart_ = shapesApart_;
    if (!computeLayers()) std::fill(apart_.begin(), apart_.end(), std::uint8_t{0});
    dirty_ = false;
    updated_ = true;
}

}  // namespace dropscope::render
