"""The Blender-import check (blender/model_import.h): Blender 3.4 imports each
object's ORIGINAL model file with its own importer, and Cycles renders, at
each pixel centre, the hit mask, the depth, the uv and the object index.

    blender -b --factory-startup -P import_model.py -- --job JOB.json

JOB.json (written by the C++ side, read here with json.load: nothing of it
is evaluated or formatted into code):
  {"out": absolute .exr path, "width": W, "height": H,
   "camera": {"matrix_world": 4 rows of 4 (Blender's frame), "fov_y_deg": a},
   "objects": [{"path": absolute model file, "format": "obj"|"ply"|"stl"|"gltf",
                "matrix": 4 rows of 4, "pass_index": k + 1}, ...]}

Per object the file is imported by Blender's importer for its format:
  obj   bpy.ops.wm.obj_import (3.4's C++ importer), forward_axis Y, up_axis Z
        (no axis conversion: the file's coordinates),
  ply   bpy.ops.import_mesh.ply (no axis option: the file's coordinates),
  stl   bpy.ops.import_mesh.stl, axis_forward Y, axis_up Z, scale 1,
  gltf  bpy.ops.import_scene.gltf (.gltf and .glb; the importer itself maps
        glTF's y-up to Blender's z-up, (x, y, z) -> (x, -z, y), and applies
        the file's node transforms),
and every object it adds that has no parent is placed by
matrix_world = matrix @ matrix_world ("matrix" is the scene object's
transform taken into Blender's frame, times the inverse of what the importer
applied: blender/model_import.h). Every material is replaced by one emission
material (nothing transparent, so the first hit is what the camera sees).

Render settings: those of render_gltf.py (setup_render: 1 sample, Box filter
0.01, transparent film, no bounces; centre_samples: the sample moved onto
the pixel centre), output a multilayer EXR with the passes Combined (alpha:
hit mask), Depth (Z), UV and IndexOB (the object's pass_index).
"""

import argparse
import json
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import render_gltf  # noqa: E402  (the render settings and the pixel-centre shift)


def fail(msg):
    print("xval import_model.py: error: " + msg, file=sys.stderr)
    sys.exit(3)


def matrix_of(rows, what):
    import mathutils
    if (not isinstance(rows, list) or len(rows) != 4 or
            any(not isinstance(r, list) or len(r) != 4 for r in rows)):
        fail("%s: expected 4 rows of 4 numbers" % what)
    return mathutils.Matrix([[float(x) for x in r] for r in rows])


def import_file(path, fmt):
    if fmt == "obj":
        result = bpy.ops.wm.obj_import(filepath=path, forward_axis="Y", up_axis="Z",
                                       global_scale=1.0, clamp_size=0.0)
    elif fmt == "ply":
        result = bpy.ops.import_mesh.ply(filepath=path)
    elif fmt == "stl":
        result = bpy.ops.import_mesh.stl(filepath=path, axis_forward="Y", axis_up="Z",
                                         global_scale=1.0, use_scene_unit=False)
    elif fmt == "gltf":
        result = bpy.ops.import_scene.gltf(filepath=path)
    else:
        fail("format %r: no Blender importer in this check" % (fmt,))
    if "FINISHED" not in result:
        fail("Blender's %s importer failed on %s" % (fmt, path))


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="import_model.py")
    p.add_argument("--job", required=True)
    args = p.parse_args(argv)
    with open(args.job, "r", encoding="utf-8") as f:
        job = json.load(f)
    render_gltf.patch_numpy()  # the 3.4 glTF importer uses numpy.bool (gone in numpy 1.24)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.world = None
    emission = bpy.data.materials.new("xval_import_emission")
    emission.use_nodes = True
    nt = emission.node_tree
    nt.nodes.clear()
    em = nt.nodes.new("ShaderNodeEmission")
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    nt.links.new(em.outputs[0], out.inputs["Surface"])

    for k, o in enumerate(job["objects"]):
        before = set(bpy.data.objects)
        import_file(str(o["path"]), str(o["format"]))
        added = [x for x in bpy.data.objects if x not in before]
        meshes = [x for x in added if x.type == "MESH"]
        if not meshes:
            fail("object %d: Blender's importer made no mesh of %s" % (k, o["path"]))
        m = matrix_of(o["matrix"], "objects[%d].matrix" % k)
        bpy.context.view_layer.update()
        for x in added:
            if x.parent is None:
                x.matrix_world = m @ x.matrix_world
        for x in added:
            if x.type == "CAMERA" or x.type == "LIGHT":
                x.hide_render = True
        for x in meshes:
            x.pass_index = int(o["pass_index"])
            x.data.materials.clear()
            x.data.materials.append(emission)
            for poly in x.data.polygons:
                poly.material_index = 0
            x.modifiers.clear()

    cam_data = bpy.data.cameras.new("xval_camera")
    cam = bpy.data.objects.new("xval_camera", cam_data)
    scene.collection.objects.link(cam)
    c = job["camera"]
    cam.matrix_world = matrix_of(c["matrix_world"], "camera.matrix_world")
    cam_data.type = "PERSP"
    cam_data.sensor_fit = "VERTICAL"
    cam_data.lens_unit = "FOV"
    import math
    cam_data.angle_y = math.radians(float(c["fov_y_deg"]))
    cam_data.clip_start = float(c["clip_start"])
    cam_data.clip_end = float(c["clip_end"])
    scene.camera = cam
    width, height = int(job["width"]), int(job["height"])
    if width < 1 or height < 1:
        fail("resolution %dx%d" % (width, height))
    render_gltf.centre_samples(cam, width, height)
    render_gltf.setup_render(scene, width, height, str(job["out"]), True)
    layer = bpy.context.view_layer
    layer.use_pass_z = True
    layer.use_pass_uv = True
    layer.use_pass_object_index = True
    bpy.ops.render.render(write_still=True)


if __name__ == "__main__":
    try:
        main()
    except SystemExit:
        raise
    except Exception as e:  # report, and make Blender exit non-zero
        import traceback
        traceback.print_exc()
        fail("%s: %s" % (type(e).__name__, e))
