#!/usr/bin/env bash
# Configure and build one CMake tree: scripts/build.sh BUILD_DIR [extra cmake args...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="$1"
shift
jobs="$(nproc 2>/dev/null || echo 2)"
cmake -S "$root" -B "$build_dir" "$@" >/dev/null
cmake --build "$build_dir" --parallel "$jobs"
