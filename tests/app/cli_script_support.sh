# Sourced by the CLI test scripts run as `SCRIPT DROPSCOPE SCENE OUT`: sets program, scene and out, and fail,
# which prints its message and the run's stderr ($out.stderr) and fails the test.
set -euo pipefail
program=$1
scene=$2
out=$3

fail() {
    echo "FAIL: $*" >&2
    [[ -f "$out.stderr" ]] && sed 's/^/  stderr: /' "$out.stderr" >&2
    exit 1
}
