// Overlap tests with an ellipsoid on one side (seed 000 section 1.3.6): Gilitschenski's K(lambda)
// for ellipsoid-ellipsoid and ellipsoid-sphere, Eberly's feature tests for ellipsoid-box.
#include "geometry/Box.hpp"
#include "geometry/Ellipsoid.hpp"
#include "geometry/Overlap.hpp"
#include "geometry/Sphere.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace dropscope {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The search for the maximiser of f stops once a step moves t = ln(lambda / (1 - lambda)) by less
// than this (relative to max(1, |t|)): lambda and 1 - lambda are then exact to a few ulps, and f,
// flat at its maximum, is exact to rounding.
constexpr double kLogOddsStep = 4.0 * std::numeric_limits<double>::epsilon();
// Newton needs ~5 steps (one for two spheres); bisection, the fallback, ~60 across the bracket.
constexpr int kMaxSearchSteps = 100;

Eigen::LLT<Eigen::Matrix3d> factorise(const Eigen::Matrix3d& m) {
    Eigen::LLT<Eigen::Matrix3d> cholesky(m);
    if (cholesky.info() != Eigen::Success)
        throw std::invalid_argument("gilitschenskiMaximum: shape matrices must be positive definite");
    return cholesky;
}

// tr(m^{-1}) from a Cholesky factor: the squared Frobenius norm of L^{-1}.
double inverseTrace(const Eigen::LLT<Eigen::Matrix3d>& cholesky) {
    return cholesky.matrixL().solve(Eigen::Matrix3d::Identity()).squaredNorm();
}

// f = dr . S^{-1} dr with S = shapeA/lambda + shapeB/(1-lambda) (seed 000 eq. 1.34, f = 1 - K),
// as a function of the log-odds t = ln(lambda / (1 - lambda)), i.e. 1/lambda = 1 + e^{-t} and
// 1/(1-lambda) = 1 + e^{t}: both stay at full relative precision however close the maximiser comes
// to 0 or 1 (a small ellipsoid against a large one). With x = S^{-1} dr and
// S' = dS/dt = e^{t} shapeB - e^{-t} shapeA,
//   df/dt = -x.S'x = e^{-t} a - e^{t} b,   a = x.shapeA x > 0,   b = x.shapeB x > 0.
// f is strictly concave in lambda for dr != 0, so df/dt changes sign once, and at the same t so
// does the balance
//   phi = ln a - ln b - 2t,   phi' = a'/a - b'/b - 2,   a' = -2 z.shapeA x,  b' = -2 z.shapeB x,
// with z = S^{-1} S'x. phi is far closer to linear than df/dt (exactly linear for two spheres).
//
// Bracket: in the basis that diagonalises both shape matrices (shapeA = L L^T,
// L^{-1} shapeB L^{-T} = V diag(mu) V^T), f = sum_i w_i^2 g_i with
// g_i = lambda(1-lambda)/((1-lambda) + mu_i lambda) concave and peaking at t_i = -ln(mu_i)/2, so
// the maximiser lies between the extreme t_i; and mu_max <= tr(shapeB) tr(shapeA^{-1}),
// mu_min >= 1 / (tr(shapeA) tr(shapeB^{-1})).
// Why f is not evaluated in that diagonal basis: the small mu lose all accuracy once
// cond(shapeA) cond(shapeB) nears 1/eps (two needles of semi-axis ratio ~2e4 gave max f wrong by
// 100%), while cond(S) <= max(cond(shapeA), cond(shapeB)).
class GilitschenskiFunction {
public:
    struct Sample {
        double value;         // f
        double balance;       // phi, of the sign of df/dt
        double balanceSlope;  // dphi/dt
    };

    GilitschenskiFunction(const Eigen::Vector3d& dr, const Eigen::Matrix3d& shapeA, const Eigen::Matrix3d& shapeB)
        : dr_(dr), shapeA_(shapeA), shapeB_(shapeB) {}

    // [lo, hi] around the maximiser, widened by 1 against rounding in the traces.
    std::pair<double, double> bracket() const {
        const double muMax = shapeB_.trace() * inverseTrace(factorise(shapeA_));
        const double muMin = 1.0 / (shapeA_.trace() * inverseTrace(factorise(shapeB_)));
        return {-0.5 * std::log(muMax) - 1.0, -0.5 * std::log(muMin) + 1.0};
    }

    Sample at(double t) const {
        const double eMinus = std::exp(-t);
        const double ePlus = std::exp(t);
        const Eigen::LLT<Eigen::Matrix3d> cholesky = factorise((1.0 + eMinus) * shapeA_ + (1.0 + ePlus) * shapeB_);
        const Eigen::Vector3d y = cholesky.matrixL().solve(dr_);
        const Eigen::Vector3d x = cholesky.matrixU().solve(y);
        const Eigen::Vector3d ax = shapeA_ * x;
        const Eigen::Vector3d bx = shapeB_ * x;
        const double a = x.dot(ax);
        const double b = x.dot(bx);
        const Eigen::Vector3d z = cholesky.solve(Eigen::Vector3d(ePlus * bx - eMinus * ax));
        return {y.squaredNorm(), std::log(a) - std::log(b) - 2.0 * t, -2.0 * z.dot(ax) / a + 2.0 * z.dot(bx) / b - 2.0};
    }

private:
    Eigen::Vector3d dr_;
    Eigen::Matrix3d shapeA_;
    Eigen::Matrix3d shapeB_;
};

// Root of the balance phi by Newton's method from the middle of the bracket, bisecting whenever a
// step would leave the bracket.
double maximise(const GilitschenskiFunction& f) {
    auto [lo, hi] = f.bracket();
    double t = 0.5 * (lo + hi);
    GilitschenskiFunction::Sample sample = f.at(t);
    for (int step = 0; step < kMaxSearchSteps; ++step) {
        if (sample.balance > 0.0) {
            lo = t;
        } else if (sample.balance < 0.0) {
            hi = t;
        } else {
            break;
        }
        double next = t - sample.balance / sample.balanceSlope;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - t) <= kLogOddsStep * std::max(1.0, std::abs(t))) break;
        t = next;
        sample = f.at(t);
    }
    return sample.value;
}

// Surface band of a sphere on the scale of its unit-sphere frame, like Ellipsoid::normalisedBand.
double normalisedBand(const Sphere& sphere) { return sphere.surfaceBand() / sphere.radius(); }

// Both ellipsoids scaled by s about their centres touch at s = sqrt(max f) (f scales as 1/s^2), so
// this compares that common scale with 1 minus the mean of the two normalised surface bands.
bool touchingScaleOverlaps(double maximum, double bandA, double bandB) {
    return std::sqrt(maximum) < 1.0 - 0.5 * (bandA + bandB);
}

double quadraticForm(const Eigen::Vector3d& x, const Eigen::Vector3d& center, const Eigen::Matrix3d& m) {
    const Eigen::Vector3d offset = x - center;
    return offset.dot(m * offset);
}

// Box vertex number `corner`: bit i selects the upper coordinate along axis i.
Point vertex(const Box& box, int corner) {
    Point p;
    for (int i = 0; i < 3; ++i) p[i] = ((corner >> i) & 1) != 0 ? box.upper()[i] : box.lower()[i];
    return p;
}

// Minimum of K(t) over the edge p0 + (p1 - p0) t when it lies strictly between the endpoints (they
// are vertices, tested on their own); +inf otherwise.
double edgeInteriorMinimum(const Point& p0, const Point& p1, const Eigen::Vector3d& center, const Eigen::Matrix3d& m) {
    const Eigen::Vector3d edge = p1 - p0;
    const Eigen::Vector3d mEdge = m * edge;
    const double a = edge.dot(mEdge);         // seed 000 eq. 1.37
    const double b = mEdge.dot(p0 - center);  // seed 000 eq. 1.38
    // seed 000 eq. 1.41, -1 <= B/A <= 0, i.e. t* = -B/A in [0,1] (eq. 1.40); verified, multiplied
    // through by A > 0.
    if (!(-a <= b && b <= 0.0)) return kInfinity;
    return quadraticForm(p0 + (-b / a) * edge, center, m);  // seed 000 eq. 1.42
}

// Minimum of K(u,v) over the face p0 + (p1 - p0) u + (p2 - p0) v when it lies inside [0,1]^2
// (otherwise it is on an edge or vertex of the face, tested on their own); +inf otherwise.
double faceInteriorMinimum(const Point& p0, const Point& p1, const Point& p2, const Eigen::Vector3d& center,
                           const Eigen::Matrix3d& m) {
    const Eigen::Vector3d e1 = p1 - p0;
    const Eigen::Vector3d e2 = p2 - p0;
    const Eigen::Vector3d me1 = m * e1;
    const Eigen::Vector3d me2 = m * e2;
    const Eigen::Vector3d offset = p0 - center;
    const double a = e1.dot(me1);      // seed 000 eq. 1.45
    const double b = e1.dot(me2);      // seed 000 eq. 1.46
    const double c = e2.dot(me2);      // seed 000 eq. 1.47
    const double d = me1.dot(offset);  // seed 000 eq. 1.48
    const double e = me2.dot(offset);  // seed 000 eq. 1.49
    // seed 000 eq. 1.52, verified:
    //   (u,v) = -[A B; B C]^{-1} (D,E) = (CD - BE, AE - BD) / (B^2 - AC).
    // [A B; B C] is the Gram matrix of two independent edges in the M inner product, so
    // B^2 - AC < 0 always and eq. 1.53 holds for every non-degenerate box.
    const double determinant = b * b - a * c;
    const double u = (c * d - b * e) / determinant;
    const double v = (a * e - b * d) / determinant;
    if (!(0.0 <= u && u <= 1.0 && 0.0 <= v && v <= 1.0)) return kInfinity;  // seed 000 eqs. 1.54-1.55
    return quadraticForm(p0 + u * e1 + v * e2, center, m);                  // seed 000 eq. 1.56
}

}  // namespace

double gilitschenskiMaximum(const Eigen::Vector3d& centerA, const Eigen::Matrix3d& shapeA,
                            const Eigen::Vector3d& centerB, const Eigen::Matrix3d& shapeB) {
    // Put the pair in a canonical order so that swapping the ellipsoids gives the bit-identical
    // result (equal shapes differ only in the sign of dr, which rounds symmetrically).
    const bool swap = std::lexicographical_compare(shapeB.data(), shapeB.data() + shapeB.size(), shapeA.data(),
                                                   shapeA.data() + shapeA.size());
    const Eigen::Matrix3d& first = swap ? shapeB : shapeA;
    const Eigen::Matrix3d& second = swap ? shapeA : shapeB;
    const Eigen::Vector3d dr = swap ? Eigen::Vector3d(centerA - centerB) : Eigen::Vector3d(centerB - centerA);
    if (dr.isZero(0.0)) return 0.0;                             // f vanishes identically
    return maximise(GilitschenskiFunction(dr, first, second));  // seed 000 eq. 1.34
}

bool ellipsoidsOverlap(const Ellipsoid& a, const Ellipsoid& b) {
    const double maximum = gilitschenskiMaximum(a.center(), a.inverseMatrix(), b.center(), b.inverseMatrix());
    return touchingScaleOverlaps(maximum, a.normalisedBand(), b.normalisedBand());
}

bool ellipsoidOverlapsSphere(const Ellipsoid& ellipsoid, const Sphere& sphere) {
    // A sphere is the ellipsoid with M^{-1} = R^2 I (seed 000 section 1.3).
    const Eigen::Matrix3d sphereShape = sphere.radius() * sphere.radius() * Eigen::Matrix3d::Identity();
    const double maximum =
        gilitschenskiMaximum(ellipsoid.center(), ellipsoid.inverseMatrix(), sphere.center(), sphereShape);
    return touchingScaleOverlaps(maximum, ellipsoid.normalisedBand(), normalisedBand(sphere));
}

double minimumQuadraticFormOverBox(const Eigen::Vector3d& center, const Eigen::Matrix3d& m, const Box& box) {
    // The ellipsoid centre in the box: the form's unconstrained minimum 0 is attained there. The
    // seed tests the box centroid instead, which misses a small ellipsoid inside a large box away
    // from its centroid; this is the complete test. Otherwise the minimum of the convex form lies
    // on the boundary, in the relative interior of exactly one vertex, edge or face.
    if ((center.array() >= box.lower().array()).all() && (center.array() <= box.upper().array()).all()) return 0.0;
    double minimum = kInfinity;
    for (int corner = 0; corner < 8; ++corner)  // the 8 vertices (seed 000 section 1.3.5)
        minimum = std::min(minimum, quadraticForm(vertex(box, corner), center, m));
    for (int axis = 0; axis < 3; ++axis) {
        const int along = 1 << axis;
        const int across1 = 1 << ((axis + 1) % 3);
        const int across2 = 1 << ((axis + 2) % 3);
        // The 4 edges parallel to `axis` start at the corners with that bit clear.
        for (int corner = 0; corner < 8; ++corner) {
            if ((corner & along) != 0) continue;
            minimum =
                std::min(minimum, edgeInteriorMinimum(vertex(box, corner), vertex(box, corner | along), center, m));
        }
        // The 2 faces normal to `axis`.
        for (const int side : {0, along}) {
            minimum = std::min(minimum, faceInteriorMinimum(vertex(box, side), vertex(box, side | across1),
                                                            vertex(box, side | across2), center, m));
        }
    }
    return minimum;
}

bool ellipsoidOverlapsBox(const Ellipsoid& ellipsoid, const Box& box) {
    const double minimum = minimumQuadraticFormOverBox(ellipsoid.center(), ellipsoid.matrix(), box);
    // The box band, in length units, moves sqrt(Q) by at least band / (longest semi-axis).
    return std::sqrt(minimum) < 1.0 - ellipsoid.normalisedBand() - box.surfaceBand() / ellipsoid.semiAxes().maxCoeff();
}

}  // namespace dropscope
