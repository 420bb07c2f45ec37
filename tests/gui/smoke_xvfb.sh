#!/usr/bin/env bash
# smoke_xvfb.sh DROPSCOPE SCENE WORKDIR
# The real window under Xvfb, driven as a user would with xdotool: start on a top-down scene, drop a
# droplet with a click in placement mode (P), fire with Space, save a screenshot with F12, quit with
# Ctrl+Q. Passes when the app exits 0 and the screenshot exists and shows a droplet where the click was.
# Exit 77 (CTest: skipped) when Xvfb or xdotool is not installed.
set -euo pipefail
program=$(realpath "$1")
scene=$(realpath "$2")
work=$3

for tool in xvfb-run xdotool convert; do
    command -v "$tool" >/dev/null || { echo "SKIP: $tool is not installed"; exit 77; }
done
rm -rf "$work"
mkdir -p "$work/home"
cd "$work"

# Inside the X server: the app in the background, xdotool against its window.
cat >drive.sh <<'DRIVE'
set -euo pipefail
program=$1
scene=$2
HOME=$PWD/home "$program" "$scene" >app.stdout 2>app.stderr &
pid=$!
window=""
for _ in $(seq 150); do
    window=$(xdotool search --name '^dropscope' 2>/dev/null | head -n 1 || true)
    [[ -n "$window" ]] && break
    sleep 0.1
done
[[ -n "$window" ]] || { echo "FAIL: no dropscope window after 15 s"; kill "$pid"; exit 1; }
sleep 3     # a few frames: shaders compiled, panels laid out (slower when CTest runs other tests too)
import -window root before.png
# Left alone, the app sleeps between events (FramePacing): an idle second costs it well under 0.3 s of
# processor time (drawing without pause, it used 1.6 s a second here). Start-up may still be drawing its
# first frames on a loaded machine, so any one of 15 seconds in a row will do.
ticks() { awk '{print $14 + $15}' "/proc/$pid/stat"; }
limit=$((3 * $(getconf CLK_TCK) / 10))
slept=""
for second in $(seq 15); do
    idleStart=$(ticks)
    sleep 1
    idleTicks=$(($(ticks) - idleStart))
    if ((idleTicks <= limit)); then slept=$second; break; fi
done
if [[ -z "$slept" ]]; then
    echo "FAIL: idle, the app used more than $limit clock ticks of processor time in each of 15 seconds (last: $idleTicks)"
    kill "$pid"
    exit 1
fi
xdotool mousemove --window "$window" 740 480
sleep 0.5
xdotool key p
sleep 0.6
xdotool click 1
sleep 1
xdotool key space
sleep 2
xdotool key F12
sleep 1.5
xdotool mousemove --window "$window" 640 60
sleep 0.3
import -window root after.png
xdotool key ctrl+q
for _ in $(seq 100); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
done
if kill -0 "$pid" 2>/dev/null; then echo "FAIL: still running 10 s after Ctrl+Q"; kill "$pid"; exit 1; fi
wait "$pid"
DRIVE

fail() {
    echo "FAIL: $*" >&2
    for log in app.stdout app.stderr; do [[ -s "$log" ]] && sed "s/^/  $log: /" "$log" >&2; done
    echo "  the screen before and after: $PWD/before.png, $PWD/after.png" >&2
    exit 1
}

xvfb-run -a -s "-screen 0 1280x800x24" bash drive.sh "$program" "$scene" || fail "the session above"
shots=(dropscope-*.png)
[[ -f "${shots[0]}" ]] || fail "F12 wrote no dropscope-*.png in the working directory"
size=$(identify -format '%wx%h' "${shots[0]}")
[[ "$size" == 1280x800 ]] || fail "screenshot is $size, not 1280x800"
# The background is (20, 23, 28); a lit water droplet is far from it.
pixel=$(convert "${shots[0]}" -format '%[fx:int(255*p{740,480}.r)],%[fx:int(255*p{740,480}.g)],%[fx:int(255*p{740,480}.b)]' info:)
IFS=, read -r r g b <<<"$pixel"
distance() { echo $(( $1 > $2 ? $1 - $2 : $2 - $1 )); }
difference=$(( $(distance "$r" 20) + $(distance "$g" 23) + $(distance "$b" 28) ))
((difference > 60)) || fail "no droplet at the click in the screenshot: pixel ($pixel)"
echo "PASS: screenshot ${shots[0]} ($size) shows the droplet at (740, 480): pixel ($pixel)"
