#!/usr/bin/env python3
"""The export cache (renderers/export_cache.h) across `xval validate` runs.

Usage: export_cache_runs.py XVAL COMPARE_RUNS TOLERANCES WORK SCENE...

1. cold then warm: two runs on one new cache folder; the first stores every
   export, the second restores them ("export cache: cached", nothing
   stored) and its results.json and report agree with the first's apart
   from timings (COMPARE_RUNS, tests/cluster/compare_runs.py);
2. concurrent: two runs started together on another new cache folder both
   exit 0 and agree with the cold run; the folder then holds only whole
   entries (each with its manifest, no temporary left).
Exit 0 when all holds, 1 with what did not.
"""
import os
import shutil
import subprocess
import sys


def main():
    xval, compare, tolerances, work = sys.argv[1:5]
    scenes = sys.argv[5:]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    failures = []

    def command(cache, out):
        return [xval, "validate", "--renderers", "reference,povray,blender", "--tolerances", tolerances,
                "--export-cache", cache, "-o", os.path.join(work, out)] + scenes

    def run(cache, out):
        r = subprocess.run(command(cache, out), capture_output=True, text=True)
        if r.returncode != 0:
            failures.append(f"{out}: exit {r.returncode}\n{r.stderr[-3000:]}")
        return r.stderr

    def agree(a, b):
        r = subprocess.run([sys.executable, compare, os.path.join(work, a), os.path.join(work, b)],
                           capture_output=True, text=True)
        if r.returncode != 0:
            failures.append(f"{a} and {b} disagree (compare_runs exit {r.returncode}):\n{r.stdout}{r.stderr}")

    cache = os.path.join(work, "cache")
    cold = run(cache, "cold")
    if "export cache: stored" not in cold:
        failures.append("the cold run stored nothing in the cache:\n" + cold[-2000:])
    warm = run(cache, "warm")
    if "export cache: cached" not in warm or "export cache: stored" in warm:
        failures.append("the warm run did not take every export from the cache:\n" + warm[-2000:])
    agree("cold", "warm")

    shared = os.path.join(work, "shared_cache")
    procs = [subprocess.Popen(command(shared, out), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
             for out in ("concurrent_a", "concurrent_b")]
    for out, p in zip(("concurrent_a", "concurrent_b"), procs):
        _, err = p.communicate(timeout=1800)
        if p.returncode != 0:
            failures.append(f"{out}: exit {p.returncode}\n{err[-3000:]}")
        agree("cold", out)
    entries = sorted(os.listdir(shared)) if os.path.isdir(shared) else []
    if not entries:
        failures.append(f"{shared}: the concurrent runs stored nothing")
    for e in entries:
        if e.startswith(".") or not os.path.isfile(os.path.join(shared, e, "manifest.json")):
            failures.append(f"{shared}/{e}: not a whole entry")

    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
