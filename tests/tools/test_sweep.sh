#!/usr/bin/env bash
# jobscripts/sweep in local mode on a tiny scene: a 2 x 2 grid gives four runs and one CSV row each, with the
# varied values and the probe maxima the runs wrote; --zip pairs values; a bad --vary is refused.
set -euo pipefail
root=$1
work=$2/sweep_test
rm -rf "$work" && mkdir -p "$work"
cat > "$work/tiny.yaml" <<'YAML'
scene: {name: tiny, end_time: 0.2}
output: {probe_interval: 0.01}
excitation: {kind: sine_pulse, amplitude: 1.0, period: 0.2}
probes:
  - {name: ag, kind: ground_acceleration}
YAML
"$root/jobscripts/sweep" "$work/tiny.yaml" --vary excitation.amplitude=1,2 --vary excitation.period=0.1,0.2 \
  --out "$work/grid" --probe ag >/dev/null
rows=$(tail -n +2 "$work/grid/sweep.csv" | wc -l)
[ "$rows" -eq 4 ] || { echo "expected 4 rows, found $rows"; exit 1; }
# amplitude 2, period 0.2: the sampled peak of the sine is exactly 2 (t = 0.05 is a probe time).
grep -q "^excitation.amplitude=2_excitation.period=0.2,2,0.2,ok,.*,2.0$" "$work/grid/sweep.csv" \
  || { echo "row for amplitude 2, period 0.2 missing or wrong:"; cat "$work/grid/sweep.csv"; exit 1; }
"$root/jobscripts/sweep" "$work/tiny.yaml" --zip --vary excitation.amplitude=1,3 --vary excitation.period=0.2,0.2 \
  --out "$work/zip" >/dev/null
[ "$(tail -n +2 "$work/zip/sweep.csv" | wc -l)" -eq 2 ] || { echo "--zip: expected 2 rows"; exit 1; }
# --keep: a point added to a finished sweep runs alone; the finished points are kept (their summaries untouched).
before=$(stat -c %Y "$work/zip/excitation.amplitude=1_excitation.period=0.2/summary.json")
out=$("$root/jobscripts/sweep" "$work/tiny.yaml" --zip --vary excitation.amplitude=1,3,4 \
  --vary excitation.period=0.2,0.2,0.2 --out "$work/zip" --keep)
[ "$(grep -c "kept: " <<<"$out")" -eq 2 ] || { echo "--keep: expected 2 kept points: $out"; exit 1; }
[ "$(stat -c %Y "$work/zip/excitation.amplitude=1_excitation.period=0.2/summary.json")" = "$before" ] \
  || { echo "--keep: a kept point was run again"; exit 1; }
[ "$(tail -n +2 "$work/zip/sweep.csv" | wc -l)" -eq 3 ] || { echo "--keep: expected 3 rows"; exit 1; }
# A changed fixed --set is another scene: nothing is kept.
out=$("$root/jobscripts/sweep" "$work/tiny.yaml" --zip --vary excitation.amplitude=1,3 \
  --vary excitation.period=0.2,0.2 --set scene.end_time=0.1 --out "$work/zip" --keep)
! grep -q "kept: " <<<"$out" || { echo "--keep kept a run of another scene: $out"; exit 1; }
# Long point names are cut to 80 characters and a hash (MPI-IO aborts on long file paths).
"$root/jobscripts/sweep" "$work/tiny.yaml" --zip --vary excitation.amplitude=1 --vary excitation.period=0.2 \
  --set excitation.start=0 --vary output.probe_interval=0.0100000000000000000000000000000000000000000000000001 \
  --out "$work/long" --dry-run >/dev/null
name=$(/usr/bin/python3 -c "import json,sys,os; print(os.path.basename(json.load(open(sys.argv[1]))[0]['folder']))" \
  "$work/long/runs.json")
[ "${#name}" -eq 91 ] || { echo "a long point name was not cut: $name"; exit 1; }
if "$root/jobscripts/sweep" "$work/tiny.yaml" --vary excitation.amplitude --out "$work/bad" 2>/dev/null; then
  echo "a malformed --vary was accepted"; exit 1
fi
"$root/jobscripts/sweep" "$work/tiny.yaml" --vary excitation.amplitude=1,2 --slurm --ranks 2 --out "$work/slurm" >/dev/null
grep -q "#SBATCH --array=1-2" "$work/slurm/sweep.sbatch" || { echo "no array line"; exit 1; }
[ "$(wc -l < "$work/slurm/runs.txt")" -eq 2 ] || { echo "runs.txt should hold 2 commands"; exit 1; }
# A misspelt key is refused by halfeti check before anything is written for SLURM or run, naming the point.
if err=$("$root/jobscripts/sweep" "$work/tiny.yaml" --vary excitation.amplitud=1,2 --slurm --out "$work/misspelt" 2>&1); then
  echo "a misspelt --vary key was accepted"; exit 1
fi
grep -q "2 of 2 point(s) do not pass halfeti check" <<<"$err" || { echo "no check error: $err"; exit 1; }
grep -q "did you mean 'amplitude'" <<<"$err" || { echo "the error does not name the key: $err"; exit 1; }
[ ! -e "$work/misspelt/sweep.sbatch" ] || { echo "a job script was written for a sweep that does not check"; exit 1; }
# The time request comes from the estimate (tiny: well under a minute, so 5 minutes).
grep -q "#SBATCH --time=00:05:00" "$work/slurm/sweep.sbatch" || { echo "time request not from the estimate"; exit 1; }
# --ranks auto: the paper's tank (13,333 particles by the check's estimate) gets 2 ranks, the array asks for them.
out=$("$root/jobscripts/sweep" "$root/inputs/bench/sph_slosh.yaml" --vary excitation.amplitude=0.5 --ranks auto \
  --slurm --out "$work/auto")
grep -q "2 rank(s) for 13333 particles" <<<"$out" || { echo "--ranks auto: $out"; exit 1; }
grep -q "#SBATCH --ntasks=2" "$work/auto/sweep.sbatch" || { echo "--ranks auto: no 2-task request"; exit 1; }
echo "sweep: ok"
