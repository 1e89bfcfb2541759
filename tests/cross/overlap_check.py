#!/usr/bin/env python3
"""Checks that `xval validate` compared a case while other jobs still rendered.

Usage: overlap_check.py RUN [--batch RENDERER]

From RUN/jobs.json, each job's record (RUN/<scene>/<renderer>.job.json:
finished_unix, and seconds from its start) and each case's difference
images (RUN/<scene>/diff_*.exr, written by that case's compare; their
modification time is when it was compared), prints per case when its jobs
ended and when it was compared, and requires:

  * every case compared after its own jobs ended (its diff images are no
    older than its last record), and
  * some case compared before the run's last job ended (the overlap);
  * with --batch RENDERER (a renderer whose jobs ran in one outside
    process, Blender's worker): some case compared before that process
    wrote its last scene's image (the newest RUN/*/RENDERER.work/RENDERER-*.exr,
    the file the worker renders into), i.e. while the batch still rendered,
    not only while its records were being written after it.

Exit 0 when both hold, 1 when not, 2 when a file is missing or unreadable.
"""
import glob
import json
import os
import sys


def main(run, batch=None):
    try:
        with open(os.path.join(run, "jobs.json")) as f:
            plan = json.load(f)
        ended = {}  # scene -> its jobs' last finished_unix
        last = (0.0, None)
        for job in plan["jobs"]:
            with open(os.path.join(run, job["scene"], job["renderer"] + ".job.json")) as f:
                rec = json.load(f)
            t = rec["finished_unix"]
            ended[job["scene"]] = max(ended.get(job["scene"], 0.0), t)
            if t > last[0]:
                last = (t, f"{job['scene']}/{job['renderer']}")
        compared = {}
        for scene in ended:
            diffs = glob.glob(os.path.join(run, scene, "diff_*.exr"))
            if not diffs:
                print(f"{scene}: no diff_*.exr: the case was not compared", file=sys.stderr)
                return 2
            compared[scene] = min(os.stat(d).st_mtime for d in diffs)
    except (OSError, KeyError, ValueError) as e:
        print(f"overlap_check: {run}: {e}", file=sys.stderr)
        return 2
    if batch:
        images = glob.glob(os.path.join(run, "*", batch + ".work", batch + "-*.exr"))
        if not images:
            print(f"overlap_check: no {batch}.work/{batch}-*.exr in {run}", file=sys.stderr)
            return 2
        batch_last = max(os.stat(i).st_mtime for i in images)
    t0 = min(ended.values())
    print(f"last job: {last[1]}, ended at {last[0] - t0:.2f} s (times from the first job's end)")
    ok, overlap = True, []
    for scene in ended:
        print(f"  {scene:32s} jobs ended {ended[scene] - t0:7.2f} s, compared {compared[scene] - t0:7.2f} s")
        if compared[scene] < ended[scene]:
            print(f"    compared before its own jobs ended", file=sys.stderr)
            ok = False
        if compared[scene] < last[0]:
            overlap.append(scene)
    if not overlap:
        print(f"no case was compared before the last job ({last[1]}) ended: no overlap", file=sys.stderr)
        ok = False
    else:
        print(f"compared while {last[1]} still rendered: {', '.join(overlap)}")
    if batch:
        during = [scene for scene in ended if compared[scene] < batch_last]
        print(f"{batch}'s worker wrote its last image at {batch_last - t0:.2f} s")
        if not during:
            print(f"no case was compared while {batch}'s worker still rendered", file=sys.stderr)
            ok = False
        else:
            print(f"compared while {batch}'s worker still rendered: {', '.join(during)}")
    return 0 if ok else 1


if __name__ == "__main__":
    if len(sys.argv) == 2:
        sys.exit(main(sys.argv[1]))
    if len(sys.argv) == 4 and sys.argv[2] == "--batch":
        sys.exit(main(sys.argv[1], sys.argv[3]))
    print(__doc__, file=sys.stderr)
    sys.exit(2)
