#!/usr/bin/env bash
# `cmake --install` of a build into a fresh prefix, then used from there alone, as a user would:
#   - the Python package: imported from the prefix (not the build tree), a trace of an absorbing sphere whose
#     counts equal `dropscope trace`'s;
#   - the C++ package: a tiny project (tests/install/consumer) configured with find_package(dropscope) against the
#     prefix, built, and run on the same scene: the same counts again.
# check_install.sh BUILD_DIR WORK_DIR PYTHON SOURCE_DIR
set -euo pipefail
build="$1"
work="$2"
python="$3"
source="$4"
# Photons end in every fate there: escaped (some unscattered) and absorbed.
scene="$source/assets/scenes/validation/opaque-sphere.json"
rm -rf "$work"
mkdir -p "$work"
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log"

"$build/app/dropscope" trace "$scene" --photons 2000 --seed 5 --out "$work/cli" >/dev/null
expected=$("$python" -c 'import json, sys
s = json.load(open(sys.argv[1]))
c = s["counts"]
print(s["photons"], c["escaped"], c["absorbed"], c["lost"], c["unscattered"])' "$work/cli/summary.json")
echo "dropscope trace: $expected"

site=$(echo "$prefix"/lib/python3*/dist-packages)
[[ -f "$site/dropscope/__init__.py" ]] || { echo "no Python package under $prefix/lib/python3*/dist-packages"; exit 1; }
cd "$work"
got=$(env -u PYTHONPATH PYTHONPATH="$site" PYTHONDONTWRITEBYTECODE=1 "$python" -c 'import sys, pathlib, dropscope
assert pathlib.Path(dropscope.__file__).resolve().is_relative_to(pathlib.Path(sys.argv[1]).resolve()), dropscope.__file__
s = dropscope.trace(dropscope.load_scene(sys.argv[2]), 2000, seed=5).summary
c = s["counts"]
print(s["photons"], c["escaped"], c["absorbed"], c["lost"], c["unscattered"])' "$prefix" "$scene")
echo "installed Python package: $got"
[[ "$got" == "$expected" ]] || { echo "the installed Python package counts differently"; exit 1; }

cmake -S "$source/tests/install/consumer" -B "$work/consumer" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" >"$work/consumer-configure.log" || { cat "$work/consumer-configure.log"; exit 1; }
cmake --build "$work/consumer" >"$work/consumer-build.log" 2>&1 || { cat "$work/consumer-build.log"; exit 1; }
got=$("$work/consumer/consumer" "$scene" 2000 5)
echo "installed C++ package (find_package(dropscope)): $got"
[[ "$got" == "$expected" ]] || { echo "the installed C++ package counts differently"; exit 1; }
if grep -rq "$source" "$prefix/lib/cmake/dropscope"; then
  echo "the installed CMake package names the source tree"
  exit 1
fi
echo "install: Python package and C++ package both work from $prefix"
