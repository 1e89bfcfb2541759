#!/usr/bin/env bash
# Runs `xval validate` on a Slurm cluster: the renders as a job array, the
# compare/report step as one job that runs after every render succeeded.
#
# Usage: scripts/slurm/submit.sh -o OUT [options] [--] [SCENES or DIRS...]
#   -o, --output DIR     output folder; must be on a filesystem every node
#                        sees at the same path (results: DIR/results.json,
#                        DIR/report.html; Slurm logs: DIR/slurm/)
#   --xval PATH          the xval executable, visible on every node
#                        (default: build/renderer/xval of this checkout)
#   --max-parallel N     at most N render tasks at once (the array's %N;
#                        default 16)
#   --jobs-per-task N    render N of the plan's jobs per array task (a
#                        batch: Blender's in one persistent worker per
#                        task CPU, the others side by side as a local run
#                        does); 1: one job per task. Default: the jobs to
#                        run split evenly over --max-parallel tasks, at
#                        most 96 per task
#   --max-array-size N   at most N tasks per array (default and upper bound:
#                        the cluster's MaxArraySize); more tasks are
#                        submitted as several arrays, one after another
#   --tolerances FILE    --timeout S    --renderers LIST    passed to `xval validate`
#   --sbatch-arg ARG     an sbatch option for every job (repeatable), e.g.
#                        --sbatch-arg=--partition=render
#   --render-arg ARG     an sbatch option for the render tasks only, e.g.
#                        --render-arg=--mem=4G --render-arg=--time=00:30:00
#   --compare-arg ARG    an sbatch option for the compare job only
#   --fresh              render everything again (default: resume, i.e. keep
#                        every render whose record says ok, whose inputs are
#                        unchanged and whose images exist)
#   --wait               wait for the compare job; exit with its status
#
# What it does: `xval validate --plan-only [--resume]` writes OUT/jobs.json
# and lists the jobs to run; those are cut into tasks of --jobs-per-task
# jobs, in plan order, one job list per line of OUT/slurm/tasks-STAMP.txt,
# and go to `sbatch --array=RANGE%N render-task.sh XVAL PLAN TASKS OFFSET`
# (line SLURM_ARRAY_TASK_ID + OFFSET is the task's list, rendered by
# `xval validate --plan PLAN --run-jobs LIST`); then `sbatch
# --dependency=afterok:ARRAY --kill-on-invalid-dep=yes compare-task.sh
# XVAL PLAN`. A failed render task fails its array job, so
# the compare job is cancelled instead of reporting; run the same command
# again and only the jobs without an ok record are submitted. Paths and
# scene names reach the jobs as arguments and through the plan file, never
# inside a generated script.
#
# Exit status: without --wait, 0 once submitted, 2 on an error. With
# --wait, the compare job's: 0 every case passes, 1 some case fails, 2 an
# error (including a render task that failed, which cancels the compare).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
die() { echo "submit: $*" >&2; exit 2; }

out="" xval="$repo/build/renderer/xval" max=16 arraysize="" per_task="" fresh=0 wait=0
validate_args=() common=() render_extra=() compare_extra=() scenes=()
need() { [ $# -ge 2 ] || die "$1 needs a value"; }
while [ $# -gt 0 ]; do
  case "$1" in
    -o|--output) need "$@"; out=$2; shift 2 ;;
    --output=*) out=${1#*=}; shift ;;
    --xval) need "$@"; xval=$2; shift 2 ;;
    --xval=*) xval=${1#*=}; shift ;;
    --max-parallel) need "$@"; max=$2; shift 2 ;;
    --max-parallel=*) max=${1#*=}; shift ;;
    --max-array-size) need "$@"; arraysize=$2; shift 2 ;;
    --max-array-size=*) arraysize=${1#*=}; shift ;;
    --jobs-per-task) need "$@"; per_task=$2; shift 2 ;;
    --jobs-per-task=*) per_task=${1#*=}; shift ;;
    --tolerances|--timeout|--renderers) need "$@"; validate_args+=("$1" "$2"); shift 2 ;;
    --tolerances=*|--timeout=*|--renderers=*) validate_args+=("${1%%=*}" "${1#*=}"); shift ;;
    --sbatch-arg) need "$@"; common+=("$2"); shift 2 ;;
    --sbatch-arg=*) common+=("${1#*=}"); shift ;;
    --render-arg) need "$@"; render_extra+=("$2"); shift 2 ;;
    --render-arg=*) render_extra+=("${1#*=}"); shift ;;
    --compare-arg) need "$@"; compare_extra+=("$2"); shift 2 ;;
    --compare-arg=*) compare_extra+=("${1#*=}"); shift ;;
    --fresh) fresh=1; shift ;;
    --wait) wait=1; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    --) shift; scenes+=("$@"); break ;;
    -*) die "unknown option $1 (see --help)" ;;
    *) scenes+=("$1"); shift ;;
  esac
done
[ -n "$out" ] || die "-o OUT is required (see --help)"
case "$max" in ''|*[!0-9]*|0) die "--max-parallel $max: expected a positive whole number" ;; esac
case "$arraysize" in *[!0-9]*|0) die "--max-array-size $arraysize: expected a positive whole number" ;; esac
case "$per_task" in *[!0-9]*|0) die "--jobs-per-task $per_task: expected a positive whole number" ;; esac
[ -x "$xval" ] || die "$xval: not an executable (build it with scripts/build.sh, or give --xval PATH)"
xval=$(cd "$(dirname "$xval")" && pwd)/$(basename "$xval")
for c in sbatch scontrol squeue; do
  command -v "$c" >/dev/null 2>&1 || die "$c not found: is this a Slurm submit host? (scripts/slurm/install.sh)"
done

# 1. The plan, and the jobs still to run.
resume=(--resume)
[ "$fresh" -eq 1 ] && resume=()
todo=$("$xval" validate --plan-only "${resume[@]}" -o "$out" "${validate_args[@]}" -- "${scenes[@]}") ||
  die "xval validate --plan-only failed (exit $?): see above"
mkdir -p "$out"
out=$(cd "$out" && pwd)
plan="$out/jobs.json"
[ -f "$plan" ] || die "$plan: not written by xval validate --plan-only"
mkdir -p "$out/slurm"
log="$out/slurm/submitted.log"
ntodo=$(printf '%s\n' "$todo" | grep -c '^[0-9]' || true)

# 2. The render tasks and array(s). The jobs to run, in plan order, are
# cut into tasks of per_task jobs; the task file holds one job list per
# line (written whole before any task can read it). Array indices must be
# below MaxArraySize, so many tasks are split into arrays of at most
# MaxArraySize (or --max-array-size) tasks, each with an offset into the
# task file; they run one after another (afterany), each at most N tasks
# at once.
arrays=()
if [ "$ntodo" -gt 0 ]; then
  maxsize=$(scontrol show config | awk '$1 == "MaxArraySize" {print $3}')
  case "$maxsize" in ''|*[!0-9]*) die "cannot read MaxArraySize from 'scontrol show config'" ;; esac
  [ -n "$arraysize" ] && [ "$arraysize" -lt "$maxsize" ] && maxsize=$arraysize
  # Default: one task per --max-parallel slot, at most 96 jobs each (so a
  # task's time stays bounded on a large plan).
  if [ -z "$per_task" ]; then
    per_task=$(( (ntodo + max - 1) / max ))
    [ "$per_task" -le 96 ] || per_task=96
  fi
  tasks="$out/slurm/tasks-$(date -u +%Y%m%dT%H%M%SZ)-$$.txt"
  # The task file, and "chunk<TAB>task range<TAB>job ranges" per array.
  specs=$(printf '%s\n' "$todo" | awk -v per="$per_task" -v m="$maxsize" -v tf="$tasks.partial" '
    function rg(lo, hi) { return lo == hi ? lo : lo "-" hi }
    function ranges(s,   a, k, i, v, lo, hi, r) {
      k = split(s, a, " "); r = ""
      for (i = 1; i <= k; i++) {
        v = a[i] + 0
        if (i == 1) { lo = hi = v; continue }
        if (v == hi + 1) { hi = v; continue }
        r = r (r == "" ? "" : ",") rg(lo, hi); lo = hi = v
      }
      if (k > 0) r = r (r == "" ? "" : ",") rg(lo, hi)
      return r
    }
    function endtask() { print ranges(task) > tf; cjobs = cjobs task; nt++; task = ""; n = 0; if (nt == m) endchunk() }
    function endchunk() { print c + 0 "\t" rg(0, nt - 1) "\t" ranges(cjobs); c++; cjobs = ""; nt = 0 }
    /^[0-9]+$/ { task = task " " $1; if (++n == per) endtask() }
    END { if (n > 0) endtask(); if (nt > 0) endchunk(); close(tf) }') ||
    die "cannot write the task file $tasks"
  mv "$tasks.partial" "$tasks"
  prev=""
  while IFS=$'\t' read -r chunk range jobs; do
    offset=$((chunk * maxsize))
    dep=()
    [ -n "$prev" ] && dep=("--dependency=afterany:$prev")
    id=$(sbatch --parsable --job-name=xval-render --array="$range%$max" \
           --output="$out/slurm/render-%A_%a.log" --chdir="$PWD" \
           "${dep[@]}" "${common[@]}" "${render_extra[@]}" \
           "$here/render-task.sh" "$xval" "$plan" "$tasks" "$offset") ||
      die "sbatch of the render array failed (exit $?)"
    id=${id%%;*}
    case "$id" in ''|*[!0-9]*) die "sbatch --parsable printed '$id': expected a job id" ;; esac
    arrays+=("$id")
    prev=$id
    echo "render array $id: tasks $range (offset $offset) of $(basename "$tasks"), $per_task jobs per task: plan jobs $jobs, at most $max at once" | tee -a "$log"
  done <<< "$specs"
fi

# 3. The compare/report step, after every render task succeeded.
dep=()
if [ ${#arrays[@]} -gt 0 ]; then
  dep=("--dependency=afterok$(printf ':%s' "${arrays[@]}")" --kill-on-invalid-dep=yes)
fi
cid=$(sbatch --parsable --job-name=xval-compare --output="$out/slurm/compare-%j.log" --chdir="$PWD" \
        "${dep[@]}" "${common[@]}" "${compare_extra[@]}" \
        "$here/compare-task.sh" "$xval" "$plan") || die "sbatch of the compare job failed (exit $?)"
cid=${cid%%;*}
case "$cid" in ''|*[!0-9]*) die "sbatch --parsable printed '$cid': expected a job id" ;; esac
echo "compare job $cid: after ${arrays[*]:-nothing (every render was done)}; log $out/slurm/compare-$cid.log" | tee -a "$log"
echo "submit: $ntodo render jobs submitted from $plan; results will be in $out/results.json"

[ "$wait" -eq 1 ] || exit 0

# 4. --wait: poll the compare job until it ends.
while :; do
  line=$(scontrol show job -o "$cid" 2>/dev/null) || die "job $cid: scontrol no longer knows it (MinJobAge?); see $out/slurm/"
  state=$(printf '%s\n' "$line" | sed -n 's/.* JobState=\([A-Z_]*\).*/\1/p')
  case "$state" in
    PENDING|RUNNING|CONFIGURING|COMPLETING|SUSPENDED|REQUEUED|RESIZING|'') sleep 2 ;;
    *) break ;;
  esac
done
code=$(printf '%s\n' "$line" | sed -n 's/.* ExitCode=\([0-9]*\):\([0-9]*\).*/\1/p')
reason=$(printf '%s\n' "$line" | sed -n 's/.* Reason=\([^ ]*\).*/\1/p')
case "$state" in
  COMPLETED) echo "submit: compare job $cid completed: every case passes ($out/report.html)"; exit 0 ;;
  FAILED)
    if [ "$code" = 1 ]; then
      echo "submit: compare job $cid: some case FAILS ($out/report.html)"; exit 1
    fi
    echo "submit: compare job $cid failed (exit $code): see $out/slurm/compare-$cid.log" >&2; exit 2 ;;
  *)
    echo "submit: compare job $cid ended $state ($reason)." >&2
    if [ ${#arrays[@]} -gt 0 ]; then
      # Let the other render tasks finish, so that a re-run does not submit
      # jobs that are still running.
      ids=$(IFS=,; echo "${arrays[*]}")
      while [ -n "$(squeue -h -j "$ids" --states=PENDING,RUNNING,SUSPENDED,COMPLETING,CONFIGURING -o %i 2>/dev/null)" ]; do
        sleep 2
      done
      echo "  A render task failed or was cancelled, so the report was not made. Failed renders:" >&2
      grep -l '"error"' "$out"/*/*.job.json 2>/dev/null | sed 's/^/    /' >&2 || true
      echo "  Logs: $out/slurm/render-<array>_<task>.log. Fix the cause, then run the same" >&2
      echo "  command again: only the jobs without an ok record are submitted." >&2
    fi
    exit 2 ;;
esac
