#!/usr/bin/env bash
# trace_interrupt.sh DROPSCOPE SCENE OUT
# Ctrl-C on a long `dropscope trace`: starts a run far too long to finish, sends SIGINT once it has
# traced for about a second, and checks the clean stop: exit status 130, one line on stderr, all three
# files written, and summary.json marked partial with 0 < photons < photons_requested.
source "$(dirname "${BASH_SOURCE[0]}")/cli_script_support.sh"

rm -rf "$out" "$out.stdout" "$out.stderr"
# Job control: the background job gets its own process group and, unlike a plain `&` job of a
# non-interactive shell, does not start with SIGINT ignored (dropscope leaves an ignored SIGINT alone).
set -m
"$program" trace "$scene" --photons 1e9 --threads 2 --out "$out" >"$out.stdout" 2>"$out.stderr" &
pid=$!

# The output folder appears just before the photons start; then let them run for a second.
for _ in $(seq 100); do
    [[ -d "$out" ]] && break
    sleep 0.1
done
[[ -d "$out" ]] || fail "no output folder after 10 s"
sleep 1
kill -INT "$pid"
status=0
wait "$pid" || status=$?

[[ $status -eq 130 ]] || fail "exit status $status, expected 130"
[[ $(wc -l <"$out.stderr") -eq 1 ]] || fail "stderr is not exactly one line"
grep -q "^dropscope: trace interrupted: " "$out.stderr" || fail "stderr does not say the trace was interrupted"
for file in summary.json angular.csv paths.jsonl; do
    [[ -f "$out/$file" ]] || fail "$file not written"
done
summary="$out/summary.json"
value() { sed -n "s/^  \"$1\": \\(.*\\),\$/\\1/p" "$summary"; }
[[ $(value partial) == true ]] || fail "summary.json does not say \"partial\": true"
photons=$(value photons)
requested=$(value photons_requested)
[[ $requested -eq 1000000000 ]] || fail "photons_requested is '$requested'"
[[ $photons -gt 0 && $photons -lt $requested ]] || fail "photons is '$photons', expected 0 < photons < $requested"
header=$(head -n 1 "$out/angular.csv")
[[ $header == "theta_lo_deg,theta_hi_deg,fraction,fraction_per_sr,stokes_q,stokes_u,stokes_v,dolp" ]] || fail "angular.csv header is '$header'"
ls "$out" | grep -q partial- && fail "temporary files left in $out"
echo "interrupted after $photons of $requested photons: exit status 130, partial results written"
