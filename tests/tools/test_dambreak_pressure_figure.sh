#!/usr/bin/env bash
# tools/dambreak_pressure_figure.py: a run folder and a study's point (STUDY_DIR#N) drawn into one PNG; a point the
# study does not have, or an argument that is not LABEL=RUN, is one line and exit 2.
set -euo pipefail
root=$1
work=$2/dambreak_pressure_figure_test
rm -rf "$work" && mkdir -p "$work/run" "$work/study"
/usr/bin/python3 - "$work" <<'PY'
import json, math, sys
work = sys.argv[1]
with open(f"{work}/run/probes.csv", "w") as f:
    f.write("t,p_wall\n")
    for k in range(1900):
        t = 0.001 * k
        f.write(f"{t},{3000.0 * (t > 0.6) + 500.0 * math.sin(300.0 * t)}\n")
json.dump([{"folder": f"{work}/run", "values": []}], open(f"{work}/study/runs.json", "w"))
PY
fig="$root/tools/dambreak_pressure_figure.py"
/usr/bin/python3 "$fig" "$work/out.png" "a run=$work/run" "a point=$work/study#1" >/dev/null
[ -s "$work/out.png" ] || { echo "no figure"; exit 1; }
for bad in "b=$work/study#2" "no-label" "c=$work/nowhere"; do
  if /usr/bin/python3 "$fig" "$work/bad.png" "$bad" 2>"$work/err"; then echo "'$bad' accepted"; exit 1; fi
  [ "$(wc -l < "$work/err")" = 1 ] || { echo "'$bad': not one line:"; cat "$work/err"; exit 1; }
done
echo "dambreak_pressure_figure: ok"
