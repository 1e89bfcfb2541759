#!/usr/bin/env bash
# The `cluster` test: `xval validate` through a real (one-node) Slurm
# cluster gives the same results as a local run, with array tasks that
# render batches of jobs and with one job per task, and re-running after
# a failed array task redoes only what failed.
#
# Usage: slurm_cluster_test.sh XVAL SOURCE_DIR WORK_DIR
# Needs root (Slurm daemons; installs slurm-wlm and munge when missing, by
# scripts/slurm/install.sh), POV-Ray and Blender (scripts/install-deps.sh).
#
#  1. starts a private cluster (scripts/slurm/start-local-cluster.sh, state
#     in WORK_DIR/cluster) and stops it on exit, whatever happens;
#  2. validates three small reference scenes through Slurm
#     (scripts/slurm/submit.sh --wait) as one array task of all nine jobs
#     (--jobs-per-task 9, one CPU: Blender's three scenes in one Blender
#     process, counted by a `blender` on PATH that logs and runs the real
#     one), then locally (xval validate), timing both, then through Slurm
#     with one job per task (--jobs-per-task 1: nine tasks); every run must
#     exit alike with 0 or 1 (2, an error, fails the test), and
#     tests/cluster/compare_runs.py must find results.json and report.html
#     of each Slurm run equal to the local run's except the timing figures;
#  3. submits the same scenes with a stand-in `povray` that fails, as
#     five tasks of two jobs in three arrays (--jobs-per-task 2
#     --max-array-size 2): the submission must end in an error (the
#     compare job is cancelled, no results.json), each POV-Ray record holds
#     the stand-in's failure and every other job of the same tasks is ok;
#     then submits again with the real POV-Ray as one task (--jobs-per-task
#     3): only the three POV-Ray jobs may be submitted, the other records
#     must be untouched, and the results must again equal the local run's.
# Wall times go to WORK_DIR/timings.txt and the output.
set -euo pipefail
[ $# -eq 3 ] || { echo "usage: $0 XVAL SOURCE_DIR WORK_DIR" >&2; exit 2; }
xval=$1 src=$(cd "$2" && pwd) work=$3
fail() { echo "cluster test FAILED: $*" >&2; exit 1; }

bash "$src/scripts/slurm/install.sh"
state="$work/cluster"
[ -d "$state" ] && bash "$src/scripts/slurm/stop-local-cluster.sh" "$state"
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
state="$work/cluster"
trap 'bash "$src/scripts/slurm/stop-local-cluster.sh" "$state"' EXIT
bash "$src/scripts/slurm/start-local-cluster.sh" "$state"
# shellcheck disable=SC1091
source "$state/env.sh"

cd "$src"  # both runs from the checkout: same provenance (git commit)
scenes=("$src/reference/scenes/light_spot.json" "$src/reference/scenes/forsyth_lambert.json"
        "$src/reference/scenes/forsyth_hemispherical.json")
# The three renderers the job counts below are written for (every pair of
# them compared, as with five).
common=(--tolerances "$src/reference/tolerances.json" --renderers reference,povray,blender)
submit=(bash "$src/scripts/slurm/submit.sh" --xval "$xval" --wait "${common[@]}")
now() { date +%s.%N; }

# A `blender` that logs its arguments and runs the real one: how many
# Blender processes a run starts, and for how many scenes.
real_blender=$(command -v blender) || fail "blender not found on PATH"
mkdir -p "$work/countbin"
printf '#!/bin/sh\nprintf "%%s\\n" "$*" >> "%s"\nexec "%s" "$@"\n' "$work/blender-calls.log" "$real_blender" \
  > "$work/countbin/blender"
chmod +x "$work/countbin/blender"
renders() { grep -c -e ' --batch ' -e ' --gltf ' "$work/blender-calls.log" || true; }

# 2. Slurm (one task renders the nine jobs), local, Slurm (a task per job).
: > "$work/blender-calls.log"
t0=$(now)
set +e
PATH="$work/countbin:$PATH" "${submit[@]}" --jobs-per-task 9 --render-arg=--cpus-per-task=1 \
  -o "$work/slurm" -- "${scenes[@]}"
rc_slurm=$?
t1=$(now)
"$xval" validate "${scenes[@]}" "${common[@]}" -o "$work/local"
rc_local=$?
t2=$(now)
"${submit[@]}" --jobs-per-task 1 -o "$work/slurm1" -- "${scenes[@]}"
rc_slurm1=$?
t3=$(now)
set -e
secs() { awk -v a="$1" -v b="$2" 'BEGIN { print b - a }'; }
{
  echo "scenes: ${#scenes[@]} (${scenes[*]##*/}), $((3 * ${#scenes[@]})) render jobs, $(nproc) CPUs, load average $(cut -d' ' -f1-3 /proc/loadavg)"
  printf 'local: %.1f s  (xval validate SCENES -o %s)\n' "$(secs "$t1" "$t2")" "$work/local"
  printf 'slurm, one task of 9 jobs: %.1f s  (scripts/slurm/submit.sh --jobs-per-task 9 --wait -o %s -- SCENES: plan, array, compare, polling)\n' \
    "$(secs "$t0" "$t1")" "$work/slurm"
  printf 'slurm, 9 tasks of 1 job: %.1f s  (scripts/slurm/submit.sh --jobs-per-task 1 --wait -o %s -- SCENES)\n' \
    "$(secs "$t2" "$t3")" "$work/slurm1"
} | tee "$work/timings.txt"
[ "$rc_local" -eq 0 ] || [ "$rc_local" -eq 1 ] || fail "the local run ended in an error (exit $rc_local)"
[ "$rc_slurm" -eq "$rc_local" ] || fail "batched Slurm run exit $rc_slurm, local run exit $rc_local"
[ "$rc_slurm1" -eq "$rc_local" ] || fail "one-job-per-task Slurm run exit $rc_slurm1, local run exit $rc_local"
n_logs=$(find "$work/slurm/slurm" -name 'render-*.log' | wc -l)
[ "$n_logs" -eq 1 ] || fail "--jobs-per-task 9: expected 1 render task log from Slurm, found $n_logs"
grep -q 'plan jobs 0-8,' "$work/slurm/slurm/submitted.log" ||
  fail "--jobs-per-task 9: expected one task of plan jobs 0-8: $(cat "$work/slurm/slurm/submitted.log")"
[ "$(renders)" -eq 1 ] && [ "$(grep -c ' --batch ' "$work/blender-calls.log")" -eq 1 ] ||
  fail "one task of three Blender scenes on one CPU: expected one batch Blender process, started: $(cat "$work/blender-calls.log")"
n_logs=$(find "$work/slurm1/slurm" -name 'render-*.log' | wc -l)
[ "$n_logs" -eq $((3 * ${#scenes[@]})) ] || fail "--jobs-per-task 1: expected $((3 * ${#scenes[@]})) render task logs from Slurm, found $n_logs"
python3 "$src/tests/cluster/compare_runs.py" "$work/local" "$work/slurm" || fail "batched Slurm and local results differ"
python3 "$src/tests/cluster/compare_runs.py" "$work/local" "$work/slurm1" || fail "one-job-per-task Slurm and local results differ"

# 3. A failing render task, then a re-run that redoes only it.
mkdir -p "$work/fakebin"
printf '#!/bin/sh\necho "stand-in povray: failing on purpose" >&2\nexit 3\n' > "$work/fakebin/povray"
chmod +x "$work/fakebin/povray"
set +e
# Two jobs per task, at most two tasks per array: 9 jobs go as five tasks
# in three arrays (offsets 0, 2, 4 into the task file).
PATH="$work/fakebin:$PATH" "${submit[@]}" --jobs-per-task 2 --max-array-size 2 -o "$work/resume" -- "${scenes[@]}"
rc=$?
set -e
[ "$rc" -eq 2 ] || fail "a failing povray: submit --wait exit $rc, expected 2 (an error)"
arrays=$(grep '^render array' "$work/resume/slurm/submitted.log" | sed 's/^render array [0-9]*: //; s/ of tasks-[^,]*,/,/')
[ "$arrays" = $'tasks 0-1 (offset 0), 2 jobs per task: plan jobs 0-3, at most 16 at once\ntasks 0-1 (offset 2), 2 jobs per task: plan jobs 4-7, at most 16 at once\ntasks 0 (offset 4), 2 jobs per task: plan jobs 8, at most 16 at once' ] ||
  fail "with --jobs-per-task 2 --max-array-size 2, expected arrays of tasks 0-1 (offset 0), 0-1 (offset 2), 0 (offset 4) over jobs 0-3, 4-7, 8; submitted: $arrays"
[ "$(cat "$work"/resume/slurm/tasks-*.txt)" = $'0-1\n2-3\n4-5\n6-7\n8' ] ||
  fail "expected the task file to list jobs 0-1, 2-3, 4-5, 6-7, 8: $(cat "$work"/resume/slurm/tasks-*.txt)"
[ "$(find "$work/resume/slurm" -name 'render-*.log' | wc -l)" -eq 5 ] || fail "expected 5 render task logs from the three arrays"
[ ! -e "$work/resume/results.json" ] || fail "a failing render task still produced results.json"
for s in "${scenes[@]}"; do
  name=$(basename "$s" .json)
  grep -q 'failing on purpose' "$work/resume/$name/povray.job.json" || fail "$name/povray.job.json does not record the stand-in's failure"
  for r in reference blender; do
    [ -f "$work/resume/$name/$r.job.json" ] || fail "$name/$r.job.json missing: a failing job of its task stopped it"
    grep -q '"error"' "$work/resume/$name/$r.job.json" && fail "$name/$r.job.json records an error"
    cp "$work/resume/$name/$r.job.json" "$work/resume/$name/$r.job.json.before"
  done
done
set +e
"${submit[@]}" --jobs-per-task 3 -o "$work/resume" -- "${scenes[@]}"
rc=$?
set -e
[ "$rc" -eq "$rc_local" ] || fail "the re-run: exit $rc, local run exit $rc_local"
last=$(grep '^render array' "$work/resume/slurm/submitted.log" | tail -n 1)
[[ $last == *"tasks 0 (offset 0)"*"plan jobs 1,4,7, "* ]] || fail "the re-run submitted '$last', expected one task of only the POV-Ray jobs 1,4,7"
for s in "${scenes[@]}"; do
  name=$(basename "$s" .json)
  for r in reference blender; do
    cmp -s "$work/resume/$name/$r.job.json" "$work/resume/$name/$r.job.json.before" ||
      fail "the re-run rendered $name/$r again"
  done
done
python3 "$src/tests/cluster/compare_runs.py" "$work/local" "$work/resume" || fail "resumed Slurm and local results differ"
echo "cluster test: Slurm results (batched tasks and one job per task) equal the local run's; a failed job was redone alone"
