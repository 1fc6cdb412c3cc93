#!/usr/bin/env bash
# tools/study: a malformed study is refused with one line naming the file, the line and the key, before any run;
# a small study (still water at two dx, 0.3 s) runs end to end, and its CSV holds each point's error against the
# closed form and its cost, with the charts drawn (a point continued with --restart costs all its legs); and an
# ensemble (`members:`), whose tables (the spread, the mean histories, and each member's statistics for two
# probes) are checked against the histories read directly.
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
refuse members_axis 's/^resolution: fluid.spacing/resolution: fluid.spacing\nmembers: {vary: {fluid.spacing: [0.006, 0.005]}, probe: p_5mm, sample: 0.01, windows: [[0, 0.3]]}/' \
  "members_axis.yaml:11: members.vary: 'fluid.spacing' is also an axis"
refuse members_window 's/^resolution: fluid.spacing/resolution: fluid.spacing\nmembers: {vary: {fluid.cfl: [0.2, 0.199]}, probe: p_5mm, sample: 0.01, windows: [[0.3, 0.1]]}/' \
  "members_window.yaml:11: members.windows: a list of \[FROM, TO\] with FROM < TO"
refuse members_probe 's/^resolution: fluid.spacing/resolution: fluid.spacing\nmembers: {vary: {fluid.cfl: [0.2, 0.199]}, probe: p_9mm, sample: 0.01, windows: [[0, 0.3]]}/' \
  "members_probe.yaml:11: members.probe: the scene has no probe 'p_9mm'"
refuse members_also 's/^resolution: fluid.spacing/resolution: fluid.spacing\nmembers: {vary: {fluid.cfl: [0.2, 0.199]}, probe: p_5mm, sample: 0.01, windows: [[0, 0.3]], also: [{probe: p_8mm}]}/' \
  "members_also.yaml:11: members.also\[0\].probe: the scene has no probe 'p_8mm'"
refuse members_also_key 's/^resolution: fluid.spacing/resolution: fluid.spacing\nmembers: {vary: {fluid.cfl: [0.2, 0.199]}, probe: p_5mm, sample: 0.01, windows: [[0, 0.3]], also: [{probe: p_25mm, scale: 2}]}/' \
  "members_also_key.yaml:11: members.also\[0\].scale: unknown key"
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
# That point run again in two legs (stopped after its first step, continued with --restart into its folder): its
# cost is both legs', the summary's cpu_seconds and earlier_cpu_seconds, wall_time and earlier_wall_time.
folder=$(/usr/bin/python3 -c 'import json, sys; print([r["folder"] for r in json.load(open(sys.argv[1]))
                                                        if ["fluid.spacing", "0.005"] in r["values"]][0])' "$work/out/runs.json")
legs="inputs/validation/hydrostatic.yaml --set scene.end_time=0.3 --set output.field_interval=0 --set output.checkpoint_interval=0 --set fluid.spacing=0.005 --out $folder"
(cd "$root" && "$2/src/app/halfeti" run $legs --overwrite --max-wall 1e-6 > "$work/leg1.log" 2>&1) && { echo "the first leg did not stop"; exit 1; }
(cd "$root" && "$2/src/app/halfeti" run $legs --restart "$folder" > "$work/leg2.log" 2>&1) || { cat "$work/leg2.log"; exit 1; }
/usr/bin/python3 "$study" collect "$work/still.yaml" --out "$work/out" > "$work/collect.log" 2>&1 \
  || { cat "$work/collect.log"; exit 1; }
/usr/bin/python3 - "$csv" "$folder/summary.json" <<'PY'
import csv, json, sys
row = list(csv.DictReader(open(sys.argv[1])))[0]
s = json.load(open(sys.argv[2]))
assert s["earlier_wall_time"] > 0 and s["cost"]["earlier_cpu_seconds"] > 0, s
for column, total in (("cpu_seconds", s["cost"]["cpu_seconds"] + s["cost"]["earlier_cpu_seconds"]),
                      ("wall_seconds", s["wall_time"] + s["earlier_wall_time"])):
    assert abs(float(row[column]) - total) <= 1e-6 * total, (column, row[column], total)
# A run continued from a checkpoint that did not record the earlier legs' CPU seconds (its summary gives null):
# they are estimated at the last leg's CPU seconds per wall second, marked "~" in study.md and noted in the CSV.
s["cost"]["earlier_cpu_seconds"] = None
json.dump(s, open(sys.argv[2], "w"))
PY
/usr/bin/python3 "$study" collect "$work/still.yaml" --out "$work/out" > "$work/collect.log" 2>&1 \
  || { cat "$work/collect.log"; exit 1; }
/usr/bin/python3 - "$csv" "$folder/summary.json" "$work/out/study.md" <<'PY'
import csv, json, sys
row = list(csv.DictReader(open(sys.argv[1])))[0]
s = json.load(open(sys.argv[2]))
cpu = s["cost"]["cpu_seconds"] * (1 + s["earlier_wall_time"] / s["wall_time"])
assert abs(float(row["cpu_seconds"]) - cpu) <= 1e-6 * cpu, (row["cpu_seconds"], cpu)
assert "estimated" in row["note"], row
md = open(sys.argv[3]).read()
assert "| ~" in md and "~: a run continued with `--restart`" in md, md
PY

# An ensemble: each dx run at two Courant numbers. ensemble.md against the histories read here: two members'
# standard deviation is |a - b| / sqrt(2), their mean (a + b) / 2, the noise of two means sqrt(s_a^2/2 + s_b^2/2).
good | sed -e 's/^resolution: fluid.spacing/resolution: fluid.spacing\nmembers: {vary: {fluid.cfl: [0.2, 0.15]}, probe: p_5mm, sample: 0.01, windows: [[0, 0.2], [0.1, 0.2]], also: [{probe: p_25mm, probe_scale: 0.001, unit: kPa}]}/' \
  -e 's/scene.end_time: 0.3/scene.end_time: 0.2/' -e 's/window: \[0.1, 0.3\]/window: [0.1, 0.2]/g' > "$work/ens.yaml"
/usr/bin/python3 "$study" run "$work/ens.yaml" --out "$work/ens" > "$work/ens.log" 2>&1 || { cat "$work/ens.log"; exit 1; }
[ -s "$work/ens/ensemble.png" ] && [ -s "$work/ens/ensemble_statistics.png" ] || { echo "no ensemble charts"; exit 1; }
/usr/bin/python3 - "$work/ens" <<'PY'
import csv, json, os, sys
import numpy as np
out = sys.argv[1]
runs = json.load(open(os.path.join(out, "runs.json")))
grid = 0.01 * np.arange(21)
hist, hist25 = {}, {}
for run in runs:
    v = dict(run["values"])
    r = list(csv.DictReader(open(os.path.join(run["folder"], "probes.csv"))))
    h = np.interp(grid, [float(x["t"]) for x in r], [float(x["p_5mm"]) for x in r])
    hist.setdefault(v["fluid.spacing"], []).append(h)
    h = np.interp(grid, [float(x["t"]) for x in r], [float(x["p_25mm"]) for x in r])
    hist25.setdefault(v["fluid.spacing"], []).append(1e-3 * h)
assert sorted(hist) == ["0.005", "0.006"] and all(len(h) == 2 for h in hist.values()), hist.keys()
rms = lambda a, m: float(np.sqrt(np.mean(a[m] ** 2)))
wins = [grid <= 0.2 + 1e-12, grid >= 0.1 - 1e-12]
spread = {dx: [rms(np.abs(a - b) / np.sqrt(2), w) for w in wins] for dx, (a, b) in hist.items()}
mean = {dx: (a + b) / 2 for dx, (a, b) in hist.items()}
lines = open(os.path.join(out, "ensemble.md")).read().splitlines()
cut = next(i for i, l in enumerate(lines) if l.startswith("Statistics of"))  # the spread's tables come first
def row(prefix):
    hit = [l for l in lines[:cut] if l.startswith(prefix)]
    assert len(hit) == 1, (prefix, lines)
    return [c.strip() for c in hit[0].strip("|").split("|")]
# the table prints three significant digits: within half a unit of the third
close = lambda text, x: abs(float(text) - x) <= 5e-3 * abs(x) + 1e-9
for dx in hist:
    cells = row(f"| spacing={dx} | 2 |")  # two members
    assert all(close(c, s) for c, s in zip(cells[2:4], spread[dx])), (cells, spread[dx])
    assert spread[dx][0] > 0, "two Courant numbers gave the same history"
    assert close(cells[4], float(mean[dx].max())) and close(cells[5], float(mean[dx].min())), cells
cells = row("| spacing=0.006 | spacing=0.005 |")
for c, w in zip(cells[2:], wins):
    diff, noise = (float(x) for x in c.split("/"))
    assert close(str(diff), rms(mean["0.005"] - mean["0.006"], w)), (c, rms(mean["0.005"] - mean["0.006"], w))
    ref = float(np.sqrt(np.mean(((hist["0.006"][0] - hist["0.006"][1]) ** 2 / 4
                                 + (hist["0.005"][0] - hist["0.005"][1]) ** 2 / 4)[w])))
    assert close(str(noise), ref), (c, ref)
# The statistics tables: each member's time mean, SD in time and largest magnitude over a window; per point their
# mean +- the two members' SD (|a - b| / sqrt(2)); successive points' difference / sqrt(s_a^2/2 + s_b^2/2).
stats = lambda h, w: [h[w].mean(), h[w].std(), np.abs(h[w]).max()]
def section(probe):
    at = [i for i, l in enumerate(lines) if l.startswith(f"Statistics of each member's `{probe}`")]
    assert len(at) == 1, (probe, lines)
    return lines[at[0]:]
for probe, hs in (("p_5mm", hist), ("p_25mm", hist25)):
    part = section(probe)
    assert ("times 0.001 [kPa]" in part[0]) == (probe == "p_25mm"), part[0]
    for dx, (a, b) in hs.items():
        for w, wt in zip(wins, ("0-0.2 s", "0.1-0.2 s")):
            hit = [l for l in part if l.startswith(f"| spacing={dx} | {wt} |")]
            cells = [c.strip() for c in hit[0].strip("|").split("|")][2:]
            for c, sa, sb in zip(cells, stats(a, w), stats(b, w)):
                m, sd = (float(x) for x in c.split("+-"))
                assert close(str(m), (sa + sb) / 2) and abs(sd - abs(sa - sb) / np.sqrt(2)) <= 5e-2 * abs(sa - sb) + 1e-9, (c, sa, sb)
    hit = [l for l in part if l.startswith("| spacing=0.006 | spacing=0.005 | 0.1-0.2 s |")]
    cells = [c.strip() for c in hit[0].strip("|").split("|")][3:]
    s6, s5 = [np.array([stats(h, wins[1]) for h in hs[dx]]) for dx in ("0.006", "0.005")]
    for c, k in zip(cells, range(3)):
        diff, noise = (float(x) for x in c.split("/"))
        assert close(str(diff), s5[:, k].mean() - s6[:, k].mean()), (probe, c)
        ref = np.sqrt(np.var(s6[:, k], ddof=1) / 2 + np.var(s5[:, k], ddof=1) / 2)
        assert abs(noise - ref) <= 5e-2 * ref + 1e-9, (probe, c, ref)
PY
echo "tools/study: refusals, a two-point study and an ensemble ok"
