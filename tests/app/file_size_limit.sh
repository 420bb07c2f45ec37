#!/usr/bin/env bash
# file_size_limit.sh DROPSCOPE SCENE OUT
# A disk that fills while a run writes, made with a file-size limit (ulimit -f, RLIMIT_FSIZE): every output of
# the run is whole or absent. trace (with paths.jsonl larger than the limit) and snapshot each exit 2
# with one line naming the file and the reason, leave no temporary file and no output; the folder trace
# created is gone again. An earlier run's files in a folder are left as they were.
source "$(dirname "${BASH_SOURCE[0]}")/cli_script_support.sh"

# Runs "$@" with files limited to 64 KiB (ulimit -f counts 1024-byte blocks) and checks a clean refusal.
limited() {
    local status=0
    (ulimit -f 64 && exec "$program" "$@") >"$out.stdout" 2>"$out.stderr" || status=$?
    [[ $status -eq 2 ]] || fail "$* exited $status, expected 2"
    [[ $(wc -l <"$out.stderr") -eq 1 ]] || fail "$*: not one line on stderr"
    grep -q "write failed (File too large); no file of this run written" "$out.stderr" ||
        fail "$*: stderr does not give the reason"
}

rm -rf "$out" "$out".*
mkdir -p "$out.parent"

# trace: paths.jsonl of 2000 photons is several hundred KiB.
limited trace "$scene" --photons 4000 --paths 2000 --out "$out/trace"
[[ ! -e "$out/trace" ]] || fail "trace left $(ls -A "$out/trace" | tr '\n' ' ')in its folder"

# The same into a folder holding an earlier, smaller run: its files stay as they were.
"$program" trace "$scene" --photons 1000 --out "$out/kept" >/dev/null
before=$(cd "$out/kept" && sha256sum ./*)
limited trace "$scene" --photons 4000 --paths 2000 --out "$out/kept"
after=$(cd "$out/kept" && sha256sum ./*)
[[ "$before" == "$after" ]] || fail "the earlier run's files changed"
[[ -z $(find "$out/kept" -name '*.partial-*') ]] || fail "temporary files left behind"

# snapshot: a 1024 x 1024 PNG is far above 64 KiB.
limited snapshot "$scene" --width 1024 --height 1024 --out "$out/shot.png"
[[ ! -e "$out/shot.png" ]] || fail "snapshot left a partial PNG"
[[ -z $(find "$(dirname "$out")" -maxdepth 1 -name "$(basename "$out")*.partial-*") ]] || fail "snapshot left a temporary file"

echo "ok: trace and snapshot outputs are whole or absent under a 64 KiB file-size limit"
