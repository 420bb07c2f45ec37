#!/usr/bin/env bash
# Reruns the literature comparisons of docs/validation.md with the Release build:
#   scripts/validate.sh [PHOTONS]    (default 1e7, about 5 s in all; the figures in the doc used 1e8, about 45 s)
# Needs build/app/dropscope (scripts/run.sh builds it). Writes its traces under ${TMPDIR:-/tmp}.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dropscope="$root/build/app/dropscope"
photons="${1:-1e7}"
out="$(mktemp -d "${TMPDIR:-/tmp}/dropscope-validation.XXXXXX")"
[[ -x "$dropscope" ]] || { echo "validate: $dropscope not built; run scripts/run.sh first" >&2; exit 1; }

trace() {  # trace NAME BINS
  "$dropscope" trace "$root/assets/scenes/validation/$1.json" --photons "$photons" --bins "$2" --out "$out/$1" >/dev/null
}
count() {  # count NAME KEY: an integer from summary.json's "counts"
  sed -n "/\"counts\"/,/}/s/.*\"$2\": \([0-9]*\).*/\1/p" "$out/$1/summary.json"
}
# The lower edge of the 0.1-degree bin with the largest radiance between two angles.
brightest() {  # brightest LO HI
  awk -F, -v lo="$1" -v hi="$2" 'NR > 1 && $1 >= lo && $2 <= hi && $4 > best { best = $4; at = $1 }
                                 END { printf "%.1f-%.1f", at, at + 0.1 }' "$out/rainbow/angular.csv"
}
mean_radiance() {  # mean_radiance LO HI
  awk -F, -v lo="$1" -v hi="$2" 'NR > 1 && $1 >= lo && $2 <= hi { sum += $4; n++ } END { printf "%.5f", sum / n }' \
    "$out/rainbow/angular.csv"
}

trace rainbow 1800
trace opaque-sphere 180
trace weak-absorption 180

echo "photons per run: $photons (results in $out)"
echo "primary rainbow, brightest bin in 135-145 deg:   $(brightest 135 145) deg"
echo "secondary rainbow, brightest bin in 125-132 deg: $(brightest 125 132) deg"
echo "Alexander's dark band, mean radiance 130-137 deg: $(mean_radiance 130 137) /sr;" \
     "inside the primary bow 139-146 deg: $(mean_radiance 139 146) /sr;" \
     "outside the secondary 122-128 deg: $(mean_radiance 122 128) /sr"
awk -v e="$(count opaque-sphere escaped)" -v a="$(count opaque-sphere absorbed)" \
  'BEGIN { printf "opaque sphere: escaped (external reflection) %.5f, absorbed %.5f\n", e / (e + a), a / (e + a) }'
awk -v a="$(count weak-absorption absorbed)" -v e="$(count weak-absorption escaped)" \
  'BEGIN { q = a / (a + e); printf "weak absorption (sigma a = 1e-3): absorbed %.6g +- %.2g, C_abs/(sigma V) = %.4f +- %.4f\n",
           q, sqrt(q / (a + e)), q / (4.0 / 3.0 * 1e-3), sqrt(q / (a + e)) / (4.0 / 3.0 * 1e-3) }'
