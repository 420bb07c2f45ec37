#!/usr/bin/env bash
# Runs the literature comparisons of docs/validation.md, the GoogleTest suite tests/validation (CTest
# label "validation"), in the Release build and prints expected against measured for each:
#   scripts/validate.sh [PHOTONS]    (photons per scene: default 1e7 as in CI, about 5 s; 1e8 is the doc's scale)
# Builds build/tests/validation_tests first. Exits non-zero when a comparison fails.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
photons="${1:-1e7}"
jobs="$(nproc 2>/dev/null || echo 2)"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DDROPSCOPE_BUILD_TESTS=ON >/dev/null
cmake --build "$build" --parallel "$jobs" --target validation_tests >/dev/null
# One process, so each scene is traced once; --gtest_brief keeps the failures and the [validation] lines.
DROPSCOPE_VALIDATION_PHOTONS="$photons" "$build/tests/validation_tests" --gtest_brief=1 && status=0 || status=$?
if ((status != 0)); then
  echo "validate: a comparison failed or could not run (above)" >&2
else
  echo "validate: every comparison holds at $photons photons per scene"
fi
exit "$status"
