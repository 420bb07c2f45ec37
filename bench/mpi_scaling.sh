#!/bin/bash
# MPI scaling of `dropscope trace` (docs/scaling.md): the same run as 1 process of 1 thread, 2 MPI ranks of 1
# thread, and 1 process of 2 threads, interleaved, REPEAT times each; prints a Markdown table of the medians.
# "trace s" is summary.json's seconds (the photons, from the first to the merged result at rank 0); "wall s"
# the whole command (start-up, scene and octree on every rank, writing). Every run's files are compared with
# the first run's (cmp, summary.json without seconds, threads and ranks): a difference fails the script.
# Usage: bench/mpi_scaling.sh [DROPSCOPE] [SCENE] [PHOTONS] [REPEAT]
set -euo pipefail
dropscope=${1:-build/app/dropscope}
scene=${2:-assets/scenes/cloud.json}
photons=${3:-4e5}
repeat=${4:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mpirun=(mpirun --allow-run-as-root --oversubscribe)

calc() { /usr/bin/python3 -c "print($1)"; }
declare -A trace wall
configs=("1x1" "2x1" "1x2")
run() {
    local config=$1 index=$2 out="$work/$1-$2"
    local start end
    start=$(date +%s.%N)
    case $config in
        1x1) "$dropscope" trace "$scene" --photons "$photons" --threads 1 --out "$out" > /dev/null ;;
        2x1) "${mpirun[@]}" -np 2 "$dropscope" trace "$scene" --photons "$photons" --threads 1 --out "$out" > /dev/null ;;
        1x2) "$dropscope" trace "$scene" --photons "$photons" --threads 2 --out "$out" > /dev/null ;;
    esac
    end=$(date +%s.%N)
    trace[$config]+="$(/usr/bin/python3 -c "import json; print(round(json.load(open('$out/summary.json'))['seconds'], 3))") "
    wall[$config]+="$(calc "$end - $start") "
    local reference="$work/1x1-0"
    for file in $(cd "$reference" && ls); do
        [ "$file" = summary.json ] && continue
        cmp -s "$reference/$file" "$out/$file" || { echo "FAIL: $config run $index: $file differs" >&2; exit 1; }
    done
    /usr/bin/python3 - "$reference/summary.json" "$out/summary.json" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
for s in (a, b):
    for k in ("seconds", "threads", "ranks"):
        s.pop(k)
sys.exit(0 if a == b else "summary.json differs")
PY
}
for ((i = 0; i < repeat; ++i)); do
    for config in "${configs[@]}"; do run "$config" "$i"; done
done

median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
echo "scene $scene, $photons photons, $repeat runs each, load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| processes x threads | trace s (each run) | trace s (median) | photons/s | speedup | wall s (median) | wall speedup |"
echo "|---|---|---|---|---|---|---|"
base=$(echo "${trace[1x1]}" | median)
base_wall=$(echo "${wall[1x1]}" | median)
for config in "${configs[@]}"; do
    t=$(echo "${trace[$config]}" | median)
    w=$(echo "${wall[$config]}" | median)
    rate=$(calc "round(float('$photons') / $t)")
    printf '| %s | %s | %.3f | %s | %.2f | %.3f | %.2f |\n' "${config/x/ x }" "${trace[$config]% }" "$t" "$rate" \
        "$(calc "$base / $t")" "$w" "$(calc "$base_wall / $w")"
done
echo
echo "every run's files identical to the first (1 x 1) run's: yes"
