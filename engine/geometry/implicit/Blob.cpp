#include "geometry/implicit/Blob.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace dropscope {

Blob::Blob(std::vector<Point> centers, std::vector<double> radii, double blend)
    : centers_(std::move(centers)), radii_(std::move(radii)), blend_(blend) {
    if (centers_.size() < 2) throw std::invalid_argument("blob needs at least 2 centers");
    if (radii_.size() != centers_.size()) throw std::invalid_argument("radii must have one entry per center");
    for (const Point& c : centers_) {
        if (!c.allFinite()) throw std::invalid_argument("centers must be finite");
    }
    for (double r : radii_) {
        if (!std::isfinite(r) || r <= 0.0) throw std::invalid_argument("radii must be finite and > 0");
    }
    if (!std::isfinite(blend_) || blend_ <= 0.0) throw std::invalid_argument("blend must be finite and > 0");
}

double Blob::value(const Point& r) const {
    // -k ln sum exp(-d_i/k) = dMin - k ln sum exp(-(d_i - dMin)/k): every exponent <= 0, the largest
    // term is exactly 1, so nothing overflows and the sum is in [1, n].
    double dMin = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < centers_.size(); ++i) dMin = std::min(dMin, (r - centers_[i]).norm() - radii_[i]);
    double sum = 0.0;
    for (std::size_t i = 0; i < centers_.size(); ++i)
        sum += std::exp(-((r - centers_[i]).norm() - radii_[i] - dMin) / blend_);
    return dMin - blend_ * std::log(sum);
}

Eigen::Vector3d Blob::gradient(const Point& r) const {
    double dMin = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < centers_.size(); ++i) dMin = std::min(dMin, (r - centers_[i]).norm() - radii_[i]);
    Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
    double sum = 0.0;
    for (std::size_t i = 0; i < centers_.size(); ++i) {
        const Eigen::Vector3d offset = r - centers_[i];
        const double distance = offset.norm();
        const double weight = std::exp(-(distance - radii_[i] - dMin) / blend_);
        sum += weight;
        if (distance > 0.0) weighted += weight * offset / distance;  // at a centre: the zero subgradient
    }
    return weighted / sum;
}

Eigen::AlignedBox3d Blob::bounds() const {
    // f >= min d - k ln n: f <= 0 needs d_i <= k ln n for some i.
    const double growth = blend_ * std::log(static_cast<double>(centers_.size()));
    Eigen::AlignedBox3d box;
    for (std::size_t i = 0; i < centers_.size(); ++i) {
        const Eigen::Vector3d half = Eigen::Vector3d::Constant(radii_[i] + growth);
        box.extend(centers_[i] - half);
        box.extend(centers_[i] + half);
    }
    return box;
}

double Blob::characteristicLength() const { return *std::min_element(radii_.begin(), radii_.end()); }

std::vector<PresetParameter> Blob::presetParameters() const {
    PresetParameter centers{"centers", {centers_.size(), 3}, {}};
    for (const Point& c : centers_) centers.values.insert(centers.values.end(), {c.x(), c.y(), c.z()});
    return {std::move(centers), {"radii", {radii_.size()}, radii_}, {"blend", {}, {blend_}}};
}

}  // namespace dropscope
