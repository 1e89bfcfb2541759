"""Where Cycles puts its one sample, with the harness's own render settings
and sample-position shift (exporters/blender/render_gltf.py), at the sizes
the harness renders when supersampling (64 x 64 at spp 1, 16 and 256:
64, 256 and 1024 pixels a side), and at a landscape and a portrait size
(96 x 64, 64 x 96: the shift's unit is the side along the sensor fit).

    blender -b --factory-startup -noaudio -P cycles_sample_offset.py -- RENDER_GLTF_PY WORK_DIR

An orthographic camera looks down at a plane whose emission is its world
position, so each pixel's colour says where its sample landed (ortho_scale
2 with the VERTICAL fit: y in [-1, 1] over H pixels, x in [-W/H, W/H]
over W):
    offset_x = (x H / W + 1) / 2 * W - (i + 0.5)
    offset_y = (y + 1) / 2 * H - (j + 0.5)
(Blender's rows run bottom-up, as its y). Fails (exit 1)
unless, with the harness's shift, every pixel's offset is within 1e-4 px,
and, without it, the offset is the constant the harness corrects
(SAMPLE_OFFSET_PX within 1e-4 px): the control that shows the measurement
sees an offset of that size.
"""
import importlib.util
import os
import sys

import bpy

argv = sys.argv[sys.argv.index("--") + 1:]
spec = importlib.util.spec_from_file_location("render_gltf", argv[0])
harness = importlib.util.module_from_spec(spec)
spec.loader.exec_module(harness)
work = argv[1]
os.makedirs(work, exist_ok=True)

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
bpy.ops.mesh.primitive_plane_add(size=4.0)
plane = bpy.context.object
mat = bpy.data.materials.new("position")
mat.use_nodes = True
nt = mat.node_tree
nt.nodes.clear()
geo = nt.nodes.new("ShaderNodeNewGeometry")
em = nt.nodes.new("ShaderNodeEmission")
out = nt.nodes.new("ShaderNodeOutputMaterial")
nt.links.new(geo.outputs["Position"], em.inputs["Color"])
nt.links.new(em.outputs[0], out.inputs["Surface"])
plane.data.materials.append(mat)
cd = bpy.data.cameras.new("ortho")
cd.type = "ORTHO"
cd.ortho_scale = 2.0
cd.sensor_fit = "VERTICAL"
cam = bpy.data.objects.new("ortho", cd)
scene.collection.objects.link(cam)
cam.location = (0.0, 0.0, 1.0)
scene.camera = cam


def offsets(W, H, shifted):
    path = os.path.join(work, "offset_%dx%d_%s.exr" % (W, H, "shifted" if shifted else "plain"))
    harness.setup_render(scene, W, H, path, False)
    if shifted:
        harness.centre_samples(cam, W, H)
    else:
        cd.shift_x = cd.shift_y = 0.0
    bpy.ops.render.render(write_still=True)
    px = bpy.data.images.load(path).pixels[:]
    dx, dy = [], []
    for j in range(H):
        for i in range(W):
            k = 4 * (j * W + i)
            dx.append((px[k] * H / W + 1.0) / 2.0 * W - (i + 0.5))
            dy.append((px[k + 1] + 1.0) / 2.0 * H - (j + 0.5))
    return dx, dy


bad = []
for W, H in ((64, 64), (256, 256), (1024, 1024), (96, 64), (64, 96)):
    R = "%dx%d" % (W, H)
    dx, dy = offsets(W, H, True)
    worst = max(max(map(abs, dx)), max(map(abs, dy)))
    print("xval: %s px, with the harness's shift: largest offset %.3g px" % (R, worst))
    if worst > 1e-4:
        bad.append("%s px: offset %.3g px with the shift" % (R, worst))
    dx, dy = offsets(W, H, False)
    spread = max(max(abs(d - harness.SAMPLE_OFFSET_PX) for d in dx), max(abs(d - harness.SAMPLE_OFFSET_PX) for d in dy))
    print("xval: %s px, without it: offset %.6g px (mean), within %.3g px of SAMPLE_OFFSET_PX" %
          (R, sum(dx) / len(dx), spread))
    if spread > 1e-4:
        bad.append("%s px: uncorrected offset not SAMPLE_OFFSET_PX (off by %.3g px)" % (R, spread))
if bad:
    print("xval: error: " + "; ".join(bad), file=sys.stderr)
    sys.exit(1)
print("xval: the harness centres Cycles' sample at every size")
