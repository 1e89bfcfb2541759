#!/usr/bin/env bash
# The `cluster` test: `xval validate` through a real (one-node) Slurm
# cluster gives the same results as a local run, and re-running after a
# failed array task redoes only what failed.
#
# Usage: slurm_cluster_test.sh XVAL SOURCE_DIR WORK_DIR
# Needs root (Slurm daemons; installs slurm-wlm and munge when missing, by
# scripts/slurm/install.sh), POV-Ray and Blender (scripts/install-deps.sh).
#
#  1. starts a private cluster (scripts/slurm/start-local-cluster.sh, state
#     in WORK_DIR/cluster) and stops it on exit, whatever happens;
#  2. validates three small reference scenes through Slurm
#     (scripts/slurm/submit.sh --wait) and locally (xval validate), timing
#     both; both must exit alike with 0 or 1 (2, an error, fails the test),
#     and tests/cluster/compare_runs.py must find results.json and
#     report.html equal except the timing figures;
#  3. submits the same scenes with a stand-in `povray` that fails, as
#     three arrays (--max-array-size 4): the submission must end in an
#     error (the compare job is cancelled, no results.json); then submits again with the real POV-Ray: only the
#     three POV-Ray jobs may be submitted, the other records must be
#     untouched, and the results must again equal the local run's.
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

# 2. Slurm, then local, same scenes.
t0=$(now)
set +e
"${submit[@]}" -o "$work/slurm" -- "${scenes[@]}"
rc_slurm=$?
t1=$(now)
"$xval" validate "${scenes[@]}" "${common[@]}" -o "$work/local"
rc_local=$?
t2=$(now)
set -e
slurm_s=$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')
local_s=$(awk -v a="$t1" -v b="$t2" 'BEGIN { print b - a }')
{
  echo "scenes: ${#scenes[@]} (${scenes[*]##*/}), $((3 * ${#scenes[@]})) render jobs, $(nproc) CPUs"
  printf 'local: %.1f s  (xval validate SCENES -o %s)\n' "$local_s" "$work/local"
  printf 'slurm: %.1f s  (scripts/slurm/submit.sh --wait -o %s -- SCENES: plan, array, compare, polling)\n' \
    "$slurm_s" "$work/slurm"
} | tee "$work/timings.txt"
[ "$rc_local" -eq 0 ] || [ "$rc_local" -eq 1 ] || fail "the local run ended in an error (exit $rc_local)"
[ "$rc_slurm" -eq "$rc_local" ] || fail "Slurm run exit $rc_slurm, local run exit $rc_local"
n_logs=$(find "$work/slurm/slurm" -name 'render-*.log' | wc -l)
[ "$n_logs" -eq $((3 * ${#scenes[@]})) ] || fail "expected $((3 * ${#scenes[@]})) render task logs from Slurm, found $n_logs"
python3 "$src/tests/cluster/compare_runs.py" "$work/local" "$work/slurm" || fail "Slurm and local results differ"

# 3. A failing render task, then a re-run that redoes only it.
mkdir -p "$work/fakebin"
printf '#!/bin/sh\necho "stand-in povray: failing on purpose" >&2\nexit 3\n' > "$work/fakebin/povray"
chmod +x "$work/fakebin/povray"
set +e
# At most 4 jobs per array: 9 jobs go as three arrays (offsets 0, 4, 8).
PATH="$work/fakebin:$PATH" "${submit[@]}" --max-array-size 4 -o "$work/resume" -- "${scenes[@]}"
rc=$?
set -e
[ "$rc" -eq 2 ] || fail "a failing povray: submit --wait exit $rc, expected 2 (an error)"
arrays=$(grep '^render array' "$work/resume/slurm/submitted.log" | sed 's/^render array [0-9]*: //')
[ "$arrays" = $'plan jobs 0-3 (offset 0), at most 16 at once\nplan jobs 0-3 (offset 4), at most 16 at once\nplan jobs 0 (offset 8), at most 16 at once' ] ||
  fail "with --max-array-size 4, expected arrays 0-3 (offset 0), 0-3 (offset 4), 0 (offset 8); submitted: $arrays"
[ "$(find "$work/resume/slurm" -name 'render-*.log' | wc -l)" -eq 9 ] || fail "expected 9 render task logs from the three arrays"
[ ! -e "$work/resume/results.json" ] || fail "a failing render task still produced results.json"
for s in "${scenes[@]}"; do
  name=$(basename "$s" .json)
  grep -q '"error"' "$work/resume/$name/povray.job.json" || fail "$name/povray.job.json does not record the failure"
  for r in reference blender; do
    grep -q '"error"' "$work/resume/$name/$r.job.json" && fail "$name/$r.job.json records an error"
    cp "$work/resume/$name/$r.job.json" "$work/resume/$name/$r.job.json.before"
  done
done
set +e
"${submit[@]}" -o "$work/resume" -- "${scenes[@]}"
rc=$?
set -e
[ "$rc" -eq "$rc_local" ] || fail "the re-run: exit $rc, local run exit $rc_local"
last=$(grep '^render array' "$work/resume/slurm/submitted.log" | tail -n 1)
[[ $last == *"plan jobs 1,4,7 "* ]] || fail "the re-run submitted '$last', expected only the POV-Ray jobs 1,4,7"
for s in "${scenes[@]}"; do
  name=$(basename "$s" .json)
  for r in reference blender; do
    cmp -s "$work/resume/$name/$r.job.json" "$work/resume/$name/$r.job.json.before" ||
      fail "the re-run rendered $name/$r again"
  done
done
python3 "$src/tests/cluster/compare_runs.py" "$work/local" "$work/resume" || fail "resumed Slurm and local results differ"
echo "cluster test: Slurm results equal the local run's; a failed task was redone alone"
