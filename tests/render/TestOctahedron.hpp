#pragma once

#include "geometry/GeneralShape.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <ostream>

namespace dropscope::test {

// A test-local GeneralShape with an exactly known surface: the octahedron |x - c| + |y - c| + |z - c| =
// size about a base centre c (default 0) in its base frame, placed by an AffineTransform. Its mesh is exact (8 flat
// faces, each with its own three corners and the face normal), so a pixel is covered exactly when the eye ray through
// its centre meets the solid, which distanceToSurface answers exactly (clipping the ray by the 8 face planes). The
// Shape members the render and GUI tests do not look at closely are simple stand-ins.
class TestOctahedron final : public GeneralShape {
public:
    explicit TestOctahedron(double size, const AffineTransform& transform = AffineTransform(),
                            const Point& baseCenter = Point::Zero())
        : GeneralShape(transform), base_(std::make_shared<Base>(size, baseCenter)) {}

    ShapeKind kind() const override { return ShapeKind::Parametric; }
    std::string_view typeName() const override { return "parametric"; }
    std::string_view presetName() const override { return "octahedron"; }
    std::vector<PresetParameter> presetParameters() const override { return {{"size", {}, {base_->size}}}; }
    std::unique_ptr<GeneralShape> withTransform(const AffineTransform& transform) const override {
        auto placed = std::unique_ptr<TestOctahedron>(new TestOctahedron(base_, transform));
        placed->setMediumId(mediumId());
        return placed;
    }

    double xMin() const override { return placedBounds().min().x(); }
    double xMax() const override { return placedBounds().max().x(); }
    double yMin() const override { return placedBounds().min().y(); }
    double yMax() const override { return placedBounds().max().y(); }
    double zMin() const override { return placedBounds().min().z(); }
    double zMax() const override { return placedBounds().max().z(); }

    double surfaceArea() const override {
        const SurfaceMesh placed = mesh();
        double area = 0.0;
        for (const auto& t : placed.triangles) {
            area += 0.5 * (placed.vertices[t[1]] - placed.vertices[t[0]])
                              .cross(placed.vertices[t[2]] - placed.vertices[t[0]])
                              .norm();
        }
        return area;
    }
    double volume() const override {
        return 4.0 / 3.0 * std::pow(base_->size, 3) * std::abs(transform().determinant());
    }

    PointLocation locatePoint(const Point& p) const override {
        const double f = (transform().applyInverse(p) - base_->center).lpNorm<1>() - base_->size;
        if (std::abs(f) <= kBandShare * base_->size) return PointLocation::OnSurface;
        return f < 0.0 ? PointLocation::Inside : PointLocation::Outside;
    }

    // The ray's span inside the solid, clipped by the 8 face planes s.q <= size in the base frame, where
    // the ray is o + t w with the same t as in space.
    double distanceToSurface(const Point& p, const Direction& d) const override {
        if (!d || !p.allFinite()) return std::numeric_limits<double>::quiet_NaN();
        const Eigen::Vector3d o = transform().applyInverse(p) - base_->center;
        const Eigen::Vector3d w = transform().applyInverseToVector(d.vector());
        double enter = -std::numeric_limits<double>::infinity();
        double leave = std::numeric_limits<double>::infinity();
        for (const Eigen::Vector3d& s : signs()) {
            const double along = s.dot(w);
            const double slack = base_->size - s.dot(o);  // >= 0 on the kept side
            if (along == 0.0) {
                if (slack < 0.0) return std::numeric_limits<double>::quiet_NaN();
                continue;
            }
            const double t = slack / along;
            if (along > 0.0)
                leave = std::min(leave, t);
            else
                enter = std::max(enter, t);
        }
        if (!(enter < leave) || leave <= 0.0) return std::numeric_limits<double>::quiet_NaN();
        return enter > 0.0 ? enter : leave;
    }

    Direction normal(const Point& p) const override {
        const Eigen::Vector3d q = transform().applyInverse(p) - base_->center;
        if (locatePoint(p) != PointLocation::OnSurface || (q.array() == 0.0).any()) return Direction();
        return transform().applyToNormal(q.array().sign().matrix());
    }

    std::unique_ptr<Shape> clone() const override { return withTransform(transform()); }
    double surfaceBand() const override { return kBandShare * base_->size; }

    int baseMeshCalls() const { return base_->meshCalls; }

protected:
    const SurfaceMesh& baseMesh() const override {
        ++base_->meshCalls;
        return base_->mesh;
    }
    const std::vector<Eigen::AlignedBox3d>& baseSurfaceCover() const override { return base_->cover; }

private:
    // A stand-in surface band: a small share of the size.
    static constexpr double kBandShare = 1e-9;

    struct Base {
        double size;
        Point center;
        SurfaceMesh mesh;
        std::vector<Eigen::AlignedBox3d> cover;
        mutable int meshCalls = 0;
        Base(double a, const Point& c) : size(a), center(c) {
            for (const Eigen::Vector3d& s : signs()) {
                std::array<Point, 3> corners{c + Point(a * s.x(), 0, 0), c + Point(0, a * s.y(), 0),
                                             c + Point(0, 0, a * s.z())};
                if (s.x() * s.y() * s.z() < 0.0) std::swap(corners[1], corners[2]);  // counter-clockwise outside
                const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
                for (const Point& corner : corners) {
                    mesh.vertices.push_back(corner);
                    mesh.normals.push_back(s.normalized());
                }
                mesh.triangles.push_back({first, first + 1, first + 2});
            }
            cover.emplace_back(c - Point::Constant(a), c + Point::Constant(a));
        }
    };

    TestOctahedron(std::shared_ptr<Base> base, const AffineTransform& transform)
        : GeneralShape(transform), base_(std::move(base)) {}

    static std::array<Eigen::Vector3d, 8> signs() {
        std::array<Eigen::Vector3d, 8> out;
        for (int k = 0; k < 8; ++k)
            out[static_cast<std::size_t>(k)] = {k & 1 ? -1.0 : 1.0, k & 2 ? -1.0 : 1.0, k & 4 ? -1.0 : 1.0};
        return out;
    }

    // The extremes of a convex polytope are at its vertices.
    Eigen::AlignedBox3d placedBounds() const {
        Eigen::AlignedBox3d box;
        for (int axis = 0; axis < 3; ++axis) {
            for (const double side : {-1.0, 1.0}) {
                box.extend(transform().apply(base_->center + side * base_->size * Point::Unit(axis)));
            }
        }
        return box;
    }

    std::shared_ptr<Base> base_;
};

}  // namespace dropscope::test
