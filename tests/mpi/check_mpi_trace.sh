#!/bin/bash
# `mpirun -np 3 dropscope trace` against one process (docs/scaling.md): the same files, byte for byte, for
# every tally (angular, spectral, orders, detector images and records, paths, results.h5), summary.json equal but
# for seconds, threads and ranks ("ranks": 3 against 1), one summary on stdout; and bad input refused once, exit 2.
# Usage: check_mpi_trace.sh DROPSCOPE MPIEXEC SOURCE_DIR WORK_DIR
set -euo pipefail
dropscope=$1
mpiexec=$2
source_dir=$3
work=$4
python=/usr/bin/python3
rm -rf "$work"
mkdir -p "$work"
# As root, Open MPI wants --allow-run-as-root; a 2-core machine needs --oversubscribe for 3 ranks.
launch=("$mpiexec" --allow-run-as-root --oversubscribe -np 3)

fail() {
    echo "FAIL: $*" >&2
    exit 1
}

compare_runs() {
    local name=$1 one=$2 three=$3
    local files_one files_three
    files_one=$(cd "$one" && ls)
    files_three=$(cd "$three" && ls)
    [ "$files_one" = "$files_three" ] || fail "$name: different files: [$files_one] against [$files_three]"
    for file in $files_one; do
        [ "$file" = summary.json ] && continue
        cmp -s "$one/$file" "$three/$file" || fail "$name: $file differs between 1 process and 3 ranks"
    done
    "$python" - "$one/summary.json" "$three/summary.json" "$name" <<'PY'
import json, sys
one, three = (json.load(open(path)) for path in sys.argv[1:3])
name = sys.argv[3]
assert one["ranks"] == 1, (name, one["ranks"])
assert three["ranks"] == 3, (name, three["ranks"])
assert three["threads"] == 1, (name, three["threads"])
for summary in (one, three):
    for key in ("seconds", "threads", "ranks"):
        del summary[key]
assert one == three, f"{name}: summary.json differs beyond seconds, threads and ranks"
PY
    echo "$name: $(echo "$files_one" | wc -w) files identical"
}

run_case() {
    local name=$1 scene=$2
    shift 2
    "$dropscope" trace "$scene" "$@" --threads 2 --out "$work/$name-one" > "$work/$name-one.out"
    "${launch[@]}" "$dropscope" trace "$scene" "$@" --threads 1 --out "$work/$name-three" \
        > "$work/$name-three.out" 2> "$work/$name-three.err" || fail "$name: mpirun failed: $(cat "$work/$name-three.err")"
    [ "$(grep -c '^trace: ' "$work/$name-three.out")" = 1 ] || fail "$name: not one summary: $(cat "$work/$name-three.out")"
    compare_runs "$name" "$work/$name-one" "$work/$name-three"
}

# Polarised, with diffraction, ray orders, paths of photons on two ranks, every detector type, and the screen's
# 12000 records from the photons of two ranks (about one hit a photon, 6667 photons a rank).
run_case detectors "$source_dir/tests/data/scenes/detectors_recorded.json" --photons 20000 --seed 5 --bins 90 \
    --paths 7000 --orders --diffraction fraunhofer
# Sunlight in wavelength bands, a far-field sky, unpolarised.
run_case sky "$source_dir/assets/scenes/rainbow-sky.json" --photons 20000 --seed 9 --bins 60 --wavelength-bins 5 \
    --polarisation none

[ "$(wc -l < "$work/detectors-three/detector-screen-records.csv")" = 12001 ] || fail "detectors: not 12000 records"
[ "$(tail -1 "$work/detectors-three/detector-screen-records.csv" | cut -d, -f1)" -gt 6667 ] ||
    fail "detectors: the records come from rank 0 alone"
# Fewer photons than ranks: a rank with nothing to trace.
run_case few "$source_dir/tests/data/scenes/detectors_recorded.json" --photons 2 --seed 3 --paths 2

# Bad input: said once (by rank 0), exit 2 from mpirun.
status=0
"${launch[@]}" "$dropscope" trace "$work/no-such-scene.json" --photons 10 --out "$work/bad" \
    > "$work/bad.out" 2> "$work/bad.err" || status=$?
[ "$status" = 2 ] || fail "bad scene: exit $status, not 2: $(cat "$work/bad.err")"
[ "$(grep -c 'no-such-scene.json' "$work/bad.err")" = 1 ] || fail "bad scene: not said once: $(cat "$work/bad.err")"
[ ! -e "$work/bad" ] || fail "bad scene: the output folder was created"
echo "bad input: exit 2, said once"
# A bad option too, though it is found before MPI starts.
status=0
"${launch[@]}" "$dropscope" trace "$source_dir/assets/scenes/rainbow-sky.json" --paths 99999999999 --out "$work/bad" \
    > "$work/bad-option.out" 2> "$work/bad-option.err" || status=$?
[ "$status" = 2 ] || fail "bad option: exit $status, not 2: $(cat "$work/bad-option.err")"
[ "$(grep -c 'dropscope: --paths' "$work/bad-option.err")" = 1 ] ||
    fail "bad option: not said once: $(cat "$work/bad-option.err")"
echo "bad option: exit 2, said once"

# The ranks on one node share its memory (docs/limits.md, "Memory"): a trace too big for the machine is refused
# by one process against MemAvailable and by 3 ranks against a third of it each, said once, before anything is
# traced or created. The largest tallies the options allow (1e7 spectral cells) on 1024 threads: about 590 GB.
huge=(trace "$source_dir/assets/scenes/rainbow-sky.json" --photons 10 --threads 1024 --bins 100000
      --wavelength-bins 100)
status=0
"$dropscope" "${huge[@]}" --out "$work/huge-one" > /dev/null 2> "$work/huge-one.err" || status=$?
[ "$status" = 2 ] || fail "huge trace, one process: exit $status, not 2: $(cat "$work/huge-one.err")"
status=0
"${launch[@]}" "$dropscope" "${huge[@]}" --out "$work/huge-three" > /dev/null 2> "$work/huge-three.err" || status=$?
[ "$status" = 2 ] || fail "huge trace, 3 ranks: exit $status, not 2: $(cat "$work/huge-three.err")"
[ "$(grep -c 'this machine has available for each of its 3 ranks' "$work/huge-three.err")" = 1 ] ||
    fail "huge trace, 3 ranks: not refused once for the ranks' share: $(cat "$work/huge-three.err")"
[ ! -e "$work/huge-one" ] && [ ! -e "$work/huge-three" ] || fail "huge trace: an output folder was created"
"$python" - "$work/huge-one.err" "$work/huge-three.err" <<'PY'
import re, sys
units = {"bytes": 1, "kB": 1e3, "MB": 1e6, "GB": 1e9, "TB": 1e12, "PB": 1e15}
def available(path):
    match = re.search(r"more than the ([0-9.e+]+) (\w+) this machine has available", open(path).read())
    assert match, open(path).read()
    return float(match.group(1)) * units[match.group(2)]
one, three = available(sys.argv[1]), available(sys.argv[2])
# MemAvailable moves between the runs, also as the ranks build their (empty) tallies.
assert 0.8 < three * 3 / one < 1.05, (one, three)
print(f"memory shared by 3 ranks: {one / 1e9:.3g} GB for one process, {three / 1e9:.3g} GB for each rank")
PY
