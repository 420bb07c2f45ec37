#include "render/DrawData.hpp"

#include "geometry/Box.hpp"
#include "geometry/Ellipsoid.hpp"
#include "geometry/GeneralShape.hpp"
#include "geometry/Sphere.hpp"
#include "render/MeshCache.hpp"

namespace dropscope::render {

namespace {

std::array<float, 9> columnMajor(const Eigen::Matrix3d& m) {
    std::array<float, 9> out{};
    for (int column = 0; column < 3; ++column) {
        for (int row = 0; row < 3; ++row)
            out[static_cast<std::size_t>(3 * column + row)] = static_cast<float>(m(row, column));
    }
    return out;
}

ShapeInstance instance(const Point& center, const Eigen::Matrix3d& linear, const Anchor& anchor, const Colour& colour) {
    return {anchor.relative(center), columnMajor(linear), columnMajor(linear.inverse()), colour};
}

}  // namespace

ShapeInstance sphereInstance(const Point& center, double radius, const Anchor& anchor, const Colour& colour) {
    return instance(center, radius * Eigen::Matrix3d::Identity(), anchor, colour);
}

bool isSphereInstance(const ShapeInstance& shape) {
    const auto scaled = [](const std::array<float, 9>& m) {
        return m[0] == m[4] && m[0] == m[8] && m[1] == 0.0f && m[2] == 0.0f && m[3] == 0.0f && m[5] == 0.0f &&
               m[6] == 0.0f && m[7] == 0.0f;
    };
    return scaled(shape.linear) && scaled(shape.inverseLinear);
}

Colour shapeColour(const Shape& shape, bool selected) { return selected ? kHighlight : mediumColour(shape.mediumId()); }

ShapeInstances buildShapeInstances(const std::vector<std::unique_ptr<Shape>>& shapes, const Anchor& anchor,
                                   ShapeId selected, MeshCache* cache) {
    ShapeInstances out;
    for (ShapeId id = 0; id < shapes.size(); ++id) {
        const Shape* shape = shapes[id].get();
        if (!shape) continue;
        const Colour colour = shapeColour(*shape, id == selected);
        switch (shape->kind()) {
        case ShapeKind::Sphere: {
            const auto& sphere = static_cast<const Sphere&>(*shape);
            out.rounded.push_back(sphereInstance(sphere.center(), sphere.radius(), anchor, colour));
            out.roundedIds.push_back(id);
            break;
        }
        case ShapeKind::Ellipsoid: {
            const auto& ellipsoid = static_cast<const Ellipsoid&>(*shape);
            const Eigen::Matrix3d linear = ellipsoid.axes() * ellipsoid.semiAxes().asDiagonal();
            out.rounded.push_back(instance(ellipsoid.center(), linear, anchor, colour));
            out.roundedIds.push_back(id);
            break;
        }
        case ShapeKind::Box: {
            const auto& box = static_cast<const Box&>(*shape);
            const Eigen::Vector3d half = 0.5 * (box.upper() - box.lower());
            out.boxes.push_back(instance(box.center(), half.asDiagonal().toDenseMatrix(), anchor, colour));
            out.boxIds.push_back(id);
            break;
        }
        case ShapeKind::Parametric:
        case ShapeKind::Implicit: {
            const auto& general = static_cast<const GeneralShape&>(*shape);
            auto geometry =
                cache ? cache->geometry(general) : std::make_shared<const MeshGeometry>(meshGeometry(general));
            out.meshes.push_back({std::move(geometry), instance(general.transform().translation(),
                                                                Eigen::Matrix3d::Identity(), anchor, colour)});
            out.meshIds.push_back(id);
            break;
        }
        }
    }
    if (cache) cache->dropUnused();
    return out;
}

void LineBatch::addBox(const Eigen::AlignedBox3d& box, const Colour& colour) {
    const auto corner = [&](int i) { return box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i)); };
    // Corner i has bit 0 = x max, bit 1 = y max, bit 2 = z max; an edge joins corners one bit apart.
    for (int i = 0; i < 8; ++i) {
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (!(i & bit)) add(corner(i), corner(i | bit), colour);
        }
    }
}

}  // namespace dropscope::render
