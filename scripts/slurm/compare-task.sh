#!/usr/bin/env bash
# The compare/report step of an `xval validate` plan, as a Slurm job that
# submit.sh makes depend on the render array(s) (afterok).
# Usage (by sbatch): sbatch compare-task.sh XVAL PLAN
# Exit status: xval's (0 every case passes, 1 some case fails, 2 an error).
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: sbatch $0 XVAL PLAN" >&2; exit 2; }
# As many cases compared at once as Slurm gave this task CPUs
# (--cpus-per-task, else the allocation; as in render-task.sh).
cpus=${SLURM_CPUS_PER_TASK:-${SLURM_CPUS_ON_NODE:-1}}
case "$cpus" in ''|*[!0-9]*|0) cpus=1 ;; esac
echo "compare-task: $2 on $(hostname), $cpus CPUs (Slurm job ${SLURM_JOB_ID:-?})"
exec "$1" validate --plan "$2" --compare-only --jobs "$cpus"
