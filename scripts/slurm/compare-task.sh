#!/usr/bin/env bash
# The compare/report step of an `xval validate` plan, as a Slurm job that
# submit.sh makes depend on the render array(s) (afterok).
# Usage (by sbatch): sbatch compare-task.sh XVAL PLAN
# Exit status: xval's (0 every case passes, 1 some case fails, 2 an error).
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: sbatch $0 XVAL PLAN" >&2; exit 2; }
echo "compare-task: $2 on $(hostname) (Slurm job ${SLURM_JOB_ID:-?})"
exec "$1" validate --plan "$2" --compare-only
