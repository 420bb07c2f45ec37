#pragma once

#include <string_view>

namespace dropscope::fuzz {

// Some scenes are slow by design, not by a bug, and would stall the fuzzer and trip its per-input timeout; the
// scene target skips them (docs/fuzzing.md). Their limits, if any, belong to the loader, not to the fuzzer.
//
// Droplet clouds ("generators") turn a few bytes into up to kMaxGeneratedDroplets (ten million) droplets, seconds
// of work and hundreds of megabytes under the sanitizers: a text whose clouds would, by a rough estimate, make more
// than kMaxFuzzedDroplets in all is skipped.
inline constexpr double kMaxFuzzedDroplets = 20'000;  // assets/scenes/cloud.json's 20000 still runs
// Each implicit shape is meshed and integrated on a fixed grid when it is read, at a cost proportional to its
// function's terms (a blob's centers, one for a superellipsoid): under the sanitizers about 0.8 s per term, and
// the loader sets no limit on them. A text with more than kMaxFuzzedImplicitTerms in all is skipped.
inline constexpr double kMaxFuzzedImplicitTerms = 6;  // tests/data/scenes/general_shapes.json has 3

// A text naming a file under /dev/ or /proc/ is skipped too: a device is read up to the loader's 1 GiB limit.
//
// False when `sceneText` is JSON that by those estimates is slow by design. What it cannot estimate (a missing or
// non-numeric field) passes: the loader refuses it before the slow part.
bool withinInputBudget(std::string_view sceneText);

}  // namespace dropscope::fuzz
