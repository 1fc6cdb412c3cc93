#!/usr/bin/env bash
# jobscripts/chain without SLURM: stand-ins for sbatch (runs the job script at once) and srun (runs the command
# on one process, with --max-wall far below one step for its first two calls, as a job's time limit would). The
# chain must stop twice with status 5, resubmit itself each time, end with status 0, and leave the probes of the
# run that never stopped.
set -euo pipefail
root=$1
work=$2/chain_test
rm -rf "$work" && mkdir -p "$work"
cat > "$work/srun" <<STANDIN
#!/usr/bin/env bash
n=\$(cat "$work/calls" 2>/dev/null || echo 0)
echo \$((n + 1)) > "$work/calls"
extra=()
[ "\$n" -lt 2 ] && extra=(--max-wall 1e-6)
exec "\$@" "\${extra[@]}"
STANDIN
chmod +x "$work/srun"
sets=(--set fluid.spacing=0.004572 --set scene.end_time=0.05 --set output.field_interval=0.05)
scene="$root/inputs/validation/dambreak.yaml"
SBATCH=bash SRUN="$work/srun" "$root/jobscripts/chain" "$scene" --out "$work/run" --time 00:10:00 \
  "${sets[@]}" > "$work/chain.log" 2>&1 || { cat "$work/chain.log"; echo "the chain failed"; exit 1; }
[ "$(cat "$work/calls")" = 3 ] || { cat "$work/chain.log"; echo "expected 3 links, got $(cat "$work/calls")"; exit 1; }
[ "$(grep -c 'halfeti-chain: exit status 5' "$work/chain.log")" = 2 ] || { cat "$work/chain.log"; echo "expected two stops"; exit 1; }
grep -q 'halfeti-chain: exit status 0' "$work/chain.log" || { echo "the last link did not end the run"; exit 1; }
grep -qE '"exit_status": "ok(_with_warnings)?"' "$work/run/summary.json" || { echo "summary.json does not say ok"; exit 1; }
grep -q -- '--signal=USR1@120' "$work/run/chain.sbatch" || { echo "the job asks for no signal before its limit"; exit 1; }
grep -q -- 'srun --mpi=pmix' "$work/run/chain.sbatch" || { echo "the job does not call srun --mpi=pmix"; exit 1; }
"$2/src/app/halfeti" run "$scene" --out "$work/direct" "${sets[@]}" > /dev/null
cmp "$work/run/probes.csv" "$work/direct/probes.csv" || { echo "the chained run's probes differ from the direct run's"; exit 1; }
# A chain into a folder that holds another run without checkpoints is refused before anything is queued.
rm -rf "$work/direct/checkpoints"/*
if SBATCH=bash SRUN="$work/srun" "$root/jobscripts/chain" "$scene" --out "$work/direct" "${sets[@]}" 2> "$work/refused.err"; then
  echo "a chain into another run's folder was not refused"; exit 1
fi
grep -q "holds another run" "$work/refused.err" || { cat "$work/refused.err"; exit 1; }
echo "jobscripts/chain: 3 links (2 stops), probes equal to the direct run's"
