"""The normal Blender shades a mesh with is the exported one: at every
covered pixel, the N the harness's node tree computes (exporters/blender/
render_gltf.py, Cycles) equals the glTF NORMAL accessor interpolated at the
point Blender itself hit, to within BOUND.

    blender -b --factory-startup -noaudio -P blender_shading_normals.py -- RENDER_GLTF_PY SCENE_GLTF WORK_DIR

SCENE_GLTF is `xval export gltf` of a mesh scene. The harness renders the
scene twice with its model colour replaced: once by 0.5 N + 0.5 (the
normal the model would use), once by P (the world position of the hit).
For each covered pixel, the triangle nearest to P (a BVH of the imported
mesh; polygon k is glTF triangle k) gives P's barycentrics (b0, b1, b2),
and the expected normal is normalize(b0 n0 + b1 n1 + b2 n2) of the
NORMAL accessor. Comparing at Blender's own hit point takes the float32
hit position out of the check (at grazing incidence it is 1e-4 off along
the ray), so what is left is the normal data and its interpolation.
Fails (exit 1) if any pixel's N is further than BOUND (max abs component)
from it: e.g. if the node tree read Blender's custom split normals, which
the importer stores compressed (up to 0.038 degrees, 6.6e-4, off on
Suzanne), or if the corner order of the normal attribute were not the
glTF index order.
"""
import importlib.util
import os
import sys

import numpy as np

argv = sys.argv[sys.argv.index("--") + 1:]
spec = importlib.util.spec_from_file_location("render_gltf", argv[0])
harness = importlib.util.module_from_spec(spec)
spec.loader.exec_module(harness)
gltf, work = argv[1], argv[2]
os.makedirs(work, exist_ok=True)
harness.patch_numpy()

import bpy  # noqa: E402
from mathutils import Vector  # noqa: E402
from mathutils.bvhtree import BVHTree  # noqa: E402

# Measured on Suzanne (tests/cross/scenes/mesh_suzanne_gltf.json, 27,316
# covered pixels): 2.1e-6 at most; the EXR's float32 P (ulp 6e-8 at
# |P| ~ 1) times a normal turning by 0.93 over a 0.12-long triangle is of
# that order. With Geometry > Normal (the split normals) instead: 5.5e-4.
BOUND = 1e-5


def render(what):
    out = os.path.join(work, what + ".exr")
    if what == "N":
        harness.model_colour = lambda g, k, P, N, V, C: g.vadd(g.scale(N, 0.5), (0.5, 0.5, 0.5))
    else:
        harness.model_colour = lambda g, k, P, N, V, C: P
    args = argparse_args(out)
    harness.render_scene(args)
    img = bpy.data.images.load(out)
    w, h = img.size
    a = np.array(img.pixels[:], dtype=np.float64).reshape(h, w, 4)
    if not np.isfinite(a).all():
        harness.fail("%s: non-finite values in Blender's image" % out)
    return a


def argparse_args(out):
    class A:
        pass
    a = A()
    a.gltf, a.out, a.mode, a.engine = gltf, out, "model", "cycles"
    return a


Ni = render("N")
Pi = render("P")
data = harness.GltfData(gltf)
meshes = [o for o in bpy.context.scene.objects if o.type == "MESH"]
if len(meshes) != 1:
    harness.fail("expected one mesh in %s, found %d" % (gltf, len(meshes)))
me = meshes[0].data
prim = data.primitive(me.name)
idx = np.array(data.accessor(prim["indices"])[0], dtype=np.int64).reshape(-1, 3)
Pv = np.array(data.accessor(prim["attributes"]["POSITION"])[0], dtype=np.float64).reshape(-1, 3)
Nv = np.array(data.accessor(prim["attributes"]["NORMAL"])[0], dtype=np.float64).reshape(-1, 3)
if len(me.polygons) != len(idx):
    harness.fail("%d polygons in Blender, %d triangles in the glTF" % (len(me.polygons), len(idx)))
bvh = BVHTree.FromPolygons([tuple(v.co) for v in me.vertices], [tuple(p.vertices) for p in me.polygons])
to_world = np.array(meshes[0].matrix_world)
if not np.allclose(to_world, np.eye(4)):
    harness.fail("the imported mesh has a transform; this check expects the exporter's identity")

covered = np.argwhere((Ni[..., 3] > 0) & (Pi[..., 3] > 0))
if len(covered) < 1000:
    harness.fail("only %d covered pixels: the render is not of the mesh" % len(covered))
worst, where = 0.0, None
for y, x in covered:
    p = Pi[y, x, :3]  # world (glTF) coordinates; Blender's are (x, -z, y)
    _, _, face, _ = bvh.find_nearest(Vector((p[0], -p[2], p[1])))
    a, b, c = Pv[idx[face]]
    m = np.stack([b - a, c - a], 1)
    u, v = np.linalg.lstsq(m, p - a, rcond=None)[0]
    n = (1 - u - v) * Nv[idx[face, 0]] + u * Nv[idx[face, 1]] + v * Nv[idx[face, 2]]
    n /= np.linalg.norm(n)
    err = np.abs(2.0 * (Ni[y, x, :3] - 0.5) - n).max()
    if err > worst:
        worst, where = err, (x, Ni.shape[0] - 1 - y, face)
print("shading normal vs exported NORMAL at Blender's hit point: max %.3g over %d pixels (pixel %s, triangle %s); bound %g"
      % (worst, len(covered), where[:2], where[2], BOUND))
if not worst <= BOUND:
    print("FAIL: Blender's shading normal differs from the exported one by %.3g > %g" % (worst, BOUND))
    sys.exit(1)
print("PASS")
