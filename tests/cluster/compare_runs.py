#!/usr/bin/env python3
"""Checks that two `xval validate` runs of the same scenes agree.

Usage: compare_runs.py RUN_A RUN_B

Compares RUN_A/results.json with RUN_B/results.json and RUN_A/report.html
with RUN_B/report.html. Everything must be equal except what legitimately
differs between two runs of the same scenes:

  results.json  wall_seconds (the run's wall time), and each render's
                `seconds`, `render_seconds`, `process_seconds`, `parse_seconds` (how long it took);
  report.html   the same figures where the report prints them: "Wall time
                X s" and each render's caption "RENDERER, X s (render Y s)";
  both          the run's own output folder in each case's `reproduce`
                command (`-o RUN/SCENE.validate`, where RUN is the run's
                folder: two runs are two folders).

Provenance (POV-Ray, Blender, OpenImageIO, compiler versions, git commit,
settings hash, tolerance file) is compared: both runs here use the same
machine and checkout. On a real cluster whose nodes differ, provenance
could legitimately differ; this check would then say so. Verdicts,
metrics, tolerances, classification, colour statistics, attribution and
errors are compared exactly (floats too: the same EXRs must give the same
numbers). Exit 0 when they agree, 1 (listing every difference) when not,
2 when a file is missing or unreadable.
"""
import json
import re
import sys

TIMING_KEYS = {"seconds", "render_seconds", "process_seconds", "parse_seconds", "wall_seconds"}


# A case's reproduce command names the run's own folder: `-o RUN/x.validate`,
# the word bare or shell-quoted (renderer/process/shell_word.h).
RUN_FOLDER = [
    (re.compile(r"-o '[^']*/([^/']+\.validate)'"), r"-o 'RUN/\1'"),
    (re.compile(r"-o [^\s']*/([^/\s']+\.validate)"), r"-o RUN/\1"),
]


def without_run_folder(text):
    for rx, repl in RUN_FOLDER:
        text = rx.sub(repl, text)
    return text


def strip_timings(node, path="", dropped=None):
    """A copy of node without timing figures; their paths go to dropped."""
    if isinstance(node, dict):
        out = {}
        for k, v in node.items():
            if k in TIMING_KEYS and isinstance(v, (int, float)):
                if dropped is not None:
                    dropped.append(f"{path}/{k}")
                continue
            if k == "reproduce" and isinstance(v, str):
                v = without_run_folder(v)
            out[k] = strip_timings(v, f"{path}/{k}", dropped)
        return out
    if isinstance(node, list):
        return [strip_timings(v, f"{path}/{i}", dropped) for i, v in enumerate(node)]
    return node


def diff(a, b, path, out):
    if type(a) is not type(b):
        out.append(f"{path}: {a!r} != {b!r}")
    elif isinstance(a, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                out.append(f"{path}/{k}: only in {'B' if k not in a else 'A'}")
            else:
                diff(a[k], b[k], f"{path}/{k}", out)
    elif isinstance(a, list):
        if len(a) != len(b):
            out.append(f"{path}: {len(a)} entries != {len(b)}")
        for i, (x, y) in enumerate(zip(a, b)):
            diff(x, y, f"{path}/{i}", out)
    elif a != b:
        out.append(f"{path}: {a!r} != {b!r}")


# The report's timing figures (validate/report/report.cpp): "Wall time 12.3 s" and
# a render caption's "reference, 0.13 s" / "(render 0.45 s)".
REPORT_TIMINGS = [
    (re.compile(r"Wall time [0-9.eE+-]+ s"), "Wall time T s"),
    (re.compile(r"(<figcaption>[a-z0-9-]+), [0-9.eE+-]+ s"), r"\1, T s"),  # ids: [a-z0-9-]
    (re.compile(r"\(render [0-9.eE+-]+ s\)"), "(render T s)"),
]


def normalise_report(text):
    text = without_run_folder(text)
    counts = []
    for rx, repl in REPORT_TIMINGS:
        text, n = rx.subn(repl, text)
        counts.append(n)
    return text, counts


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    a_dir, b_dir = sys.argv[1], sys.argv[2]
    try:
        with open(f"{a_dir}/results.json") as f:
            ra = json.load(f)
        with open(f"{b_dir}/results.json") as f:
            rb = json.load(f)
        with open(f"{a_dir}/report.html") as f:
            ha = f.read()
        with open(f"{b_dir}/report.html") as f:
            hb = f.read()
    except (OSError, ValueError) as e:
        print(f"compare_runs: {e}", file=sys.stderr)
        return 2
    problems = []
    dropped = []
    sa = strip_timings(ra, "", dropped)
    sb = strip_timings(rb)
    diff(sa, sb, "results.json", problems)
    if not sa.get("cases"):
        problems.append("results.json: no cases (nothing was compared)")
    na, ca = normalise_report(ha)
    nb, cb = normalise_report(hb)
    if ca[0] != 1:
        problems.append(f"{a_dir}/report.html: expected one 'Wall time' figure, found {ca[0]}")
    if na != nb:
        la, lb = na.splitlines(), nb.splitlines()
        for i, (x, y) in enumerate(zip(la, lb)):
            if x != y:
                problems.append(f"report.html line {i + 1} differs beyond timings:\n  A: {x[:300]}\n  B: {y[:300]}")
                break
        else:
            problems.append(f"report.html: {len(la)} lines != {len(lb)}")
    if problems:
        print(f"compare_runs: {a_dir} and {b_dir} differ:", file=sys.stderr)
        for p in problems:
            print("  " + p, file=sys.stderr)
        return 1
    print(f"compare_runs: {len(sa['cases'])} cases agree; ignored {len(dropped)} timing figures in "
          f"results.json and {ca[0] + ca[1] + ca[2]} in report.html")
    return 0


if __name__ == "__main__":
    sys.exit(main())
