#!/usr/bin/env bash
# Local vs Slurm on one machine, before (one job per process / per array
# task) and after (batches), in one run: the four runs one after another,
# interleaved so that the machine's load drifts alike over both pairs.
#
# Usage (as root: it starts a one-node cluster, scripts/slurm/start-local-cluster.sh):
#   bash scripts/slurm/bench-local-vs-slurm.sh [-o DIR] [--xval PATH]
#        [--renderers LIST] [--] [SCENES or DIRS...]
#   -o DIR          work folder (default /tmp/xval-bench-slurm; emptied)
#   --xval PATH     the xval executable (default build/renderer/xval)
#   --renderers L   passed to every run (default reference,povray,blender)
#   SCENES          default reference/scenes
#
# The runs, with as many CPUs as the machine has (nproc):
#   local before   xval validate SCENES --batch 1 --schedule count
#   slurm before   submit.sh --jobs-per-task 1 --max-parallel NPROC
#   local after    xval validate SCENES             (batches, weighted pool)
#   slurm after    submit.sh --max-parallel NPROC   (batches: the jobs split
#                  over NPROC array tasks of one CPU each)
# Prints per run: wall seconds, the sum of the jobs' own `seconds` (their
# records; a batched job's count from its batch's start, so this sum only
# compares runs of one variant), the load average before and after, and Slurm / local wall per
# pair; checks with tests/cluster/compare_runs.py that every run's results
# equal the first's, timings aside. Exit 0 when they do, 1 when not, 2 on
# an error.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
die() { echo "bench-local-vs-slurm: $*" >&2; exit 2; }
work=/tmp/xval-bench-slurm xval="$repo/build/renderer/xval" renderers=reference,povray,blender scenes=()
while [ $# -gt 0 ]; do
  case "$1" in
    -o) [ $# -ge 2 ] || die "-o needs a value"; work=$2; shift 2 ;;
    --xval) [ $# -ge 2 ] || die "--xval needs a value"; xval=$2; shift 2 ;;
    --renderers) [ $# -ge 2 ] || die "--renderers needs a value"; renderers=$2; shift 2 ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    --) shift; scenes+=("$@"); break ;;
    -*) die "unknown option $1 (see --help)" ;;
    *) scenes+=("$1"); shift ;;
  esac
done
[ ${#scenes[@]} -gt 0 ] || scenes=("$repo/reference/scenes")
[ -x "$xval" ] || die "$xval: not an executable (build it first, or give --xval)"
[ "$(id -u)" -eq 0 ] || die "needs root (it starts Slurm's daemons)"
xval=$(cd "$(dirname "$xval")" && pwd)/$(basename "$xval")

bash "$here/install.sh"
state="$work/cluster"
[ -d "$state" ] && bash "$here/stop-local-cluster.sh" "$state"
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
state="$work/cluster"
trap 'bash "$here/stop-local-cluster.sh" "$state"' EXIT
bash "$here/start-local-cluster.sh" "$state"
# shellcheck disable=SC1091
source "$state/env.sh"
cpus=$(nproc)
cd "$repo"

now() { date +%s.%N; }
load() { cut -d' ' -f1 /proc/loadavg; }
common=(--renderers "$renderers")
submit=(bash "$here/submit.sh" --xval "$xval" --wait --max-parallel "$cpus" "${common[@]}")
names=() walls=() sums=() loads=() rcs=()
# RUN NAME COMMAND...: times the command, whose output folder is $work/NAME.
run() {
  local name=$1; shift
  local l0 t0 t1 rc
  l0=$(load); t0=$(now)
  set +e; "$@" > "$work/$name.log" 2>&1; rc=$?; set -e
  t1=$(now)
  [ "$rc" -le 1 ] || { tail -n 20 "$work/$name.log" >&2; die "$name: exit $rc (log $work/$name.log)"; }
  names+=("$name"); rcs+=("$rc")
  walls+=("$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", b - a }')")
  sums+=("$(python3 -c 'import json,sys,glob; print("%.1f" % sum(json.load(open(f)).get("seconds", 0) for f in glob.glob(sys.argv[1] + "/*/*.job.json")))' "$work/$name")")
  loads+=("$l0 -> $(load)")
  echo "$name: ${walls[-1]} s wall, jobs' seconds ${sums[-1]} s, load $l0 -> $(load), exit $rc" >&2
}
run local-before "$xval" validate "${scenes[@]}" "${common[@]}" --batch 1 --schedule count -o "$work/local-before"
run slurm-before "${submit[@]}" --jobs-per-task 1 -o "$work/slurm-before" -- "${scenes[@]}"
run local-after "$xval" validate "${scenes[@]}" "${common[@]}" -o "$work/local-after"
run slurm-after "${submit[@]}" -o "$work/slurm-after" -- "${scenes[@]}"

jobs=$(python3 -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["jobs"]))' "$work/local-before/jobs.json")
tasks_before=$(find "$work/slurm-before/slurm" -name 'render-*.log' | wc -l)
tasks_after=$(find "$work/slurm-after/slurm" -name 'render-*.log' | wc -l)
echo
echo "$jobs render jobs ($renderers), $cpus CPUs; Slurm: $tasks_before array tasks before, $tasks_after after"
printf '| %-12s | %8s | %14s | %-14s |\n' run wall "jobs' seconds" "load average"
for i in "${!names[@]}"; do
  printf '| %-12s | %6s s | %12s s | %-14s |\n' "${names[$i]}" "${walls[$i]}" "${sums[$i]}" "${loads[$i]}"
done
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'; }
echo "Slurm / local wall: before $(ratio "${walls[1]}" "${walls[0]}"), after $(ratio "${walls[3]}" "${walls[2]}")"
echo "after / before wall: local $(ratio "${walls[2]}" "${walls[0]}"), Slurm $(ratio "${walls[3]}" "${walls[1]}")"
same=0
for n in slurm-before local-after slurm-after; do
  python3 "$repo/tests/cluster/compare_runs.py" "$work/local-before" "$work/$n" > "$work/compare-$n.txt" 2>&1 ||
    { same=1; echo "$n: results differ from local-before's ($work/compare-$n.txt)"; }
done
[ "$same" -eq 0 ] && echo "every run's results equal local-before's (timings aside)"
exit "$same"
