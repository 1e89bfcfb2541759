#!/usr/bin/python3
"""How much of its precision bound each reference pair's difference uses.

    scripts/precision-headroom.py RUN_FOLDER

RUN_FOLDER: an `xval validate` output folder (its results.json and the
renders' EXRs, which validate writes beside it). For every pair of the
reference renderer with another renderer, over the pixels both cover that
have no edge sample and no backfacing sample (where only the precision
bound explains a difference) and differ by more than the tolerance, it
prints the share (e - tol) / P(p) of the pair's precision bound P(p) =
B_reference(p) + B_other(p) (docs/pixel-classes.md, Precision) the
difference uses: its median, 99th and 99.9th percentiles and maximum. A
share above 1 is a pixel the bound does not explain. The two renderers'
precision models are read from results.json (metrics.precision), the
probe channels from the reference's EXR.

/usr/bin/python3 on purpose: numpy and the OpenImageIO module are Debian's.
"""
import json
import os
import sys

import numpy as np
import OpenImageIO as oiio


def read(path):
    buf = oiio.ImageBuf(path)
    pixels = buf.get_pixels(oiio.FLOAT)
    if buf.has_error or pixels is None:
        sys.exit("%s: cannot read: %s" % (path, buf.geterror()))
    return buf.spec().channelnames, pixels


def bound(model, probes, value):
    return (model["position_steps"] * probes["precision.position"] + model["uv_steps"] * probes["precision.uv"]
            + model["normal_steps"] * probes["precision.normal"] + model["relative"] * value
            + model["quantum_16bit"] / 65535.0)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.split("\n\n")[1])
    run = sys.argv[1]
    with open(os.path.join(run, "results.json"), encoding="utf-8") as f:
        results = json.load(f)
    shares = {}
    for case in results["cases"]:
        ref_image = case["renders"].get("reference", {}).get("image")
        if not ref_image:
            continue
        names, ref = read(os.path.join(run, os.path.splitext(ref_image)[0] + ".exr"))
        ch = {k: ref[:, :, names.index(k)] for k in
              ("A", "edge_fraction", "backfacing", "precision.position", "precision.uv", "precision.normal")}
        for pair in case["pairs"]:
            a, _, b = pair["pair"].partition("-")
            if a != "reference" or "metrics" not in pair:
                continue
            other_file = os.path.join(run, case["scene"], b + ".exr")
            if not os.path.exists(other_file):
                continue
            _, other = read(other_file)
            tol = pair["metrics"]["tolerance"]["max_abs_16bit"] / 65535.0
            models = pair["metrics"]["precision"]
            only_precision = (ch["A"] > 0) & (other[:, :, 3] > 0) & (ch["edge_fraction"] == 0) & (ch["backfacing"] == 0)
            err = np.abs(ref[:, :, :3] - other[:, :, :3]).max(axis=2)
            value = np.maximum(ref[:, :, :3].max(axis=2), other[:, :, :3].max(axis=2))
            p = bound(models["a"], ch, value) + bound(models["b"], ch, value)
            sel = only_precision & (err > tol)
            shares.setdefault(b, []).extend(((err[sel] - tol) / np.maximum(p[sel], 1e-12)).ravel().tolist())
    for name, x in shares.items():
        x = np.array(x)
        if len(x) == 0:
            print("%s: no pixel over the tolerance where only the precision bound explains one" % name)
            continue
        print("%s: %d pixels; (e - tol) / P: median %.3f, p99 %.3f, p99.9 %.3f, max %.3f"
              % (name, len(x), np.median(x), np.percentile(x, 99), np.percentile(x, 99.9), x.max()))


if __name__ == "__main__":
    main()
