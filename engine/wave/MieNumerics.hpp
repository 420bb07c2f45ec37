#pragma once

#include <cstddef>

// The numerical choices of the Lorenz-Mie engine, each with the reason for its value (docs/mie.md).
namespace dropscope::mie {

// Terms of the series: N = x + 4 x^(1/3) + 2 rounded (Wiscombe 1980; Bohren & Huffman's NSTOP).
std::size_t termCount(double x);

// The downward recurrence of D_n(mx) starts at max(N, |mx|) + kStartMargin + kStartAiryWidths (|mx|/2)^(1/3)
// with D = 0. Above the turning point n ~ |mx| the wrong start mixes in the dominant solution chi_n, whose
// share shrinks going down like Ai/Bi over the Airy width (|mx|/2)^(1/3): 8 widths make it ~1e-13 at
// n = |mx|, where B&H's margin of 15 alone leaves ~0.3 of it when |mx| ~ 1e4 (docs/mie.md, "Recurrences").
inline constexpr std::size_t kStartMargin = 16;
inline constexpr double kStartAiryWidths = 8.0;

// Gauss-Legendre nodes of an angular bin of width w (radians): ceil(kNodesPerPhase x w) + kExtraNodes,
// in panels of at most kMaxPanelOrder nodes each. S11 holds angular frequencies up to 2N ~ 2x, and 2 nodes
// per radian of x w integrate it to rounding: the bins add up to Q_sca within 1e-15 (x <= 1), 4e-12
// (x = 1e3) and 1e-9 (x = 1e4), and twice the nodes change none of these (docs/mie.md, "Angular bins").
inline constexpr double kNodesPerPhase = 2.0;
inline constexpr std::size_t kExtraNodes = 12;
inline constexpr std::size_t kMaxPanelOrder = 64;

// The bins of one sphere run on OpenMP threads only above this many term evaluations (nodes x N): about
// 5 ms on one core. Below it, starting and joining threads costs more than it saves (x = 100, 180 bins:
// 0.56 ms on one thread, 8 ms on two of a loaded 2-core machine).
inline constexpr double kParallelTermEvaluations = 4e6;

// Default sampling of a size-parameter range: one size per kDefaultSpacing of x, which resolves the
// ripple's quasi-period (~0.8 in x for water), at most kMaxDefaultSizes (docs/mie.md, "Averages").
inline constexpr double kDefaultSpacing = 0.1;
inline constexpr std::size_t kMaxDefaultSizes = 1000;

// Radius distributions: as many probability midpoints as the default count over the x range between
// the kSpreadTail and 1 - kSpreadTail quantiles, at least kMinRadiusSamples unless the distribution is
// fixed (docs/mie.md, "Averages").
inline constexpr double kSpreadTail = 1e-3;
inline constexpr std::size_t kMinRadiusSamples = 32;

}  // namespace dropscope::mie
