"""Where Cycles puts its one sample, with the harness's own render settings
and sample-position shift (exporters/blender/render_gltf.py), at the sizes
the harness renders when supersampling (64 x 64 at spp 1, 16 and 256:
64, 256 and 1024 pixels a side).

    blender -b --factory-startup -noaudio -P cycles_sample_offset.py -- RENDER_GLTF_PY WORK_DIR

An orthographic camera looks down at a plane whose emission is its world
position, so each pixel's colour says where its sample landed:
    offset_x = (x + 1) / 2 * R - (i + 0.5)  (ortho_scale 2: x in [-1, 1] over R pixels)
and the same for y (Blender's rows run bottom-up, as its y). Fails (exit 1)
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


def offsets(R, shifted):
    path = os.path.join(work, "offset_%d_%s.exr" % (R, "shifted" if shifted else "plain"))
    harness.setup_render(scene, R, R, path, False)
    if shifted:
        harness.centre_samples(cam, R, R)
    else:
        cd.shift_x = cd.shift_y = 0.0
    bpy.ops.render.render(write_still=True)
    px = bpy.data.images.load(path).pixels[:]
    dx, dy = [], []
    for j in range(R):
        for i in range(R):
            k = 4 * (j * R + i)
            dx.append((px[k] + 1.0) / 2.0 * R - (i + 0.5))
            dy.append((px[k + 1] + 1.0) / 2.0 * R - (j + 0.5))
    return dx, dy


bad = []
for R in (64, 256, 1024):
    dx, dy = offsets(R, True)
    worst = max(max(map(abs, dx)), max(map(abs, dy)))
    print("xval: %d px, with the harness's shift: largest offset %.3g px" % (R, worst))
    if worst > 1e-4:
        bad.append("%d px: offset %.3g px with the shift" % (R, worst))
    dx, dy = offsets(R, False)
    spread = max(max(abs(d - harness.SAMPLE_OFFSET_PX) for d in dx), max(abs(d - harness.SAMPLE_OFFSET_PX) for d in dy))
    print("xval: %d px, without it: offset %.6g px (mean), within %.3g px of SAMPLE_OFFSET_PX" %
          (R, sum(dx) / len(dx), spread))
    if spread > 1e-4:
        bad.append("%d px: uncorrected offset not SAMPLE_OFFSET_PX (off by %.3g px)" % (R, spread))
if bad:
    print("xval: error: " + "; ".join(bad), file=sys.stderr)
    sys.exit(1)
print("xval: the harness centres Cycles' sample at every size")
