#!/usr/bin/env bash
# The job scripts on a real SLURM (tools/slurm-local: one node on the loopback address, its daemons started here
# and stopped on exit): a tiny sweep (a two-task array), a strong and a weak scaling pair (1 and 2 ranks), and the
# paper's array (8 scenes on 2 ranks each) at a tiny end time. Every job must end COMPLETED with exit code 0 and
# every run's summary.json must say "ok"; the wait is bounded (WAIT seconds, then the test fails, never hangs).
#   test_slurm.sh SOURCE_DIR BINARY_DIR
set -euo pipefail
root=$1
work=$2/slurm_test
WAIT=${WAIT:-420}
rm -rf "$work" && mkdir -p "$work"
daemons="$work/daemons"
trap '"$root/tools/slurm-local" stop "$daemons" >/dev/null || true' EXIT
"$root/tools/slurm-local" start "$daemons"
eval "$("$root/tools/slurm-local" env "$daemons")"
fail() { echo "slurm test: $*" >&2; exit 1; }

jobs=()
submitted() {  # the job id of an "Submitted batch job N" line
  local id
  id=$(sed -n 's/^Submitted batch job \([0-9]*\).*/\1/p' <<<"$1")
  [ -n "$id" ] || fail "no job id in: $1"
  jobs+=("$id")
}

# 1. A sweep: two ground-acceleration runs (no water, a second each) as one array.
cat >"$work/tiny.yaml" <<'YAML'
scene: {name: tiny, end_time: 0.2}
output: {probe_interval: 0.01}
excitation: {kind: sine_pulse, amplitude: 1.0, period: 0.2}
probes:
  - {name: ag, kind: ground_acceleration}
YAML
out=$("$root/jobscripts/sweep" "$work/tiny.yaml" --vary excitation.amplitude=1,2 --out "$work/sweep" --slurm \
  --submit --time 00:05:00 2>&1) || fail "sweep submission: $out"
submitted "$out"

# 2-3. Strong and weak scaling pairs of the water benchmark, 0.002 s.
for kind in strong weak; do
  out=$("$root/jobscripts/scaling" --$kind "$root/inputs/bench/sph_slosh.yaml" --ranks 1,2 \
    --set scene.end_time=0.002 --out "$work/scaling_$kind" --slurm --submit 2>&1) || fail "$kind scaling: $out"
  while read -r line; do submitted "$line"; done < <(grep '^Submitted batch job' <<<"$out")
done

# 4. The paper's array, 2 ranks a scene, 0.003 s of each.
out=$(cd "$root" && HALFETI_PAPER_OUT="$work/paper" sbatch --ntasks=2 --output="$work/paper-%A_%a.out" \
  jobscripts/paper.sbatch --set scene.end_time=0.003 2>&1) || fail "paper array: $out"
submitted "$out"
echo "slurm test: submitted jobs ${jobs[*]}"

# Wait, bounded.
deadline=$((SECONDS + WAIT))
while [ -n "$(squeue -h -o %i 2>/dev/null)" ]; do
  [ $SECONDS -lt $deadline ] || { squeue; fail "jobs still queued or running after $WAIT s"; }
  sleep 2
done

# Every job (every array task) COMPLETED with exit code 0:0.
for id in "${jobs[@]}"; do
  states=$(scontrol show job "$id" | grep -o 'JobState=[A-Z_]*\|ExitCode=[0-9:]*' | paste -d' ' - -)
  [ -n "$states" ] || fail "job $id: scontrol knows nothing of it"
  bad=$(grep -v 'JobState=COMPLETED ExitCode=0:0' <<<"$states" || true)
  [ -z "$bad" ] || fail "job $id: $bad"
done

# Their outputs.
ok_summary() { python3 -c "import json,sys; s=json.load(open(sys.argv[1])); sys.exit(0 if s['exit_status']=='ok' else 1)" "$1"; }
"$root/jobscripts/sweep" --collect "$work/sweep" >/dev/null
[ "$(grep -c ',ok,' "$work/sweep/sweep.csv")" -eq 2 ] || fail "sweep.csv: $(cat "$work/sweep/sweep.csv")"
for kind in strong weak; do
  "$root/jobscripts/scaling" --collect "$work/scaling_$kind" >/dev/null || fail "$kind scaling: a run not ok"
  [ -f "$work/scaling_$kind/scaling.png" ] || fail "$kind scaling: no chart"
  [ "$(tail -n +2 "$work/scaling_$kind/scaling.csv" | wc -l)" -eq 2 ] || fail "$kind scaling: expected 2 rows"
done
# The weak pair's second run holds twice the particles of the first.
python3 - "$work/scaling_weak/scaling.csv" <<'PY' || fail "weak scaling: particles do not double"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
sys.exit(0 if int(rows[1]["particles"]) == 2 * int(rows[0]["particles"]) else 1)
PY
n=0
for s in cosine_free cosine_cable sine_free sine_cable elcentro_free elcentro_cable cosine_cable_standard \
         sine_cable_standard; do
  ok_summary "$work/paper/$s/summary.json" || fail "paper $s: $(head -c 300 "$work/paper/$s/summary.json")"
  grep -q '"ranks": 2' "$work/paper/$s/summary.json" || fail "paper $s: not on 2 ranks"
  n=$((n + 1))
done
echo "slurm test: ok (${#jobs[@]} submissions, sweep 2 runs, scaling 2 + 2, paper $n scenes; $SECONDS s)"
