# Sourced by the CLI test scripts run as `SCRIPT DROPSCOPE SCENE OUT`: sets program, scene and out, and fail,
# which prints its message and the run's stderr ($out.stderr) and fails the test.
set -euo pipefail
# Under the sanitizer build's LeakSanitizer suppressions, a clean exit would add its "Suppressions used" table
# to stderr; the scripts count stderr's lines.
if [[ -n "${LSAN_OPTIONS:-}" ]]; then export LSAN_OPTIONS="$LSAN_OPTIONS:print_suppressions=0"; fi
program=$1
scene=$2
out=$3

fail() {
    echo "FAIL: $*" >&2
    [[ -f "$out.stderr" ]] && sed 's/^/  stderr: /' "$out.stderr" >&2
    exit 1
}
