#include "geometry/RayQuadric.hpp"

#include <cmath>
#include <limits>

namespace dropscope {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

double quadricDistance(const RayQuadratic& q, PointLocation start, double chordBand) {
    const double root = std::sqrt(std::max(q.discriminant, 0.0));
    switch (start) {
    case PointLocation::Inside:
        // c < 0: one root of each sign; take the positive one without cancellation.
        return q.b <= 0.0 ? (-q.b + root) / q.a : -q.c / (q.b + root);
    case PointLocation::OnSurface: {
        if (q.b >= 0.0) return 0.0;  // leaving or tangent
        const double farSide = (-q.b + root) / q.a;
        return farSide > chordBand ? farSide : 0.0;
    }
    case PointLocation::Outside:
        if (q.b >= 0.0 || q.discriminant <= 0.0) return kNaN;  // moving away, or missing
        if (2.0 * root / q.a <= chordBand) return kNaN;        // grazing touch: never enters
        return q.c / (-q.b + root);                              // nearer root, cancellation-free
    }
    return kNaN;
}

}  // namespace dropscope
