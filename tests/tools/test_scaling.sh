#!/usr/bin/env bash
# jobscripts/scaling locally: a strong pair (the same particles on 1 and 2 ranks) and a weak pair (twice the tank
# and the particles on 2 ranks), both collected with an efficiency and a chart; bad requests are refused.
set -euo pipefail
root=$1
work=$2/scaling_test
rm -rf "$work" && mkdir -p "$work"
scene="$root/inputs/bench/sph_slosh.yaml"
for kind in strong weak; do
  "$root/jobscripts/scaling" --$kind "$scene" --ranks 1,2 --set scene.end_time=0.001 --out "$work/$kind" >/dev/null
  [ -f "$work/$kind/scaling.png" ] || { echo "$kind: no chart"; exit 1; }
done
python3 - "$work" <<'PY'
import csv, os, sys
for kind, factor in (("strong", 1), ("weak", 2)):
    rows = list(csv.DictReader(open(os.path.join(sys.argv[1], kind, "scaling.csv"))))
    assert [r["ranks"] for r in rows] == ["1", "2"], (kind, rows)
    assert all(r["exit_status"] == "ok" for r in rows), (kind, rows)
    assert int(rows[1]["particles"]) == factor * int(rows[0]["particles"]), (kind, rows)
    assert float(rows[0]["efficiency"]) == 1.0 and float(rows[1]["efficiency"]) > 0.0, (kind, rows)
    assert float(rows[1]["forces_per_step"]) > 0.0, (kind, rows)  # the phases per step
PY
# Repeated rounds: the rank counts in turn, one row per rank count with the medians and the rounds' range.
"$root/jobscripts/scaling" --strong "$scene" --ranks 1,2 --repeat 2 --set scene.end_time=0.001 --out "$work/repeat" \
  >/dev/null
for f in ranks_1_1 ranks_2_1 ranks_1_2 ranks_2_2; do
  [ -f "$work/repeat/$f/summary.json" ] || { echo "repeat: no $f"; exit 1; }
done
python3 - "$work/repeat" <<'PY'
import csv, json, os, statistics, sys
out = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(out, "scaling.csv"))))
assert [r["ranks"] for r in rows] == ["1", "2"] and all(r["repeats"] == "2" for r in rows), rows
for r in rows:
    per_step = []
    for k in (1, 2):
        s = json.load(open(os.path.join(out, f"ranks_{r['ranks']}_{k}", "summary.json")))
        assert s["steps_this_run"] == s["steps"], s  # a run that continues none
        per_step.append(s["loop_wall_time"] / s["steps_this_run"])
    assert abs(float(r["seconds_per_step"]) - statistics.median(per_step)) <= 1e-12 * max(per_step), (r, per_step)
    assert float(r["seconds_per_step_min"]) == min(per_step) and float(r["seconds_per_step_max"]) == max(per_step)
    e, lo, hi = float(r["efficiency"]), float(r["efficiency_min"]), float(r["efficiency_max"])
    assert 0.0 < lo <= hi and (r["ranks"] == "1") == (lo == hi == e == 1.0), r
PY
refuse() {  # the command must exit 2 with a message containing $1
  local want=$1; shift
  if err=$("$@" 2>&1); then echo "accepted: $*"; exit 1; fi
  grep -q -- "$want" <<<"$err" || { echo "wrong message for $*: $err"; exit 1; }
}
# The weak member's tank and probes are stretched, its depth kept.
grep -q "length: 0.6" "$work/weak/scenes/sph_slosh_x2.yaml" || { echo "weak: tank not stretched"; exit 1; }
refuse "expected distinct rank counts" "$root/jobscripts/scaling" --strong "$scene" --ranks 2,0 --out "$work/bad"
refuse "water only" "$root/jobscripts/scaling" --weak "$root/inputs/paper/cosine_cable.yaml" --ranks 1,2 --out "$work/bad"
refuse "does not pass halfeti check" "$root/jobscripts/scaling" --strong "$scene" --ranks 1 --set fluid.spacng=1 --out "$work/bad"
refuse "expected a count of 1 or more" "$root/jobscripts/scaling" --strong "$scene" --ranks 1 --repeat 0 --out "$work/bad"
refuse "one of --strong SCENE or --weak" "$root/jobscripts/scaling" --ranks 1 --out "$work/bad"
echo "scaling: ok"
