#!/usr/bin/env bash
# tools/study: a malformed study is refused with one line naming the file, the line and the key, before any run;
# a small study (still water at two dx, 0.3 s) runs end to end, and its CSV holds each point's error against the
# closed form and its cost, with the charts drawn.
set -euo pipefail
root=$1
work=$2/study_test
rm -rf "$work" && mkdir -p "$work"
study="$root/tools/study"
good() {
  cat <<YAML
study: {name: still, description: the tool's own test}
base: inputs/validation/hydrostatic.yaml
set: {scene.end_time: 0.3, output.field_interval: 0, output.checkpoint_interval: 0}
reference: {value: 931.95, source: rho g (d - y)}
measure: {probe: p_5mm, metric: mean, window: [0.1, 0.3], relative_to: 931.95}
also:
  - {name: p_noise, probe: p_5mm, metric: noise, smooth: 0.02, window: [0.1, 0.3]}
axes:
  fluid.spacing: [0.006, 0.005]
resolution: fluid.spacing
YAML
}
refuse() {  # name, sed expression applied to the good study, the expected message
  good | sed "$2" > "$work/$1.yaml"
  if /usr/bin/python3 "$study" check "$work/$1.yaml" > "$work/$1.out" 2>&1; then
    echo "$1: accepted"; exit 1
  fi
  grep -q -- "$3" "$work/$1.out" || { echo "$1: expected '$3' in:"; cat "$work/$1.out"; exit 1; }
  [ "$(wc -l < "$work/$1.out")" = 1 ] || { echo "$1: more than one line:"; cat "$work/$1.out"; exit 1; }
}
refuse unknown_key 's/^resolution:/resolutoin:/' "unknown_key.yaml:10: resolutoin: unknown key"
refuse bad_metric 's/metric: mean/metric: median/' "bad_metric.yaml:5: measure.metric: 'median'"
refuse no_probe 's/probe: p_5mm/probe: p_6mm/' "no_probe.yaml:5: measure.probe: the scene has no probe 'p_6mm'"
refuse no_file 's|reference: {value: 931.95, source: rho g (d - y)}|reference: {file: nowhere.csv, columns: [a, b], source: x}|' \
  "no_file.yaml:4: reference.file: missing or unreadable file 'nowhere.csv'"
refuse no_column 's|reference: {value: 931.95, source: rho g (d - y)}|reference: {file: inputs/validation/data/antoci_gate_exp_x.csv, columns: [time_s, disp_z], source: x}|' \
  "no_column.yaml:4: reference.columns: no column 'disp_z'"
refuse bad_key_value 's/fluid.spacing: \[0.006, 0.005\]/fluid.spacing: [0.006, -1]/' "bad_key_value.yaml: point"
refuse no_source 's/, source: rho g (d - y)//' "no_source.yaml:4: reference.source"
refuse noise_width 's/metric: noise, smooth: 0.02,/metric: noise,/' "noise_width.yaml:7: also\[0\].smooth: the noise metric needs"
refuse also_probe 's/name: p_noise, probe: p_5mm/name: p_noise, probe: p_7mm/' "also_probe.yaml:7: also\[0\].probe: the scene has no probe 'p_7mm'"
refuse list_lengths 's/^resolution: fluid.spacing/  fluid.xsph: [0.05]\ndesign: list/' "list_lengths.yaml:9: axes: design: list needs lists of one length"
# One factor at a time: two keys of two values each are two points (a grid would be four).
good | sed 's/^resolution: fluid.spacing/  fluid.xsph: [0.05, 0.0]\ndesign: list/' > "$work/list.yaml"
/usr/bin/python3 "$study" check "$work/list.yaml" | grep -q "^tools/study: 2 point(s) checked" \
  || { echo "a list design of two points"; /usr/bin/python3 "$study" check "$work/list.yaml"; exit 1; }

good > "$work/still.yaml"
/usr/bin/python3 "$study" run "$work/still.yaml" --out "$work/out" > "$work/run.log" 2>&1 || { cat "$work/run.log"; exit 1; }
csv="$work/out/study.csv"
[ "$(wc -l < "$csv")" = 3 ] || { cat "$csv"; echo "expected two points"; exit 1; }
/usr/bin/python3 - "$csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for r in rows:
    assert r["status"].startswith("ok"), r
    # Still water at dx 5-6 mm: the pressure 5 mm up within 5 % of rho g (d - y) (docs/sph.md: within 1 % at 1.5 mm).
    assert 0 <= float(r["relative_error"]) < 0.05, r
    assert float(r["cpu_seconds"]) > 0 and float(r["wall_seconds"]) > 0 and float(r["peak_memory_mb"]) > 1, r
    # The `also` column: still water's pressure noise about its 20 ms mean, a few pascals (not its 932 Pa level).
    assert 0 <= float(r["p_noise"]) < 50, r
PY
for f in study.md error_cost.png convergence.png; do
  [ -s "$work/out/$f" ] || { echo "no $f"; exit 1; }
done
grep -q "the runner's own" "$work/run.log" || { cat "$work/run.log"; exit 1; }
# An axis shortened after the runs: collecting again leaves the run of the dropped point out, and says so.
good | sed 's/fluid.spacing: \[0.006, 0.005\]/fluid.spacing: [0.005]/' > "$work/still.yaml"
/usr/bin/python3 "$study" collect "$work/still.yaml" --out "$work/out" > "$work/collect.log" 2>&1 \
  || { cat "$work/collect.log"; exit 1; }
grep -q "1 run(s) of points no longer in" "$work/collect.log" || { cat "$work/collect.log"; exit 1; }
[ "$(wc -l < "$csv")" = 2 ] || { cat "$csv"; echo "expected one point after the axis was shortened"; exit 1; }
echo "tools/study: refusals and a two-point study ok"
