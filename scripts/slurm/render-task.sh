#!/usr/bin/env bash
# One render task of an `xval validate` plan, run as a Slurm array task
# (submitted by submit.sh): line OFFSET + SLURM_ARRAY_TASK_ID (0-based) of
# TASKS is the task's job list (plan indices and ranges, "0-3,7"), which
# `xval validate --plan PLAN --run-jobs LIST` renders as a local run
# renders its jobs: Blender's in persistent workers, the others in the
# weighted pool, on the CPUs Slurm gave the task. A task of one job runs
# `--run-job K`.
# Usage (by sbatch): sbatch --array=LIST render-task.sh XVAL PLAN TASKS [OFFSET]
# Exit status: xval's (0 every job rendered, 2 some job failed: see the
# jobs' records OUT/<scene>/<renderer>.job.json and this task's log).
set -euo pipefail
[ $# -ge 3 ] && [ $# -le 4 ] || { echo "usage: sbatch --array=LIST $0 XVAL PLAN TASKS [OFFSET]" >&2; exit 2; }
xval=$1 plan=$2 tasks=$3 offset=${4:-0}
case "$offset" in ''|*[!0-9]*) echo "render-task: OFFSET '$offset': expected a number" >&2; exit 2 ;; esac
task=${SLURM_ARRAY_TASK_ID:-}
case "$task" in
  ''|*[!0-9]*) echo "render-task: SLURM_ARRAY_TASK_ID is '$task': expected a number (submit with sbatch --array)" >&2; exit 2 ;;
esac
line=$((offset + task))
list=$(sed -n "$((line + 1))p" "$tasks") || { echo "render-task: cannot read $tasks" >&2; exit 2; }
case "$list" in
  ''|*[!0-9,-]*) echo "render-task: $tasks line $((line + 1)) (task $line) is '$list': expected a job list such as 0-3,7" >&2; exit 2 ;;
esac
# The CPUs Slurm gave this task (--cpus-per-task, else the allocation).
# (Inline, as in compare-task.sh: sbatch runs a copy of this script from
# its spool folder, so a file beside it cannot be sourced.)
cpus=${SLURM_CPUS_PER_TASK:-${SLURM_CPUS_ON_NODE:-1}}
case "$cpus" in ''|*[!0-9]*|0) cpus=1 ;; esac
echo "render-task: task $line, jobs $list of $plan on $(hostname), $cpus CPUs (Slurm ${SLURM_ARRAY_JOB_ID:-?}_$task)"
case "$list" in
  *[,-]*) exec "$xval" validate --plan "$plan" --run-jobs "$list" --jobs "$cpus" ;;
  *) exec "$xval" validate --plan "$plan" --run-job "$list" ;;
esac
