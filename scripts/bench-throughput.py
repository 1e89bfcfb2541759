#!/usr/bin/python3
"""Throughput of `xval validate`: how much of a run's wall time is the
renderers' own work (docs/performance.md, "Validation throughput").

    scripts/bench-throughput.py [-o DIR] [--xval PATH] [--renderers LIST]
        [--sets reference,sweep] [--sweep-scenes N] [--variants unbatched,after]
        [--before-xval PATH] [--repeat N]

For every set (the reference scenes, and the sweep generated from
reference/specs/throughput_sweep.json: 360 scenes of 32x32, or the first N)
and every variant, one after the other in this one run (the variants
alternate, --repeat times), it runs `xval validate SET -o DIR/SET-VARIANT[-K]`
with a new, empty export cache of its own (DIR/SET-VARIANT[-K].cache: every
run exports every scene) and prints per run the figures below, and per
variant their medians when repeated. The variants:

  unbatched  one Blender process per scene and jobs scheduled by count
             (`--batch 1 --schedule count`: validate as it was before the
             Blender batches and the weighted pool)
  before     the defaults of another xval build (--before-xval, e.g. one
             built from the main branch): what a change of this build gains
  after      the defaults of this build (--xval)

The figures:

  wall      the validate process's wall time (our timer around it)
  busy      per renderer, the renderer's own work summed over the set's
            scenes: the reference renderer's job seconds (the render is all
            it does); POV-Ray's parse + bounding + trace times from its log;
            Blender's (Cycles and EEVEE) render "Time:" from its log; any
            other renderer: its job seconds
  ratio     wall / (busy summed over renderers / cores): 1 means every
            second of the run was a renderer's own work on every core
  scenes/min

and, per set, whether the variants' results.json agree timings aside
(tests/cluster/compare_runs.py). Each run's figures also go to
DIR/bench.json. Not a test: nothing is asserted, the figures are printed.

Run it with the system Python (/usr/bin/python3): Blender takes its
Python's home from the PATH, and a pyenv interpreter puts its own first
(Blender then finds no numpy and every Blender render fails).
"""
import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SPEC = os.path.join(ROOT, "reference", "specs", "throughput_sweep.json")
COMPARE = os.path.join(ROOT, "tests", "cluster", "compare_runs.py")
VARIANTS = {"unbatched": ["--batch", "1", "--schedule", "count"], "before": [], "after": []}

# Blender: " Time: 00:00.27 (Saving: 00:00.00)"
BLENDER_TIME = re.compile(r" Time: (\d+):([0-9.]+)")


def blender_busy(log):
    found = None
    with open(log, errors="replace") as f:
        for line in f:
            m = BLENDER_TIME.search(line)
            if m:
                found = int(m.group(1)) * 60 + float(m.group(2))
    return found


def busy_of_run(out):
    """{renderer: [seconds summed, jobs counted, jobs without a figure]}"""
    plan = json.load(open(os.path.join(out, "jobs.json")))
    busy = {}
    for job in plan["jobs"]:
        scene, renderer = job["scene"], job["renderer"]
        rec_file = os.path.join(out, scene, renderer + ".job.json")
        entry = busy.setdefault(renderer, [0.0, 0, 0])
        if not os.path.exists(rec_file):
            entry[2] += 1
            continue
        rec = json.load(open(rec_file))
        work = os.path.join(out, scene, renderer + ".work")
        value = None
        if renderer == "povray":
            # The job record has POV-Ray's log figures (read by xval):
            # parse (with bounding) and trace; either missing: no figure.
            if "parse_seconds" in rec and "render_seconds" in rec:
                value = rec["parse_seconds"] + rec["render_seconds"]
        elif renderer in ("blender", "eevee") and os.path.exists(os.path.join(work, renderer + ".log")):
            value = blender_busy(os.path.join(work, renderer + ".log"))
        elif renderer not in ("povray", "blender", "eevee"):
            value = rec.get("seconds")
        if value is None:
            entry[2] += 1
        else:
            entry[0] += value
            entry[1] += 1
    return busy


def median(values):
    return statistics.median(values)


def scene_files(folder, limit):
    files = sorted(f for f in os.listdir(folder) if f.endswith(".json"))
    return [os.path.join(folder, f) for f in (files[:limit] if limit else files)]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("-o", "--out", default="/tmp/xval-bench-throughput")
    p.add_argument("--xval", default=os.path.join(ROOT, "build", "renderer", "xval"))
    p.add_argument("--renderers", default="", help="validate --renderers (default: every renderer)")
    p.add_argument("--sets", default="reference,sweep")
    p.add_argument("--sweep-scenes", type=int, default=0, help="only the first N sweep scenes (0: all)")
    p.add_argument("--variants", default="unbatched,after")
    p.add_argument("--before-xval", default="", help="the xval of the variant `before`")
    p.add_argument("--repeat", type=int, default=1, help="run the variants, alternating, N times")
    p.add_argument("--cores", type=int, default=os.cpu_count())
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    sets = {}
    for s in a.sets.split(","):
        if s == "reference":
            sets[s] = [os.path.join(ROOT, "reference", "scenes")]
        elif s == "sweep":
            folder = os.path.join(a.out, "sweep-scenes")
            if not os.path.isdir(folder):
                subprocess.run([a.xval, "generate", SPEC, "-o", folder], check=True, stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL)
            sets[s] = scene_files(folder, a.sweep_scenes)
        else:
            sys.exit("bench-throughput: --sets: unknown set %r (reference, sweep)" % s)
    variants = a.variants.split(",")
    for variant in variants:
        if variant not in VARIANTS:
            sys.exit("bench-throughput: --variants: unknown variant %r (%s)" % (variant, ", ".join(VARIANTS)))
    if "before" in variants and not a.before_xval:
        sys.exit("bench-throughput: --variants before: give --before-xval PATH (the build to compare with)")
    figures = []
    for set_name, inputs in sets.items():
        runs = {}
        for k in range(a.repeat):
            for variant in variants:
                name = "%s-%s" % (set_name, variant) + ("-%d" % (k + 1) if a.repeat > 1 else "")
                out = os.path.join(a.out, name)
                cache = out + ".cache"
                shutil.rmtree(cache, ignore_errors=True)
                xval = a.before_xval if variant == "before" else a.xval
                cmd = [xval, "validate", "-o", out, "--export-cache", cache] + VARIANTS[variant]
                if a.renderers:
                    cmd += ["--renderers", a.renderers]
                cmd += ["--"] + inputs
                log = open(out + ".log", "w")
                load_start = os.getloadavg()[0]
                t0 = time.monotonic()
                status = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT).returncode
                wall = time.monotonic() - t0
                busy = busy_of_run(out)
                total = sum(v[0] for v in busy.values())
                scenes = len(json.load(open(os.path.join(out, "jobs.json")))["scenes"])
                f = {"set": set_name, "variant": variant, "run": name, "xval": xval, "exit": status,
                     "scenes": scenes, "wall": wall,
                     "busy": {r: {"seconds": v[0], "jobs": v[1], "without_figure": v[2]} for r, v in busy.items()},
                     "busy_total": total, "cores": a.cores,
                     "ratio": wall / (total / a.cores) if total > 0 else None,
                     "scenes_per_minute": scenes / wall * 60.0,
                     "load_average_start": load_start, "load_average": os.getloadavg()[0]}
                figures.append(f)
                runs.setdefault(variant, []).append(out)
                print("%-9s %-9s exit %d  %4d scenes  wall %7.1f s  busy %s = %.1f s  ratio %s  %.1f scenes/min  (load %.1f -> %.1f)" % (
                    set_name, name, status, scenes, wall,
                    " + ".join("%s %.1f" % (r, v[0]) + ("" if not v[2] else " (%d without)" % v[2])
                               for r, v in busy.items()),
                    total, "%.2f" % f["ratio"] if f["ratio"] else "-", f["scenes_per_minute"], load_start,
                    f["load_average"]), flush=True)
        first = runs[variants[0]][0]
        for variant in variants:
            for other in runs[variant]:
                if other == first:
                    continue
                r = subprocess.run([sys.executable, COMPARE, first, other], capture_output=True, text=True)
                print("%-9s %s vs %s: results %s" % (set_name, os.path.basename(first), os.path.basename(other),
                      "agree (timings aside)" if r.returncode == 0 else "DIFFER:\n" + r.stdout + r.stderr), flush=True)
        for variant in variants:
            mine = [f for f in figures if f["set"] == set_name and f["variant"] == variant]
            print("%-9s %-9s median of %d: wall %.1f s, busy %.1f s, ratio %.2f, %.1f scenes/min" % (
                set_name, variant, len(mine), median([f["wall"] for f in mine]),
                median([f["busy_total"] for f in mine]), median([f["ratio"] or 0.0 for f in mine]),
                median([f["scenes_per_minute"] for f in mine])), flush=True)
        base = [f["scenes_per_minute"] for f in figures if f["set"] == set_name and f["variant"] == variants[0]]
        for variant in variants[1:]:
            mine = [f["scenes_per_minute"] for f in figures if f["set"] == set_name and f["variant"] == variant]
            print("%-9s %s / %s: %.2fx scenes per minute (medians)" % (set_name, variant, variants[0],
                  median(mine) / median(base)))
    with open(os.path.join(a.out, "bench.json"), "w") as fh:
        json.dump(figures, fh, indent=1)


if __name__ == "__main__":
    main()
