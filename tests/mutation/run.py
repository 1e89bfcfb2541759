#!/usr/bin/python3
"""The mutation test of issue #36 (docs/mutation-test.md): how specific and
how sensitive `xval validate`'s verdicts are, measured on a generated set of
ordinary scenes (tests/mutation/generated_spec.json) with the correct
renderers and with wrong renderers (tests/mutation/renderers/*.json).

    tests/mutation/run.py --xval build/renderer/xval -o results/mutation --jobs 2
    tests/mutation/run.py --xval build/renderer/xval -o /tmp/mq --quick --check-mutants

1. specificity: the set validated with reference, povray, blender, eevee and
   gl; the share of scenes whose case passes (no scene declares a tolerance).
2. sensitivity: per mutant, the set validated with reference, gl and the
   mutant. Per (mutant, scene) the fault is *visible* when, decided from the
   two EXRs alone (never from xval's verdict), more than 0.5% of the covered
   pixels differ by more than 16/65535 or any pixel by more than 256/65535
   (visibility() below). A visible fault is *detected* when the case fails and
   its attribution names the mutant. Sensitivity = detected / visible.

Writes OUT/mutation.json and OUT/mutation.md (both rates, every miss) and
prints them. Resumable: every validate runs with --resume into its own
folder, and each mutant's folder starts with hard links to the reference and
gl renders of the specificity run (the same jobs: --resume keeps them).
--assert-rates exits 1 unless both rates reach 98%.

--check-mutants is the instrument's own test, and renders only: each
mutant (`xval render --renderer mutant-NAME`) on the scene of CHECK_SCENES
its fault applies to, against the reference renderer's image; it exits 1
unless every mutant's image differs visibly.

This file is /usr/bin/python3 on purpose: numpy and the OpenImageIO module
are Debian's (python3-numpy, python3-openimageio).
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time

import numpy as np
import OpenImageIO as oiio

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
SPEC = os.path.join(HERE, "generated_spec.json")
# Issue #36's three scenes a user wrote from the docs (user_scenes/README.md),
# run beside the generated set in both rates.
USER_SCENES = os.path.join(HERE, "user_scenes")
MUTANT_DIR = os.path.join(HERE, "renderers")
TOLERANCES = os.path.join(REPO, "reference", "tolerances.json")
CORRECT = ["reference", "povray", "blender", "eevee", "gl"]
# The renderers each mutant is validated with, besides itself: two correct
# ones, so the attribution can single the mutant out.
BESIDE_MUTANT = ["reference", "gl"]
REQUIRED_RATE = 0.98

# Visible (independent of xval's verdict logic): per pixel the largest
# difference over R, G, B, A (premultiplied, so lost coverage counts), in
# 1/65535, over the pixels either image covers.
VISIBLE_ABOVE_16BIT = 16.0
VISIBLE_FRACTION = 0.005
VISIBLE_ANY_ABOVE_16BIT = 256.0

# --check-mutants: for each mutant, a scene of the set its fault applies to
# (and is visible on: measured by the full run, docs/mutation-test.md).
CHECK_SCENES = {
    "shininess": "gen_knot_phong_paper_phong_plain_spot_attenuated_spp4",
    "kd": "gen_knot_phong_paper_phong_plain_spot_attenuated_spp4",
    "ambient": "gen_knot_phong_paper_phong_plain_spot_attenuated_spp4",
    "light-moved": "gen_knot_phong_paper_phong_plain_spot_attenuated_spp4",
    "spot-cutoff": "gen_knot_phong_paper_phong_plain_spot_attenuated_spp4",
    "attenuation-swap": "gen_knot_phong_paper_phong_plain_spot_attenuated_spp4",
    "gouraud": "gen_knot_phong_paper_phong_plain_spot_attenuated_spp4",
    "nearest": "gen_sphere_phong_paper_phong_noise_min_bilinear_point_attenuated_spp1",
    "texture-vflip": "gen_boxes_bidir_phong_noise_mag_nearest_spot_attenuated_spp1",
    "texture-srgb": "gen_sphere_phong_paper_phong_noise_min_bilinear_point_attenuated_spp1",
    "output-srgb": "gen_knot_phong_paper_phong_plain_spot_attenuated_spp4",
    "shift": "gen_knot_phong_paper_phong_plain_spot_attenuated_spp4",
    "odd-rows": "gen_knot_phong_paper_phong_plain_spot_attenuated_spp4",
    "cracks": "gen_knot_phong_paper_phong_plain_spot_attenuated_spp4",
    "grazing-cull": "gen_knot_phong_paper_phong_plain_spot_attenuated_spp4",
    "edge-coverage-drop": "gen_knot_phong_paper_phong_plain_spot_attenuated_spp4",
    "edge-coverage-unassociated": "gen_knot_phong_paper_phong_plain_spot_attenuated_spp4",
}

# --quick: these scenes of the set (every mutant's fault applies to one of
# them at least: textures image and brick, spot and attenuated lights,
# Phong shading, spp 1 and 4, a model file).
QUICK_SCENES = [
    "gen_boxes_bidir_phong_noise_mag_nearest_spot_attenuated_spp1",
    "gen_knot_phong_paper_phong_plain_spot_attenuated_spp4",
    "gen_sphere_phong_paper_phong_noise_min_bilinear_point_attenuated_spp1",
    "gen_wuson_ply_wrap_phong_noise_min_bilinear_several_spp1",
    "gen_wuson_stl_mirrored_wrap_phong_noise_min_trilinear_point_attenuated_spp1",
    "gen_suzanne_gltf_phong_paper_phong_brick_spot_attenuated_spp1",
]


def read_rgba(path):
    buf = oiio.ImageBuf(path)
    pixels = buf.get_pixels(oiio.FLOAT)
    if buf.has_error or pixels is None:
        raise RuntimeError(path + ": cannot read: " + buf.geterror())
    names = list(buf.spec().channelnames)
    missing = [c for c in "RGBA" if c not in names]
    if missing:
        raise RuntimeError(path + ": no channel(s) " + ",".join(missing))
    return np.stack([pixels[:, :, names.index(c)] for c in "RGBA"], axis=-1)


def visibility(mutant_exr, reference_exr):
    """Whether the mutant's image differs visibly from the reference's, and
    the figures that decide it."""
    a, b = read_rgba(mutant_exr), read_rgba(reference_exr)
    if a.shape != b.shape:
        return {"visible": True, "reason": "sizes differ %s vs %s" % (a.shape, b.shape)}
    diff = np.abs(a - b).max(axis=-1) * 65535.0
    covered = (a[:, :, 3] > 0) | (b[:, :, 3] > 0)
    n_covered = int(covered.sum())
    over = int((diff[covered] > VISIBLE_ABOVE_16BIT).sum()) if n_covered else 0
    max_diff = float(diff.max())
    visible = (n_covered > 0 and over > VISIBLE_FRACTION * n_covered) or max_diff > VISIBLE_ANY_ABOVE_16BIT
    return {"visible": bool(visible), "covered": n_covered, "over_16": over,
            "fraction_over_16": over / n_covered if n_covered else 0.0, "max_16bit": max_diff}


def mutants(only):
    names = sorted(f[:-5] for f in os.listdir(MUTANT_DIR) if f.endswith(".json"))
    if only:
        unknown = [m for m in only if m not in names]
        if unknown:
            sys.exit("run.py: unknown mutant(s) %s (known: %s)" % (", ".join(unknown), ", ".join(names)))
        names = [m for m in names if m in only]
    return names


def validate(xval, scenes, renderers, out, jobs, renderer_file=None, log=None, report_only=False):
    if report_only:
        return None, read_cases(out)
    cmd = [xval, "validate", *scenes, "--renderers", ",".join(renderers), "-o", out, "--jobs", str(jobs),
           "--tolerances", TOLERANCES, "--resume"]
    if renderer_file:
        cmd += ["--renderer-file", renderer_file]
    with open(log, "w") as f:
        rc = subprocess.run(cmd, stdin=subprocess.DEVNULL, stdout=f, stderr=subprocess.STDOUT).returncode
    if rc not in (0, 1) and not os.path.exists(os.path.join(out, "results.json")):
        raise RuntimeError("%s exited %d without results.json; see %s" % (" ".join(cmd), rc, log))
    return rc, read_cases(out)


def read_cases(out):
    results = os.path.join(out, "results.json")
    if not os.path.exists(results):
        raise RuntimeError(results + ": missing (run without --report-only first)")
    with open(results) as f:
        return {c["scene"]: c for c in json.load(f)["cases"]}


# How renderers::attribute (registry.cpp) says that a pair disagrees: at
# the end of its clause, before "(the other pairs agree)", or before "only
# on the fraction within tolerance" (a pair failing on the fraction alone).
DISAGREE_CLAUSE = re.compile(r" disagree( \(| only on the fraction|$)")


def names_as_deviating(attribution, name):
    """Whether the attribution (renderers::attribute in registry.cpp) puts
    `name` among the renderers that deviate ("X deviates (A and B agree)",
    "X deviates (unexplained differences against A and B; A and B fail
    only on the fraction within tolerance)", "X deviates, only on the
    fraction within tolerance (...)", "X and Y deviate (...)") or in a pair
    that disagrees ("A and X disagree; ...", "A and X disagree only on the
    fraction within tolerance"), not among those that agree."""
    for clause in attribution.split("; "):
        if " deviate" in clause:
            if name in clause.split(" deviate")[0]:
                return True
        elif DISAGREE_CLAUSE.search(clause):
            if name in clause.split(" disagree")[0]:
                return True
    return False


def fails_hard(pair):
    """Whether a pair of results.json fails on more than the fraction within
    tolerance (a mask disagreement, the unexplained cap: its "failed"
    criteria, renderer/image/pair_failure.h)."""
    return pair.get("pass") is False and any(f["key"] != "fraction" for f in pair.get("failed", []))


def miss_cause(cell, correct_cases):
    """Why a visible fault was missed, in the groups docs/mutation-test.md
    lists."""
    if cell["pass"]:
        return "the case passes"
    if cell["pass"] is None:
        return "no case"
    pairs = {p["pair"]: p for p in correct_cases.get(cell["scene"], {}).get("pairs", [])}
    beside = "-".join(BESIDE_MUTANT)
    # A pair of correct renderers failing on the fraction alone still lets
    # the attribution single the mutant out (renderers::attribute): only a
    # hard failure between them leaves no majority.
    if beside in pairs and fails_hard(pairs[beside]):
        return "fails, but %s already disagree (no majority to single the mutant out)" % " and ".join(BESIDE_MUTANT)
    return "fails, attribution does not name the mutant"


def seed_from(specificity, out, scenes):
    """Hard links to the specificity run's reference and gl renders and
    records, so --resume keeps them."""
    for s in scenes:
        src, dst = os.path.join(specificity, s), os.path.join(out, s)
        if not os.path.isdir(src):
            continue
        os.makedirs(dst, exist_ok=True)
        for f in os.listdir(src):
            if f.split(".")[0] in BESIDE_MUTANT and os.path.isfile(os.path.join(src, f)) \
                    and not os.path.exists(os.path.join(dst, f)):
                os.link(os.path.join(src, f), os.path.join(dst, f))


def render(xval, scene, exr, log, renderer=None):
    cmd = [xval, "render", scene, "-o", exr, "-q"]
    if renderer:
        cmd += ["--renderer", "mutant-" + renderer, "--renderer-file", os.path.join(MUTANT_DIR, renderer + ".json")]
    with open(log, "w") as f:
        rc = subprocess.run(cmd, stdin=subprocess.DEVNULL, stdout=f, stderr=subprocess.STDOUT).returncode
    if rc != 0:
        raise RuntimeError("%s exited %d; see %s" % (" ".join(cmd), rc, log))


def check_mutants(xval, set_dir, names, out, which):
    """Each mutant's image on its scene must differ visibly from the
    reference renderer's."""
    missing = [m for m in which if m not in CHECK_SCENES]
    unknown = [s for s in CHECK_SCENES.values() if s not in names]
    if missing or unknown:
        sys.exit("run.py: CHECK_SCENES has no scene for %s; names scenes not in the set: %s"
                 % (", ".join(missing) or "-", ", ".join(unknown) or "-"))
    status = 0
    rendered = set()
    for m in which:
        scene = CHECK_SCENES[m]
        ref = os.path.join(out, scene + ".reference.exr")
        if ref not in rendered:  # rendered anew by each run: never an earlier xval's image
            render(xval, os.path.join(set_dir, scene + ".json"), ref, ref + ".log")
            rendered.add(ref)
        exr = os.path.join(out, scene + "." + m + ".exr")
        render(xval, os.path.join(set_dir, scene + ".json"), exr, exr + ".log", renderer=m)
        v = visibility(exr, ref)
        print("%-28s %s on %s: %.2f%% of %d covered pixels over %g/65535, max %.0f/65535"
              % (m, "visible" if v["visible"] else "NOT VISIBLE", scene, 100 * v["fraction_over_16"],
                 v["covered"], VISIBLE_ABOVE_16BIT, v["max_16bit"]))
        status |= 0 if v["visible"] else 1
    return status


def failing_pairs(case):
    """The compared pairs that fail (not those a renderer cannot express)."""
    return [p["pair"] for p in case.get("pairs", []) if not p.get("pass") and "not_expressible" not in p]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--xval", required=True, help="the xval executable")
    ap.add_argument("-o", "--output", required=True, help="output folder (resumable)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--quick", action="store_true",
                    help="only the scenes of QUICK_SCENES and the user scenes, every mutant")
    ap.add_argument("--mutants", default="", help="only these mutants, comma-separated")
    ap.add_argument("--no-specificity", action="store_true",
                    help="skip the five-renderer run (the mutants then render their reference and gl images)")
    ap.add_argument("--check-mutants", action="store_true",
                    help="only render each mutant on its scene of CHECK_SCENES and exit 1 unless its image "
                         "differs visibly from the reference renderer's")
    ap.add_argument("--report-only", action="store_true",
                    help="run no validate: read the results.json files an earlier run wrote and report")
    ap.add_argument("--assert-rates", action="store_true", help="exit 1 unless both rates are at least 98%%")
    args = ap.parse_args()
    xval = os.path.abspath(args.xval)
    out = os.path.abspath(args.output)
    os.makedirs(out, exist_ok=True)
    env_xval = os.environ.get("XVAL")
    os.environ["XVAL"] = xval  # the mutants' script renders with it
    if env_xval and os.path.abspath(env_xval) != xval:
        print("run.py: XVAL=%s replaced by --xval %s" % (env_xval, xval))
    start = time.time()

    set_dir = os.path.join(out, "set")
    gen = subprocess.run([xval, "generate", SPEC, "-o", set_dir], stdin=subprocess.DEVNULL,
                         capture_output=True, text=True)
    if gen.returncode != 0:
        sys.exit("run.py: xval generate %s failed (exit %d):\n%s" % (SPEC, gen.returncode, gen.stderr))
    names = sorted(f[:-5] for f in os.listdir(set_dir) if f.endswith(".json"))
    if args.check_mutants:
        return check_mutants(xval, set_dir, names, out, mutants([x for x in args.mutants.split(",") if x]))
    if args.quick:
        missing = [s for s in QUICK_SCENES if s not in names]
        if missing:
            sys.exit("run.py: QUICK_SCENES not in the generated set: " + ", ".join(missing))
        names = QUICK_SCENES
    scenes = [os.path.join(set_dir, s + ".json") for s in names]
    users = sorted(f[:-5] for f in os.listdir(USER_SCENES) if f.endswith(".json"))
    names = names + users
    scenes += [os.path.join(USER_SCENES, s + ".json") for s in users]
    report = {"command": " ".join(sys.argv), "scenes": len(names), "quick": args.quick,
              "report_only": args.report_only,
              "definition_of_visible": "more than %g%% of the covered pixels differ by more than %g/65535, or any "
                                       "pixel by more than %g/65535 (largest of R, G, B, A, premultiplied)"
                                       % (100 * VISIBLE_FRACTION, VISIBLE_ABOVE_16BIT, VISIBLE_ANY_ABOVE_16BIT)}

    # 1. specificity
    specificity_dir = os.path.join(out, "specificity")
    if not args.no_specificity:
        t = time.time()
        rc, cases = validate(xval, scenes, CORRECT, specificity_dir, args.jobs,
                             log=os.path.join(out, "specificity.log"), report_only=args.report_only)
        correct_cases = cases
        passed = [s for s in names if cases.get(s, {}).get("pass")]
        misses = [{"scene": s, "attribution": cases.get(s, {}).get("attribution", "(no case)"),
                   "failing_pairs": failing_pairs(cases.get(s, {}))} for s in names if s not in passed]
        report["specificity"] = {"renderers": CORRECT, "passed": len(passed), "scenes": len(names),
                                 "rate": len(passed) / len(names), "misses": misses, "seconds": time.time() - t}
        print("specificity: %d of %d scenes pass (%.1f%%) with %s, %.0f s"
              % (len(passed), len(names), 100.0 * len(passed) / len(names), ",".join(CORRECT), time.time() - t))

    # 2. sensitivity
    per_mutant, cells = {}, []
    if args.no_specificity:
        correct_cases = {}
    for m in mutants([x for x in args.mutants.split(",") if x]):
        t = time.time()
        name = "mutant-" + m
        mdir = os.path.join(out, "mutants", m)
        os.makedirs(mdir, exist_ok=True)
        if not args.no_specificity and not args.report_only:
            seed_from(specificity_dir, mdir, names)
        rc, cases = validate(xval, scenes, BESIDE_MUTANT + [name], mdir, args.jobs,
                             renderer_file=os.path.join(MUTANT_DIR, m + ".json"), log=os.path.join(mdir, "validate.log"),
                             report_only=args.report_only)
        visible = detected = 0
        for s in names:
            case = cases.get(s, {})
            cell = {"mutant": m, "scene": s, "pass": case.get("pass"), "attribution": case.get("attribution", "(no case)")}
            mexr, rexr = os.path.join(mdir, s, name + ".exr"), os.path.join(mdir, s, "reference.exr")
            if os.path.exists(mexr) and os.path.exists(rexr):
                cell.update(visibility(mexr, rexr))
            else:
                cell.update({"visible": None, "reason": "no render (see the case's renders in results.json)"})
            cell["detected"] = bool(cell["pass"] is False and names_as_deviating(cell["attribution"], name))
            cell["deviates"] = (name + " deviates") in cell["attribution"]
            if cell["visible"] and not cell["detected"]:
                cell["cause"] = miss_cause(cell, correct_cases)
            if cell["visible"]:
                visible += 1
                detected += cell["detected"]
            cells.append(cell)
        per_mutant[m] = {"visible": visible, "detected": detected, "scenes": len(names), "seconds": time.time() - t}
        print("%-28s visible on %2d of %d scenes, detected %2d, %.0f s" % (m, visible, len(names), detected, time.time() - t))
    visible = [c for c in cells if c["visible"]]
    detected = [c for c in visible if c["detected"]]
    errors = [c for c in cells if c["visible"] is None]
    report["sensitivity"] = {
        "renderers_beside_mutant": BESIDE_MUTANT, "visible": len(visible), "detected": len(detected),
        "rate": len(detected) / len(visible) if visible else None, "per_mutant": per_mutant,
        "misses": [{k: c[k] for k in ("mutant", "scene", "pass", "attribution", "cause", "fraction_over_16", "max_16bit")}
                   for c in visible if not c["detected"]],
        "no_render": [{k: c[k] for k in ("mutant", "scene", "attribution")} for c in errors],
        # Visible faults the case caught but whose attribution does not say
        # "<mutant> deviates" (it names the mutant among failing pairs).
        "detected_not_singled_out": [{k: c[k] for k in ("mutant", "scene", "attribution")}
                                     for c in detected if not c["deviates"]]}
    report["cells"] = cells
    report["seconds"] = time.time() - start
    if visible:
        print("sensitivity: %d of %d visible (mutant, scene) cases detected (%.1f%%)"
              % (len(detected), len(visible), 100.0 * len(detected) / len(visible)))
    for c in report["sensitivity"]["misses"]:
        print("  miss: %s on %s: %s: %s (%.2f%% over 16/65535, max %.0f/65535)"
              % (c["mutant"], c["scene"], c["cause"], c["attribution"], 100 * c["fraction_over_16"], c["max_16bit"]))
    for c in errors:
        print("  no render: %s on %s: %s" % (c["mutant"], c["scene"], c["attribution"]))
    print("run time: %.0f s" % report["seconds"])
    with open(os.path.join(out, "mutation.json"), "w") as f:
        json.dump(report, f, indent=1)
    with open(os.path.join(out, "mutation.md"), "w") as f:
        f.write(markdown(report))
    print("wrote %s and %s" % (os.path.join(out, "mutation.json"), os.path.join(out, "mutation.md")))

    status = 0
    if errors:
        print("run.py: %d (mutant, scene) cases have no mutant render" % len(errors))
        status = 1
    if args.assert_rates:
        spec_rate = report.get("specificity", {}).get("rate")
        sens_rate = report["sensitivity"]["rate"]
        if spec_rate is None or spec_rate < REQUIRED_RATE or sens_rate is None or sens_rate < REQUIRED_RATE:
            print("run.py: the rates are below %g%%: specificity %s, sensitivity %s"
                  % (100 * REQUIRED_RATE, spec_rate, sens_rate))
            status = 1
    return status


def markdown(r):
    lines = ["# Mutation test: specificity and sensitivity of xval validate", "",
             "Command: `%s`" % r["command"], "",
             "Scenes: %d%s. Visible: %s." % (r["scenes"], " (--quick)" if r["quick"] else "", r["definition_of_visible"]), ""]
    sp = r.get("specificity")
    if sp:
        lines += ["## Specificity", "",
                  "%d of %d scenes pass with %s and no declared tolerance: **%.1f%%**%s."
                  % (sp["passed"], sp["scenes"], ", ".join(sp["renderers"]), 100 * sp["rate"],
                     "" if r["report_only"] else " (%.0f s)" % sp["seconds"]), ""]
        if sp["misses"]:
            lines += ["| scene | failing pairs | attribution |", "| --- | --- | --- |"]
            lines += ["| %s | %s | %s |" % (m["scene"], ", ".join(m["failing_pairs"]), m["attribution"]) for m in sp["misses"]]
            lines.append("")
    se = r["sensitivity"]
    lines += ["## Sensitivity", ""]
    if se["rate"] is not None:
        lines += ["%d of %d visible (mutant, scene) faults fail their case with an attribution naming the mutant: "
                  "**%.1f%%** (validated with %s and the mutant)." % (se["detected"], se["visible"], 100 * se["rate"],
                                                                        ", ".join(se["renderers_beside_mutant"])), ""]
    lines += ["| mutant | visible on | detected |", "| --- | --- | --- |"]
    lines += ["| %s | %d | %d |" % (m, p["visible"], p["detected"]) for m, p in se["per_mutant"].items()]
    lines.append("")
    if se["misses"]:
        lines += ["### Misses, by cause", ""]
        causes = sorted({c["cause"] for c in se["misses"]})
        for cause in causes:
            group = [c for c in se["misses"] if c["cause"] == cause]
            lines += ["#### %s: %d" % (cause, len(group)), "",
                      "| mutant | scene | attribution | over 16/65535 | max /65535 |", "| --- | --- | --- | --- | --- |"]
            lines += ["| %s | %s | %s | %.2f%% | %.0f |" % (c["mutant"], c["scene"], c["attribution"],
                                                          100 * c["fraction_over_16"], c["max_16bit"]) for c in group]
            lines.append("")
    if se["no_render"]:
        lines += ["### No mutant render", ""] + ["* %s on %s: %s" % (c["mutant"], c["scene"], c["attribution"])
                                                  for c in se["no_render"]] + [""]
    if not r["report_only"]:
        lines += ["Run time: %.0f s." % r["seconds"], ""]
    return "\n".join(lines)


if __name__ == "__main__":
    sys.exit(main())
