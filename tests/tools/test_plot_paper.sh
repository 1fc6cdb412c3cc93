#!/usr/bin/env bash
# tools/plot and tools/paper on a short run of the plate-and-cables scene: one chart per probe, the paper's tension
# chart, and a comparison table that reads the initial tension (135 kPa), marks the other scenes "not run" and
# leaves a run still under way out.
set -euo pipefail
root=$1
work=$2/plot_paper_test
rm -rf "$work" && mkdir -p "$work/paper"
"$2/src/app/halfeti" run "$root/inputs/validation/plate_cables.yaml" --out "$work/paper/cosine_cable" --overwrite \
  --set scene.end_time=0.02 --set output.field_interval=0.01 >/dev/null
/usr/bin/python3 "$root/tools/plot" "$work/paper/cosine_cable" >/dev/null
for probe in tip_x left_stress right_stress right_slack; do
  [ -s "$work/paper/cosine_cable/plots/probe_$probe.png" ] || { echo "no chart for $probe"; exit 1; }
done
/usr/bin/python3 "$root/tools/paper" figures "$work/paper" >/dev/null
[ -s "$work/paper/paper_figures/tension_cosine.png" ] || { echo "no tension chart"; exit 1; }
/usr/bin/python3 "$root/tools/paper" compare "$work/paper" --markdown "$work/comparison.md" >/dev/null
grep -q "| cosine_cable: initial cable tension \[kPa\] | 135 | 135 | -0 % |" "$work/comparison.md" \
  || { echo "initial tension row wrong:"; grep "initial cable" "$work/comparison.md"; exit 1; }
grep -qF '| sine_free | not run (`tools/paper run sine_free`) |' "$work/comparison.md" \
  || { echo "missing runs not marked with their command"; exit 1; }
grep -qF '| sine: max tip displacement, free [% of height] | 35% | not run (`tools/paper run sine_free`) |' \
  "$work/comparison.md" || { echo "a row of a missing run does not name its command"; exit 1; }
# A run still under way (summary "running", probes so far) is left out, its row saying so.
cp -r "$work/paper/cosine_cable" "$work/paper/sine_cable"
sed -i 's/"exit_status": *"[a-z_]*"/"exit_status": "running"/' "$work/paper/sine_cable/summary.json"
/usr/bin/python3 "$root/tools/paper" compare "$work/paper" --markdown "$work/comparison.md" >/dev/null
grep -qF '| sine_cable | running (not finished' "$work/comparison.md" \
  || { echo "a run under way not marked:"; grep "sine_cable |" "$work/comparison.md"; exit 1; }
grep -qF '| sine_cable: initial cable tension [kPa] | 135 | not run' "$work/comparison.md" \
  || { echo "a run under way gave figures:"; grep "sine_cable: initial" "$work/comparison.md"; exit 1; }
if /usr/bin/python3 "$root/tools/plot" "$work/nowhere" 2>/dev/null; then echo "a missing run was accepted"; exit 1; fi
# A run without water has nothing to animate: one line naming why, exit 2.
set +e
message=$(/usr/bin/python3 "$root/tools/plot" "$work/paper/cosine_cable" --movie 2>&1 >/dev/null)
status=$?
set -e
[ "$status" -eq 2 ] && grep -q "no field files" <<<"$message" || { echo "--movie without water: $status '$message'"; exit 1; }
echo "plot and paper: ok"
