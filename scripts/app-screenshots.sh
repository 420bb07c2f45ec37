#!/usr/bin/env bash
# Takes the screenshots of docs/images/app-*.png: the real app in a window under Xvfb, driven with
# xdotool as a user would, captured with ImageMagick's `import`. Usage: scripts/app-screenshots.sh
# [BUILD_DIR] (default build/); ONLY=app-ray-tree takes just that one. Look at every image before
# committing it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
program="$(realpath "${1:-$root/build}")/app/dropscope"
out="$root/docs/images"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$out" "$work/home"

# shot NAME SCENE ACTIONS...: start the app on SCENE, run the xdotool ACTIONS (each a quoted string of
# xdotool arguments, or "sleep S"), capture the screen into docs/images/NAME.png, quit.
shot() {
    local name=$1 scene=$2
    shift 2
    [[ -n "${ONLY:-}" && "$ONLY" != "$name" ]] && return 0
    cat >"$work/drive.sh" <<DRIVE
set -euo pipefail
cd "$work"
HOME="$work/home" "$program" "$scene" >"$work/$name.log" 2>&1 &
pid=\$!
sleep 2.5
$(for action in "$@"; do
    if [[ $action == sleep* ]]; then echo "$action"; else echo "xdotool $action; sleep 0.4"; fi
done)
sleep 0.6
import -window root "$out/$name.png"
xdotool key ctrl+q
for _ in \$(seq 100); do kill -0 \$pid 2>/dev/null || break; sleep 0.1; done
if kill -0 \$pid 2>/dev/null; then echo "$name: no exit 10 s after Ctrl+Q" >&2; kill -9 \$pid; exit 1; fi
wait \$pid
DRIVE
    rm -rf "$work/home/.config"
    if ! xvfb-run -a -s "-screen 0 1280x800x24" bash "$work/drive.sh"; then
        echo "FAILED: $name" >&2
        sed 's/^/  /' "$work/$name.log" >&2 || true
        return 1
    fi
    echo "docs/images/$name.png"
    sleep 1  # the next xvfb-run -a picks a free display only once this one's lock is gone
}

default="$root/assets/scenes/default.json"
cloud="$root/assets/scenes/cloud.json"
topdown="$root/tests/data/scenes/gui_top_down.json"
gallery="$root/assets/scenes/shapes_gallery.json"
# The default scene with its beam linearly polarised at 30 degrees from x (towards x cross z = -y).
polarised="$work/default-linear.json"
sed 's|"radius": 1.5}|"radius": 1.5, "polarisation": {"linear_deg": 30, "reference": [1, 0, 0]}}|' "$default" >"$polarised"
grep -q linear_deg "$polarised" || { echo "the polarised scene was not made from $default" >&2; exit 1; }

shot app-overview "$default" "mousemove 640 450" "key space" "sleep 2"
shot app-select-edit "$default" "mousemove 560 430" "click 1" "mousemove 570 440"
shot app-placement "$topdown" "key p" "mousemove 740 480" "click 1" "mousemove 770 470"
shot app-octree "$cloud" "mousemove 640 60" "key c" "key bracketright" "key bracketright" "sleep 1"
shot app-slice "$cloud" "mousemove 640 60" "key l" "key c" "key bracketright" "sleep 1"
shot app-path-inspector "$default" "mousemove 640 60" "key space" "sleep 2" "key Right" "key Right" "key Right"
# The beam's central ray meets drop-a head on, where every branch stays on the axis: aim it (A) at a
# point off the droplet's centre first, then fire the tree (R) and zoom in.
shot app-ray-tree "$default" "mousemove 612 396" "key a" "key r" "mousemove 560 420" "click --repeat 4 --delay 100 4" \
    "mousemove 640 60" "sleep 1"
shot app-help "$default" "mousemove 640 60" "key F1"
# Detectors (docs/gui.md, "Detectors"): 20,000 photons (typed into the Fire panel), then the plane "screen"
# selected in the Detectors panel (its image, its move and aim handles), the paths switched off (the Paths
# panel) so that the far-field camera's frustum shows.
detectors="$root/tests/data/scenes/detectors.json"
shot app-detectors-edit "$detectors" "mousemove 1040 310" "click 1" "key ctrl+a" "type 20000" "key Return" \
    "mousemove 640 60" "key space" "sleep 3" "mousemove 110 324" "click 1" "mousemove 967 501" "click 1" "mousemove 640 60" "sleep 0.5"
# 100,000 photons (typed into the Fire panel's photon count), then the Results panel's Plot... button, the
# mouse over the primary rainbow's edge near 138 degrees.
shot app-results-plot "$default" "mousemove 1040 215" "click 1" "key ctrl+a" "type 100000" "key Return" \
    "mousemove 640 60" "key space" "sleep 3" "mousemove 35 702" "click 1" "mousemove 791 330" "sleep 0.5"
# The parametric and implicit presets, photons fired, the Bezier droplet in the middle selected.
shot app-general-shapes "$gallery" "mousemove 640 420" "key space" "sleep 2" "click 1"
# Polarisation: the Fire panel with the linearly polarised beam, 1000 photons fired.
shot app-polarisation-fire "$polarised" "mousemove 640 60" "key space" "sleep 2"
# The default (unpolarised) beam, seed 4 (typed into the Fire panel), translucent shapes (View menu), paths
# coloured by DoLP; photon 2, a primary-rainbow ray in drop-a, at its internal reflection (event 2). The
# view orbited until the glass cell is behind drop-a and zoomed in on the event: the ellipse (white) in its
# circle (grey); the event table scrolled sideways (Shift+wheel) to its Stokes columns.
shot app-polarisation-paths "$default" "mousemove 1040 261" "click 1" "key ctrl+a" "type 4" "key Return" \
    "mousemove 640 60" "key space" "sleep 2" "mousemove 113 9" "click 1" "mousemove 150 186" "click 1" \
    "mousemove 1130 500" "click 1" "mousemove 1130 562" "click 1" "mousemove 1060 580" "click 1" \
    "mousemove 640 60" "key Right" "key Right" "mousemove 700 650" "mousedown 1" "mousemove 600 640" \
    "mousemove 500 630" "mousemove 420 620" "mouseup 1" "mousemove 675 390" "click --repeat 5 --delay 100 4" \
    "mousemove 1100 700" "keydown shift" "click --repeat 40 5" "keyup shift" "mousemove 1100 430"
# The same 100,000 photons, the mouse on the polarisation sub-plot at the primary rainbow (138 degrees):
# -P12/P11 and DoLP read out there.
shot app-polarisation-results "$default" "mousemove 1040 215" "click 1" "key ctrl+a" "type 100000" "key Return" \
    "mousemove 640 60" "key space" "sleep 3" "mousemove 35 702" "click 1" "mousemove 791 500" "sleep 0.5"
# Wavelengths (docs/gui.md, "Wavelengths"): a water droplet with water's own n and kappa under a beam of
# sunlight 0.266 degrees wide. The Fire panel with its sun spectrum and divergence, 1000 photons fired.
rainbow="$root/assets/scenes/sunlit-rainbow.json"
shot app-spectra-fire "$rainbow" "mousemove 640 60" "key space" "sleep 2"
# The Media panel's Dispersion window on the droplet's water (its dispersion button), n plotted.
shot app-spectra-media "$rainbow" "mousemove 270 386" "click 1" "sleep 0.5" "mousemove 520 190" "sleep 0.5"
# 200 paths kept (typed into the Fire panel), coloured by wavelength (the Paths panel's colour switch),
# photon 0 selected (Right).
shot app-spectra-paths "$rainbow" "mousemove 1040 333" "click 1" "key ctrl+a" "type 200" "key Return" \
    "mousemove 640 60" "key space" "sleep 2" "mousemove 1143 500" "click 1" "sleep 0.5" "mousemove 1143 583" \
    "click 1" "mousemove 640 60" "key Right"
# 1,000,000 photons in 6 wavelength bands (both typed into the Fire panel), the Results plot moved to the
# top left and enlarged (dragged by its title and its corner), zoomed to 125-150 degrees (a drag over the
# bands), the mouse on the bands at the primary bow.
shot app-spectra-results "$rainbow" "mousemove 1040 310" "click 1" "key ctrl+a" "type 1000000" "key Return" \
    "mousemove 1000 402" "click 1" "key ctrl+a" "type 6" "key Return" "mousemove 640 60" "key space" "sleep 8" \
    "mousemove 35 702" "click 1" "mousemove 500 190" "mousedown 1" "mousemove 420 110" "mousemove 350 30" \
    "mouseup 1" "mousemove 798 458" "mousedown 1" "mousemove 1000 600" "mousemove 1270 770" "mouseup 1" \
    "mousemove 929 400" "mousedown 1" "mousemove 1000 400" "mousemove 1070 400" "mouseup 1" \
    "mousemove 773 420" "sleep 0.5"
# Detectors (docs/gui.md, "Detectors"): rainbow-sky.json, 12,000,000 photons (typed into the Fire panel), the
# sky's window opened from the Results panel's "images:" line, binning 2 (its combo box), the mouse on the
# primary bow.
sky="$root/assets/scenes/rainbow-sky.json"
shot app-detectors-sky "$sky" "mousemove 1040 310" "click 1" "key ctrl+a" "type 12000000" "key Return" \
    "mousemove 640 60" "key space" "sleep 80" "mousemove 80 757" "click 1" "sleep 1" "mousemove 570 84" "click 1" \
    "sleep 0.5" "mousemove 570 122" "click 1" "sleep 0.5" "mousemove 671 283" "sleep 0.5"
# The same scene after 2,000,000 photons: the Energy budget window (the Results panel's Budget... button) and the
# Ray orders plot (Orders...), dragged by its title below the budget.
shot app-detectors-results "$sky" "mousemove 1040 310" "click 1" "key ctrl+a" "type 2000000" "key Return" \
    "mousemove 640 60" "key space" "sleep 20" "mousemove 280 722" "click 1" "sleep 0.5" "mousemove 275 740" "click 1" \
    "sleep 1" "mousemove 640 190" "mousedown 1" "mousemove 670 280" "mousemove 700 372" "mouseup 1" "mousemove 640 790"
# 20,000 photons with 500 paths kept (typed into the Fire panel), the Paths panel's filters on order p2 and hit
# "screen", the first photon kept selected and stepped to its internal reflection. The Detectors panel is closed
# first, which hides the detectors' layer too: the screen's image would stand between the view and the drop.
shot app-detectors-paths "$sky" "mousemove 318 300" "click 1" "sleep 0.3" "mousemove 1040 333" "click 1" "key ctrl+a" "type 500" "key Return" \
    "mousemove 1040 310" "click 1" "key ctrl+a" "type 20000" "key Return" "mousemove 640 60" "key space" "sleep 4" \
    "mousemove 990 523" "click 1" "sleep 0.5" "mousemove 990 612" "click 1" "sleep 0.5" "mousemove 1110 523" "click 1" \
    "sleep 0.5" "mousemove 1110 578" "click 1" "sleep 0.5" "mousemove 1100 547" "click 1" "mousemove 640 60" \
    "key Right" "key Right"
# Mie theory (docs/gui.md, "Mie theory"): one water droplet of x = 1200 in a beam 1.5 times as wide,
# diffraction switched on (the Fire panel), 1,000,000 photons; the Results panel moved up and enlarged, its band
# table unfolded, its plot opened, moved and narrowed, the mouse on the polarisation beyond the bow (140 degrees).
mie="$root/assets/scenes/mie-droplet.json"
shot app-mie "$mie" "mousemove 966 425" "click 1" "mousemove 1040 310" "click 1" "key ctrl+a" "type 1000000" \
    "key Return" "mousemove 640 60" "key space" "sleep 10" "mousemove 100 624" "mousedown 1" "mousemove 100 500" \
    "mousemove 100 330" "mouseup 1" "sleep 0.5" "mousemove 325 475" "mousedown 1" "mousemove 380 600" \
    "mousemove 405 770" "mouseup 1" "sleep 0.5" "mousemove 20 458" "click 1" "sleep 0.5" "mousemove 35 408" "click 1" \
    "sleep 1" "mousemove 420 189" "mousedown 1" "mousemove 460 220" "mousemove 498 258" "mouseup 1" "sleep 0.5" \
    "mousemove 1025 686" "mousedown 1" "mousemove 980 700" "mousemove 945 740" "mouseup 1" "sleep 0.5" \
    "mousemove 811 560" "sleep 0.5"
