#!/usr/bin/env bash
# xval validate's job mechanics, without Slurm and without POV-Ray or
# Blender (label `unit`): the plan, one job at a time, resume, the compare
# step's handling of jobs that did not run, and the errors (each must name
# the file and field or job). Only the reference renderer renders here; a
# stand-in `povray` that fails shows that an external tool's failure is an
# error.
# Usage: validate_jobs_test.sh XVAL SOURCE_DIR WORK_DIR
set -uo pipefail
xval=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
failures=0 checks=0
pass() { checks=$((checks + 1)); echo "ok: $1"; }
fail() { checks=$((checks + 1)); failures=$((failures + 1)); echo "FAILED: $1" >&2; }
expect() {  # DESCRIPTION COMMAND...: the command must succeed (eval '...' for several)
  local d=$1; shift
  if "$@"; then pass "$d"; else fail "$d"; fi
}
# run CMD...: sets rc, out (stdout), err (stderr)
run() {
  "$@" >"$work/out" 2>"$work/err"
  rc=$?
  out=$(cat "$work/out")
  err=$(cat "$work/err")
}

scene="$src/reference/scenes/light_spot.json"
tol="$src/reference/tolerances.json"
o="$work/run"

# The plan: three jobs, all to run; nothing rendered.
run "$xval" validate "$scene" --renderers reference,povray,blender --tolerances "$tol" -o "$o" --plan-only
expect "plan-only exits 0" [ "$rc" -eq 0 ]
expect "plan-only lists jobs 0 1 2 (got: $out)" [ "$out" = $'0\n1\n2' ]
expect "plan-only writes jobs.json" [ -f "$o/jobs.json" ]
expect "plan-only renders nothing" [ ! -e "$o/light_spot/reference.exr" ]
expect "plan lists the three renderers in order" \
  python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); sys.exit([x["renderer"] for x in j["jobs"]] != ["reference","povray","blender"])' "$o/jobs.json"

# One job: the reference render, its images and record.
run "$xval" validate --plan "$o/jobs.json" --run-job 0
expect "run-job 0 (reference) exits 0 (stderr: $err)" [ "$rc" -eq 0 ]
expect "run-job 0 writes the EXR and PNG" eval '[ -s "$o/light_spot/reference.exr" ] && [ -s "$o/light_spot/reference.png" ]'
expect "run-job 0's record says ok" \
  python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); sys.exit("error" in r or r["renderer"] != "reference" or r["seconds"] <= 0)' "$o/light_spot/reference.job.json"
expect "no temporary files are left" [ -z "$(find "$o" -name '*.partial*')" ]

# Resume: the done job is not listed; without --resume everything is.
run "$xval" validate "$scene" --renderers reference,povray,blender --tolerances "$tol" -o "$o" --plan-only --resume
expect "plan-only --resume lists jobs 1 2 (got: $out)" [ "$out" = $'1\n2' ]
run "$xval" validate "$scene" --renderers reference,povray,blender --tolerances "$tol" -o "$o" --plan-only
expect "plan-only without --resume lists 0 1 2 again (got: $out)" [ "$out" = $'0\n1\n2' ]

# Compare with jobs that never ran: an error (exit 2), said per render.
run "$xval" validate --plan "$o/jobs.json" --compare-only
expect "compare-only with jobs not run exits 2 (got $rc)" [ "$rc" -eq 2 ]
expect "results.json says povray was not rendered, naming its record" \
  python3 -c 'import json,sys; c=json.load(open(sys.argv[1]))["cases"][0]; e=c["renders"]["povray"].get("error",""); sys.exit(not ("not rendered" in e and "povray.job.json" in e) or "error" in c["renders"]["reference"])' "$o/results.json"

# A failing external renderer is an error in the record and the exit status.
mkdir -p "$work/fakebin"
printf '#!/bin/sh\necho "stand-in povray: failing on purpose" >&2\nexit 3\n' > "$work/fakebin/povray"
chmod +x "$work/fakebin/povray"
run env PATH="$work/fakebin:$PATH" "$xval" validate --plan "$o/jobs.json" --run-job 1
expect "run-job with a failing povray exits 2 (got $rc)" [ "$rc" -eq 2 ]
expect "its record holds the error" \
  python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); sys.exit(not r.get("error"))' "$o/light_spot/povray.job.json"
run "$xval" validate "$scene" --renderers reference,povray,blender --tolerances "$tol" -o "$o" --plan-only --resume
expect "a failed job is listed again on resume (got: $out)" [ "$out" = $'1\n2' ]

# A job list (a Slurm array task's batch): every listed job runs and gets
# its record, a failing one is that job's error, the others are ok.
rm -f "$o/light_spot/reference.job.json"
run env PATH="$work/fakebin:$PATH" "$xval" validate --plan "$o/jobs.json" --run-jobs 1,0 --jobs 1
expect "run-jobs 1,0 with a failing povray exits 2 (got $rc)" [ "$rc" -eq 2 ]
expect "run-jobs says 1 of 2 ok, 1 failed (stderr: $err)" eval '[[ $err == *"jobs 1,0: 1 of 2 ok, 1 failed"* ]]'
expect "run-jobs: the povray record holds the stand-in's failure" \
  python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); sys.exit("failing on purpose" not in r.get("error",""))' "$o/light_spot/povray.job.json"
expect "run-jobs: the reference job of the same list is ok" \
  python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); sys.exit("error" in r or r["seconds"] <= 0)' "$o/light_spot/reference.job.json"
run "$xval" validate --plan "$o/jobs.json" --run-jobs 0 --jobs 1 --schedule count
expect "run-jobs 0 exits 0 (stderr: $err)" eval '[ "$rc" -eq 0 ] && [[ $err == *"jobs 0: 1 of 1 ok, 0 failed"* ]]'
for bad in "0,0|job 0 is given twice" "0-3|job 3 is not in the plan (it has jobs 0 to 2)" "2-1|the range ends before it starts" \
           "0,,1|item \"\": expected a job index" "x|item \"x\": expected a job index" "-1|item \"-1\": expected"; do
  run "$xval" validate --plan "$o/jobs.json" --run-jobs="${bad%%|*}"
  expect "run-jobs '${bad%%|*}' is refused naming the item (stderr: $err)" eval '[ "$rc" -eq 2 ] && [[ $err == *"${bad#*|}"* ]]'
done
run "$xval" validate --plan "$o/jobs.json" --run-job 0 --jobs 2
expect "--jobs with --run-job is refused" eval '[ "$rc" -eq 2 ] && [[ $err == *"come from the plan"* ]]'

# Bad requests name what is wrong.
run "$xval" validate --plan "$o/jobs.json" --run-job 3
expect "run-job out of range exits 2 naming the range" eval '[ "$rc" -eq 2 ] && [[ $err == *"has jobs 0 to 2"* ]]'
run "$xval" validate --plan "$o/jobs.json" --run-job 0 -o "$work/elsewhere"
expect "--plan with -o is refused" eval '[ "$rc" -eq 2 ] && [[ $err == *"come from the plan"* ]]'
sed 's/"renderer": "povray"/"renderer": "foo"/' "$o/jobs.json" > "$work/bad_plan.json"
run "$xval" validate --plan "$work/bad_plan.json" --run-job 0
expect "a tampered plan names the field (stderr: $err)" eval '[ "$rc" -eq 2 ] && [[ $err == *'\''bad_plan.json: jobs[1].scene/renderer: "light_spot"/"foo": expected "light_spot"/"povray"'\''* ]]'

# A scene edited after planning: the job refuses it, resume redoes it.
cp "$scene" "$work/edited.json"
o2="$work/edited"
run "$xval" validate "$work/edited.json" --tolerances "$tol" -o "$o2" --plan-only
echo " " >> "$work/edited.json"
run "$xval" validate --plan "$o2/jobs.json" --run-job 0
expect "a scene changed since planning is an error (stderr: $err)" eval '[ "$rc" -eq 2 ] && [[ $err == *"changed since the plan was written"* ]]'

# Two scene files with one name would share an output folder: refused.
run "$xval" validate "$scene" "$work/edited.json" --tolerances "$tol" -o "$work/dup" --plan-only
expect "duplicate scene names are refused (stderr: $err)" eval '[ "$rc" -eq 2 ] && [[ $err == *"also the name of"* ]]'

echo "$((checks - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
