#pragma once

#include <cstddef>
#include <vector>

namespace dropscope {

// The Gauss-Legendre rule of `order` nodes on [-1, 1]: nodes ascending, weights summing to 2. Newton's
// method on the Legendre recurrence; nodes and weights good to a few ulp for the orders the Mie bins use
// (up to 64).
struct GaussLegendreRule {
    std::vector<double> nodes;
    std::vector<double> weights;
};
GaussLegendreRule gaussLegendre(std::size_t order);

}  // namespace dropscope
