# Writes Blender's own Suzanne (bpy.ops.mesh.primitive_monkey_add, with its
# uv map) as OBJ and as glTF 2.0 with Blender 3.4's own exporters, for the
# reference scenes mesh_suzanne_obj_untextured and mesh_suzanne_gltf_untextured
# (and the textured scenes of tests/cross, mesh_suzanne_obj and _gltf):
#
#   blender -b --factory-startup --python-exit-code 1 -P scripts/make-suzanne.py -- OUT_DIR
#
# writes OUT_DIR/Suzanne.obj (no .mtl: materials off) and OUT_DIR/Suzanne.gltf
# with its .bin. The monkey is smooth-shaded (vertex normals exported) and
# triangulated by the exporters; nothing else is in the scene. The files
# in reference/models were made by this script (reference/models/README.md).
import os
import sys

import bpy
import numpy

if not hasattr(numpy, "bool"):  # numpy 1.24 removed the alias the 3.4 glTF add-on uses
    numpy.bool = bool

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
if len(argv) != 1:
    sys.exit("usage: blender -b --factory-startup -P scripts/make-suzanne.py -- OUT_DIR")
out = os.path.abspath(argv[0])
os.makedirs(out, exist_ok=True)

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.mesh.primitive_monkey_add(size=2.0, calc_uvs=True, location=(0, 0, 0))
bpy.ops.object.shade_smooth()
obj = bpy.context.active_object
obj.name = obj.data.name = "Suzanne"

bpy.ops.wm.obj_export(filepath=os.path.join(out, "Suzanne.obj"), export_selected_objects=False,
                      export_uv=True, export_normals=True, export_materials=False,
                      export_triangulated_mesh=True, forward_axis="NEGATIVE_Z", up_axis="Y")
bpy.ops.export_scene.gltf(filepath=os.path.join(out, "Suzanne.gltf"), export_format="GLTF_SEPARATE",
                          export_materials="NONE", export_normals=True, export_texcoords=True,
                          export_yup=True, export_apply=True)
print("make-suzanne: wrote", os.path.join(out, "Suzanne.obj"), "and", os.path.join(out, "Suzanne.gltf"))
