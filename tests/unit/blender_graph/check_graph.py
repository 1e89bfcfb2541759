"""Evaluates the Blender harness's shader-node graph numerically and
compares it with the reference shader (Shader<double>).

    python3 check_graph.py RENDER_GLTF_PY CASES_JSON

CASES_JSON is written by xval_blender_graph_samples: per case a glTF export
and sample points with the reference colour. For each case this runs the
real node-building code of RENDER_GLTF_PY (mesh_attributes,
build_model_material) against the numeric stand-in bpy.py next to this
file, on the export's own `xval_shading` extras and buffers, and evaluates
the graph at every sample:
  phong    attribute xval_normal = the sample's normal (and the script's
           per-corner NORMAL array must hold the mesh's vertex normals);
  flat     attribute xval_face_normal = the script's face array at the
           sample's triangle (which must be the reference's face normal);
  gouraud  attribute xval_gouraud = the script's corner colours blended
           with the sample's barycentrics.
Geometry > Position is the sample point in Blender's frame (the importer's
(x, y, z) -> (x, -z, y)). Exits 1 with every failing sample (case, point,
expected, got) when any differs by more than the case's tolerance, 2 on
bad input.
"""

import importlib.util
import json
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bpy  # noqa: E402  (the stand-in)


def importer_to_blender(v):
    """Blender's glTF importer: (x, y, z) -> (x, -z, y)."""
    return (v[0], -v[2], v[1])


def load_script(path):
    spec = importlib.util.spec_from_file_location("render_gltf", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def check_case(script, case, failures):
    data = script.GltfData(case["gltf"])
    k = json.loads(data.doc["scenes"][0]["extras"]["xval_shading"])
    prim = data.primitive("xval_mesh_0")
    attrs, corners = script.mesh_attributes(data, prim, k["shading"])
    tree = bpy.NodeTree()
    script.build_model_material(tree, k, object() if k["texture_filter"] is not None else None)
    tol = case["tolerance"]
    worst = 0.0

    def fail(sample, what):
        failures.append("%s, triangle %d, P %s: %s" % (
            case["name"], sample["triangle"], sample.get("position"), what))

    for s in case["samples"]:
        t, b = s["triangle"], s["bary"]
        at = {}
        if k["shading"] == "phong":
            corner = attrs["xval_normal"][1]
            for j in range(3):
                got = tuple(corner[9 * t + 3 * j:9 * t + 3 * j + 3])
                if got != tuple(s["corner_normals"][j]):
                    fail(s, "corner %d normal %s, the mesh's is %s" % (j, got, s["corner_normals"][j]))
            at["xval_normal"] = tuple(s["normal"])
        elif k["shading"] == "flat":
            faces = attrs["xval_face_normal"][1]
            got = tuple(faces[3 * t:3 * t + 3])
            want = s["face_normal"]
            if any(abs(got[i] - want[i]) > 1e-7 for i in range(3)):
                fail(s, "face normal %s, the reference renderer's is %s" % (got, want))
            at["xval_face_normal"] = got
        else:
            col = attrs["xval_gouraud"][1]
            at["xval_gouraud"] = tuple(
                sum(b[j] * col[9 * t + 3 * j + i] for j in range(3)) for i in range(3))
        pos = importer_to_blender(s["position"]) if "position" in s else (0.0, 0.0, 0.0)
        ctx = bpy.Context(pos, at, tuple(s["colour"]) if "colour" in s else None)
        got = bpy.evaluate(tree, ctx)
        want = s["expected"]
        err = max(abs(got[i] - want[i]) / max(1.0, abs(want[i])) for i in range(3))
        worst = max(worst, err)
        if not err <= tol:
            fail(s, "graph %s, reference %s (error %.3g > %.3g%s)" % (
                got, want, err, tol, ", a point exactly on a spot cone" if s["boundary"] else ""))
    return worst, len(case["samples"])


def unknown_model_refused(script, case, failures):
    """A model the harness does not know stops it with an error (fail():
    SystemExit 3), never falls through to another model's graph."""
    k = json.loads(script.GltfData(case["gltf"]).doc["scenes"][0]["extras"]["xval_shading"])
    k["model"] = "no_such_model"
    try:
        script.build_model_material(bpy.NodeTree(), k, object() if k["texture_filter"] is not None else None)
    except SystemExit as e:
        if e.code != 3:
            failures.append("unknown model: exit %s, expected 3" % e.code)
        return
    failures.append("unknown model: a node graph was built for model \"no_such_model\"")


def main():
    if len(sys.argv) != 3:
        print("usage: check_graph.py RENDER_GLTF_PY CASES_JSON", file=sys.stderr)
        return 2
    script = load_script(sys.argv[1])
    with open(sys.argv[2], "r", encoding="utf-8") as f:
        cases = json.load(f)["cases"]
    if not cases:
        print("check_graph.py: no cases in " + sys.argv[2], file=sys.stderr)
        return 2
    failures = []
    worst, samples, boundary = {}, 0, 0
    for case in cases:
        shading = json.loads(script.GltfData(case["gltf"]).doc["scenes"][0]["extras"]["xval_shading"])["shading"]
        w, n = check_case(script, case, failures)
        worst[shading] = max(worst.get(shading, 0.0), w)
        samples += n
        boundary += case["boundary_samples"]
    print("%d cases, %d samples (%d exactly on a spot cone); largest relative error by shading: %s"
          % (len(cases), samples, boundary, ", ".join("%s %.3g" % kv for kv in sorted(worst.items()))))
    unknown_model_refused(script, cases[0], failures)
    if failures:
        print("%d samples disagree with the reference shader:" % len(failures))
        for msg in failures[:40]:
            print("  " + msg)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
