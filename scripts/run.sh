#!/usr/bin/env bash
# First of the README's two commands: install what is missing, build Release into build/, and run the
# main job on the bundled default scene.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

scripts/install-deps.sh
scripts/build.sh build -DCMAKE_BUILD_TYPE=Release -DDROPSCOPE_BUILD_TESTS=OFF -DDROPSCOPE_BUILD_BENCH=OFF
build/app/dropscope inspect assets/scenes/default.json
# Extra arguments go to trace (e.g. --threads 1 --seed 7); PHOTONS=1e7 scripts/run.sh traces more.
build/app/dropscope trace assets/scenes/default.json --photons "${PHOTONS:-1e6}" --paths 10 --out build/trace-default "$@"
