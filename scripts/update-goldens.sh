#!/usr/bin/env bash
# Regenerates every golden image listed in tests/golden/cases.txt with the built dropscope, and removes
# golden images no case names any more (docs/golden-images.md). Look at every image before committing.
#
#   scripts/update-goldens.sh [BUILD_DIR]    BUILD_DIR defaults to build/; it is configured (Release) if
#                                            new, and its dropscope target rebuilt first.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="$(realpath -m "${1:-$root/build}")"
cases="$root/tests/golden/cases.txt"
scenes="$root/tests/data/scenes/golden"
goldens="$root/tests/golden"
jobs="$(nproc 2>/dev/null || echo 2)"

if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
  cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build_dir" --target dropscope --parallel "$jobs"
program="$build_dir/app/dropscope"

declare -A listed=()
while read -r name scene arguments || [[ -n "$name" ]]; do
  [[ -z "$name" || "$name" == \#* ]] && continue
  read -r -a extra <<<"$arguments"
  "$program" snapshot "$scenes/$scene" --out "$goldens/$name.png" "${extra[@]}"
  listed["$name"]=1
done <"$cases"

for image in "$goldens"/*.png; do
  [[ -e "$image" ]] || continue
  name="$(basename "$image" .png)"
  if [[ -z "${listed[$name]:-}" ]]; then
    rm -- "$image"
    echo "removed $image: no case of $cases names it"
  fi
done
echo "${#listed[@]} golden images in $goldens; look at each one (docs/golden-images.md) before committing"
