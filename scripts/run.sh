#!/usr/bin/env bash
# First of the README's two commands: install what is missing, build Release into build/, and open the
# app on the bundled default scene. Without a display it says so in one line and runs the headless jobs
# instead: a snapshot of the default scene and a Monte Carlo trace of it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

scripts/install-deps.sh
scripts/build.sh build -DCMAKE_BUILD_TYPE=Release -DDROPSCOPE_BUILD_TESTS=OFF -DDROPSCOPE_BUILD_BENCH=OFF
scene=assets/scenes/default.json
if [[ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]]; then
  exec build/app/dropscope "$scene"
fi
echo "run.sh: no display (DISPLAY is not set), so no window; headless instead: dropscope snapshot $scene --out build/default.png (and a trace)"
build/app/dropscope snapshot "$scene" --out build/default.png --paths 20 --photons 20
# Extra arguments go to trace (e.g. --threads 1 --seed 7); PHOTONS=1e7 scripts/run.sh traces more.
build/app/dropscope trace "$scene" --photons "${PHOTONS:-1e6}" --paths 10 --out build/trace-default "$@"
