#!/usr/bin/env python3
"""Prints the cross-renderer agreement tables of README.md and
docs/povray-export.md from a validate run's results.json.

    python3 scripts/agreement-table.py results/validation/results.json readme
    python3 scripts/agreement-table.py results/validation/results.json povray

Errors are in 1/65535 over the pixels both renders cover (the metrics
record of docs/results-schema.json); "within (tol.)" is the share of those
pixels within the pair's per-pixel tolerance, given in brackets.
"""
import json
import sys


def pair(case, name):
    for p in case.get("pairs", []):
        if p["pair"] == name:
            return p
    return None


def compared(p):
    """A pair with metrics; a renderer that cannot express the scene
    (verdict not_expressible, docs/results-schema.json) has none."""
    return p is not None and "metrics" in p


def not_compared(p):
    return "not expressible" if p is not None and p.get("verdict") == "not_expressible" else "(not compared)"


def cell_metrics(p):
    m = p["metrics"]
    return "%.2f / %.2f / %.3f" % (m["max_abs_16bit"], m["p999_abs_16bit"], m["rmse_16bit"])


def within(p):
    m = p["metrics"]
    return "%.3f%% (%g)" % (100.0 * m["fraction_within"], m["tolerance"]["max_abs_16bit"])


def readme(cases):
    print("| scene | POV-Ray: max / p99.9 / RMSE | within (tol.) | POV-Ray s | "
          "Blender: max / p99.9 / RMSE | within (tol.) | Blender render / process s | ref s |")
    print("|---|---|---|---|---|---|---|---|")
    for c in cases:
        pov, bl = pair(c, "reference-povray"), pair(c, "reference-blender")
        r = c["renders"]
        if not compared(pov) and not compared(bl) and (pov is None or bl is None):
            print("| %s | (not compared) |||||||" % c["scene"])
            continue
        pov_cells = ((cell_metrics(pov), within(pov), "%.2f" % r["povray"]["seconds"]) if compared(pov)
                     else (not_compared(pov), "", ""))
        bl_cells = ((cell_metrics(bl), within(bl), "%.2f / %.2f" % (
            r["blender"].get("render_seconds", float("nan")), r["blender"]["seconds"])) if compared(bl)
                    else (not_compared(bl), "", ""))
        print("| %s | %s | %s | %s | %s | %s | %s | %.2f |" % (
            (c["scene"],) + pov_cells + bl_cells + (r["reference"]["seconds"],)))


def povray(cases):
    print("| scene | verdict | max | p99.9 | RMSE | within tol. | tol. | "
          "over tol.: precision/edge/backf./unexpl. | ref s | POV-Ray s |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for c in cases:
        p = pair(c, "reference-povray")
        if not compared(p):
            print("| %s | %s ||||||||||" % (c["scene"], not_compared(p)))
            continue
        m, o = p["metrics"], p["metrics"]["over_tolerance"]
        print("| %s | %s | %.2f | %.2f | %.3f | %.3f%% | %g | %d/%d/%d/%d | %.2f | %.2f |" % (
            c["scene"], "PASS" if p["pass"] else "FAIL", m["max_abs_16bit"], m["p999_abs_16bit"],
            m["rmse_16bit"], 100.0 * m["fraction_within"], m["tolerance"]["max_abs_16bit"],
            o["precision"], o["edge"], o["backfacing_normal"], o["unexplained"],
            c["renders"]["reference"]["seconds"], c["renders"]["povray"]["seconds"]))


def main():
    if len(sys.argv) != 3 or sys.argv[2] not in ("readme", "povray"):
        sys.exit("usage: agreement-table.py RESULTS.json readme|povray")
    with open(sys.argv[1], encoding="utf-8") as f:
        cases = json.load(f)["cases"]
    (readme if sys.argv[2] == "readme" else povray)(cases)


if __name__ == "__main__":
    main()
