#!/usr/bin/env bash
# memory_limit.sh DROPSCOPE SCENE OUT
# Runs too big for the memory a process may use (here an address-space limit, ulimit -v, as a batch system
# sets one) are refused before they start, with their estimate: exit 2, one line, no output folder
# (docs/limits.md, "Memory"). Not run under AddressSanitizer, which needs far more address space than it uses.
source "$(dirname "${BASH_SOURCE[0]}")/cli_script_support.sh"

refused() {
    local pattern=$1
    shift
    local status=0
    (ulimit -v 1500000 && exec "$program" "$@") >"$out.stdout" 2>"$out.stderr" || status=$?
    [[ $status -eq 2 ]] || fail "$* exited $status, expected 2"
    [[ $(wc -l <"$out.stderr") -eq 1 ]] || fail "$*: not one line on stderr"
    grep -Eq "$pattern" "$out.stderr" || fail "$*: stderr does not match $pattern"
}

rm -rf "$out" "$out".*
mkdir -p "$(dirname "$out")"
# 1e6 recorded paths: about 3 GB.
refused "^dropscope: this trace needs about 3\.[0-9]+ GB \(tallies .* paths 3\.[0-9]+ GB, detector records 0 bytes\), more than the [0-9.]+ [GM]B this machine has available \(docs/limits\.md\)" \
    trace "$scene" --photons 1e6 --paths 1e6 --out "$out"
[[ ! -e "$out" ]] || fail "the refused trace created its output folder"

# A generated cloud of 1e7 droplets: about 6 GB to load.
cat >"$out.cloud.json" <<'JSON'
{"dropscope": 1, "media": {"water": {"n": 1.333}},
 "generators": [{"type": "droplet_cloud", "region": {"min": [0, 0, 0], "max": [1000, 1000, 1000]},
                 "count": 10000000, "radius": {"distribution": "fixed", "value": 0.05}, "medium": "water"}],
 "sources": [{"type": "ray", "origin": [-1, 0, 0], "direction": [1, 0, 0]}]}
JSON
refused "cloud\.json: generators\[0\]\.count: 10000000 droplets need about 6 GB to load .*more than the [0-9.]+ [GM]B this machine has available" \
    inspect "$out.cloud.json"

echo "ok: runs beyond a 1.5 GB address-space limit are refused up front with their estimate"
