#!/usr/bin/env bash
# Second of the README's two commands: the same set-up, then every test through CTest, twice:
# a Release build (build/) and an AddressSanitizer + UndefinedBehaviorSanitizer build (build-asan/). The second is
# compiled by clang, so that it also builds and runs the libFuzzer targets of tests/fuzz (docs/fuzzing.md).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
jobs="$(nproc 2>/dev/null || echo 2)"

scripts/install-deps.sh

echo "== Release build and tests (build/)"
scripts/build.sh build -DCMAKE_BUILD_TYPE=Release -DDROPSCOPE_BUILD_TESTS=ON -DDROPSCOPE_BUILD_BENCH=ON
ctest --test-dir build --output-on-failure --parallel "$jobs"

echo "== Sanitizer build and tests (build-asan/: ASan + UBSan, clang, with the fuzzers)"
scripts/build.sh build-asan -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-g1 -O1" \
  -DDROPSCOPE_SANITIZE=ON -DDROPSCOPE_FUZZ=ON -DDROPSCOPE_BUILD_TESTS=ON -DDROPSCOPE_BUILD_BENCH=OFF
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  LSAN_OPTIONS=suppressions="$root/scripts/lsan.supp" \
  ctest --test-dir build-asan --output-on-failure --parallel "$jobs"
