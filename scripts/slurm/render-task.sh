#!/usr/bin/env bash
# One render job of an `xval validate` plan, run as a Slurm array task
# (submitted by submit.sh): job = OFFSET + SLURM_ARRAY_TASK_ID.
# Usage (by sbatch): sbatch --array=LIST render-task.sh XVAL PLAN [OFFSET]
# Exit status: xval's (0 rendered, 2 the render failed: see the job's
# record OUT/<scene>/<renderer>.job.json and this task's log).
set -euo pipefail
[ $# -ge 2 ] && [ $# -le 3 ] || { echo "usage: sbatch --array=LIST $0 XVAL PLAN [OFFSET]" >&2; exit 2; }
xval=$1
plan=$2
offset=${3:-0}
case "$offset" in ''|*[!0-9]*) echo "render-task: OFFSET '$offset': expected a number" >&2; exit 2 ;; esac
task=${SLURM_ARRAY_TASK_ID:-}
case "$task" in
  ''|*[!0-9]*) echo "render-task: SLURM_ARRAY_TASK_ID is '$task': expected a number (submit with sbatch --array)" >&2; exit 2 ;;
esac
job=$((offset + task))
echo "render-task: job $job of $plan on $(hostname) (Slurm ${SLURM_ARRAY_JOB_ID:-?}_$task)"
exec "$xval" validate --plan "$plan" --run-job "$job"
