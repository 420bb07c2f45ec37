#pragma once

#include "geometry/AffineTransform.hpp"
#include "geometry/Shape.hpp"
#include "geometry/SurfaceMesh.hpp"

#include <Eigen/Geometry>

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace dropscope {

// One named list of numbers a preset was built from, as nested arrays in a scene file: `values`
// holds the product of `extents` numbers in row-major order ({} extents: a single number;
// {3}: a vector; {n, 3}: n points; {n, 16, 3}: n bicubic control nets).
struct PresetParameter {
    std::string key;
    std::vector<std::size_t> extents;
    std::vector<double> values;

    bool operator==(const PresetParameter&) const = default;
};

// A shape given by a base surface shared between shapes (std::shared_ptr, seed 000 1.4 and
// Appendix A) and an affine transformation M r + r0 placing it: the parametric and implicit shapes.
// Whatever is known of the base (mesh, surface cover, area, volume) is computed once, in the base.
class GeneralShape : public Shape {
public:
    const AffineTransform& transform() const { return transform_; }

    // The scene file's "preset" and its parameters (the base's, before the transform).
    virtual std::string_view presetName() const = 0;
    virtual std::vector<PresetParameter> presetParameters() const = 0;

    // The same base under another transformation (the base is shared, not copied); medium kept.
    virtual std::unique_ptr<GeneralShape> withTransform(const AffineTransform& transform) const = 0;

    // "parametric torus {major_radius: 2, minor_radius: 0.5} M=[[1, 0, 0], ...] r0=(1, 2, 3)"; a parameter
    // of more than kPrintedValues numbers (Bezier patches) is summarised as "[N numbers]".
    void print(std::ostream& os) const final;
    // Conservative: some cover cell meets the box, or the box, holding no surface, is inside.
    bool mayMeetBox(const Eigen::AlignedBox3d& box) const final;
    // The same kind, preset, parameters and matrix M; r0 may differ.
    bool sameFormAs(const Shape& other) const final;

    // The base's tessellation, placed by the transform.
    SurfaceMesh mesh() const;
    // Axis-aligned boxes that together contain the whole surface (conservative overlap tests).
    std::vector<Eigen::AlignedBox3d> surfaceCover() const;
    // Whether `test` holds for some box of the surface cover, each placed as it is tested: the overlap
    // tests' inner loop, which must not build the whole placed cover once per call.
    template <class Test>
    bool anyCoverBox(Test&& test) const {
        for (const Eigen::AlignedBox3d& box : baseSurfaceCover()) {
            if (test(transform_.applyToBox(box))) return true;
        }
        return false;
    }
    // A point on the surface (a vertex of the mesh).
    Point surfacePoint() const;

    // Throws std::invalid_argument when the placed shape is unusable: bounds, volume or area not finite
    // or not positive (a transform or parameters at the edge of the double range), or a surface the
    // tessellation does not resolve (no mesh: a blob's droplet far smaller than the blob).
    void checkUsable() const;

protected:
    explicit GeneralShape(const AffineTransform& transform) : transform_(transform) {}
    GeneralShape(const GeneralShape&) = default;
    GeneralShape& operator=(const GeneralShape&) = default;

    // In the base's own frame, computed once per base.
    virtual const SurfaceMesh& baseMesh() const = 0;
    virtual const std::vector<Eigen::AlignedBox3d>& baseSurfaceCover() const = 0;

private:
    AffineTransform transform_;
};

// The shape as a GeneralShape when it is parametric or implicit, else null.
inline const GeneralShape* asGeneralShape(const Shape& shape) {
    const bool general = shape.kind() == ShapeKind::Parametric || shape.kind() == ShapeKind::Implicit;
    return general ? static_cast<const GeneralShape*>(&shape) : nullptr;
}

// "sphere", "box", ..., or for a general shape its type and preset: "parametric torus".
std::string shapeTypeLabel(const Shape& shape);

}  // namespace dropscope
