"""Render an xval glTF export in Blender 3.4 (Cycles) with the scene's
lighting model evaluated as shader-node math.

    blender -b --factory-startup -P render_gltf.py -- \
        --gltf DIR/scene.gltf --out OUT.exr [--mode model|native-lambert]

mode model (default): every mesh gets an Emission shader (strength 1) whose
colour is the model of docs/models.md built from Math / Vector Math nodes:
  P = Geometry > Position, V = Geometry > Incoming,
  N = the glTF NORMAL accessor copied into a float corner attribute
      (`xval_normal`) in index order, normalised (the importer's custom
      split normals are compressed, up to 0.034 degrees off); flat shading
      reads a face attribute (`xval_face_normal`) with the triangle's normal
      oriented to agree with its vertex normals, as the reference renderer;
  C = the texture through an Image Texture node (Non-Color: stored values,
      Closest or Linear as the glTF sampler, Repeat), or the base colour;
  Gouraud reads the `_XVAL_GOURAUD` vertex colours of the export.
V is normalize(eye - P) from the scene's camera position (Geometry >
Incoming is up to 4.3e-6 off, which pow(R.V, 55) turns into ~15/65535).
The render settings make Cycles evaluate that exactly once per pixel
centre: 1 sample, no adaptive sampling, no denoising, 0 bounces, Box filter
of width 0.01, transparent film (alpha = hit mask), no clamping, Standard
view transform, no dither; output 32-bit float OpenEXR, unsaturated.

mode native-lambert: Blender's own Lambert, for checking geometry, camera
and light conversion against Blender's shading: a white Diffuse BSDF lit by
the imported point light (radius 0), direct light only; writes the
diffuse-direct pass (DiffDir) as R, G, B, A.

The scene description is read as data only: json.loads of the glTF scene
extras ("xval") and of the .gltf file, numpy of the .bin buffer. Nothing
from the scene is evaluated or formatted into code.
"""

import argparse
import json
import math
import os
import sys

import numpy

# Blender 3.4's glTF importer uses numpy.bool, removed in numpy 1.24.
if not hasattr(numpy, "bool"):
    numpy.bool = bool

import bpy  # noqa: E402


def fail(msg):
    print("xval render_gltf.py: error: " + msg, file=sys.stderr)
    sys.exit(3)


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="render_gltf.py")
    p.add_argument("--gltf", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--mode", choices=["model", "native-lambert"], default="model")
    return p.parse_args(argv)


def to_blender(v):
    """glTF / xval world (x, y, z), +y up -> Blender (x, -z, y), +z up."""
    return (float(v[0]), -float(v[2]), float(v[1]))


# ---------------------------------------------------------------- glTF data
class GltfData:
    """Reads accessors of the exported .gltf/.bin with numpy."""

    def __init__(self, path):
        with open(path, "r", encoding="utf-8") as f:
            self.doc = json.load(f)
        folder = os.path.dirname(os.path.abspath(path))
        self.buffers = []
        for b in self.doc["buffers"]:
            uri = b["uri"]
            if "/" in uri or "\\" in uri or uri.startswith("."):
                fail("buffer uri %r leaves the export folder" % uri)
            with open(os.path.join(folder, uri), "rb") as f:
                self.buffers.append(f.read())

    def accessor(self, index):
        a = self.doc["accessors"][index]
        v = self.doc["bufferViews"][a["bufferView"]]
        dtype = {5126: numpy.float32, 5125: numpy.uint32}[a["componentType"]]
        width = {"SCALAR": 1, "VEC2": 2, "VEC3": 3}[a["type"]]
        start = v.get("byteOffset", 0) + a.get("byteOffset", 0)
        arr = numpy.frombuffer(self.buffers[v["buffer"]], dtype=dtype,
                               count=a["count"] * width, offset=start)
        return arr.reshape(a["count"], width) if width > 1 else arr

    def primitive(self, mesh_name):
        for m in self.doc["meshes"]:
            if m.get("name") == mesh_name:
                return m["primitives"][0]
        fail("mesh %r not in the glTF" % mesh_name)


# ------------------------------------------------------------ node builder
class Nodes:
    """Small helpers over a shader node tree; every value may be a number,
    a 3-tuple or an output socket."""

    def __init__(self, tree):
        self.nodes = tree.nodes
        self.links = tree.links

    def _set(self, sock, v):
        if isinstance(v, bpy.types.NodeSocket):
            self.links.new(v, sock)
        else:
            sock.default_value = v

    def math(self, op, a, b=0.0, clamp=False):
        n = self.nodes.new("ShaderNodeMath")
        n.operation = op
        n.use_clamp = clamp
        self._set(n.inputs[0], a)
        self._set(n.inputs[1], b)
        return n.outputs[0]

    def vmath(self, op, a, b=(0.0, 0.0, 0.0), scale=None):
        n = self.nodes.new("ShaderNodeVectorMath")
        n.operation = op
        self._set(n.inputs[0], a)
        self._set(n.inputs[1], b)
        if scale is not None:
            self._set(n.inputs["Scale"], scale)
        return n.outputs["Value"] if op in ("DOT_PRODUCT", "LENGTH") else n.outputs["Vector"]

    def vec(self, x, y, z):
        n = self.nodes.new("ShaderNodeCombineXYZ")
        for i, c in enumerate((x, y, z)):
            self._set(n.inputs[i], c)
        return n.outputs[0]

    def const(self, v):
        return self.vec(float(v[0]), float(v[1]), float(v[2]))

    # scalar helpers
    def add(self, a, b, clamp=False):
        return self.math("ADD", a, b, clamp)

    def mul(self, a, b):
        return self.math("MULTIPLY", a, b)

    def clamp0(self, x):
        return self.math("MAXIMUM", x, 0.0)

    def saturate(self, x):
        return self.math("ADD", x, 0.0, clamp=True)

    def scale(self, v, s):
        return self.vmath("SCALE", v, scale=s)

    def vadd(self, a, b):
        return self.vmath("ADD", a, b)

    def vmul(self, a, b):
        return self.vmath("MULTIPLY", a, b)


# ------------------------------------------------------------- the models
YIQ_Y = (0.29889531, 0.58662247, 0.11448223)  # the listing's luma row


def light_luma(c):
    s = sum(YIQ_Y)
    return sum(w / s * float(x) for w, x in zip(YIQ_Y, c))


def ambient_sum(scene):
    a = [0.0, 0.0, 0.0]
    for l in scene["lights"]:
        if l["type"] == "ambient":
            a = [a[i] + l["color"][i] for i in range(3)]
    return a


class LightTerm:
    """Per light: L, x = N.L, att and lit (None when 1), w = att lit, and
    R.V (built on first use)."""

    def __init__(self, g, light, P, N, V, NV):
        self.g, self.light, self.V, self.NV = g, light, V, NV
        t = light["type"]
        self.att = self.lit = None
        if t == "directional":
            d = light["direction"]
            n = math.sqrt(sum(c * c for c in d))
            self.L = g.const(to_blender([-c / n for c in d]))
        else:
            Lvec = g.vmath("SUBTRACT", g.const(to_blender(light["position"])), P)
            dist = g.vmath("LENGTH", Lvec)
            self.L = g.vmath("NORMALIZE", Lvec)
            a = light["attenuation"]
            if (a["constant"], a["linear"], a["quadratic"]) != (1.0, 0.0, 0.0):
                # 1 / (c + l d + q d^2)
                den = g.add(a["constant"], g.add(g.mul(a["linear"], dist),
                                                 g.mul(a["quadratic"], g.mul(dist, dist))))
                self.att = g.math("DIVIDE", 1.0, den)
            if t == "spot":
                # lit where dot(-L, axis) >= cos(cutoff); dot(L, -axis) = dot(-L, axis)
                d = light["direction"]
                n = math.sqrt(sum(c * c for c in d))
                minus_axis = to_blender([-c / n for c in d])
                self.lit = g.math("GREATER_THAN", g.vmath("DOT_PRODUCT", self.L, minus_axis),
                                  math.cos(math.radians(light["cutoff_deg"])))
        if self.att is not None and self.lit is not None:
            self.w = g.mul(self.att, self.lit)
        else:
            self.w = self.att if self.att is not None else self.lit
        self.x = g.vmath("DOT_PRODUCT", N, self.L)
        self._rv = None

    def rv(self):
        # R.V = 2 (N.L)(N.V) - L.V
        if self._rv is None:
            g = self.g
            lv = g.vmath("DOT_PRODUCT", self.L, self.V)
            self._rv = g.math("SUBTRACT", g.mul(2.0, g.mul(self.x, self.NV)), lv)
        return self._rv

    def weighted(self, value):
        return value if self.w is None else self.g.mul(self.w, value)


def forsyth(g, m, x):
    t = m["type"]
    if t == "lambert":
        return g.scale(m["c0"], g.clamp0(x))
    if t == "wrap_around":
        f = m["factor"]
        return g.scale(m["c0"], g.math("DIVIDE", g.clamp0(g.add(x, f)), 1.0 + f))
    if t == "hemispherical":
        c0, c2 = m["c0"], m["c2"]
        diff = tuple(c0[i] - c2[i] for i in range(3))
        return g.vadd(tuple(c2), g.scale(diff, g.mul(g.add(x, 1.0), 0.5)))
    neg = g.clamp0(g.mul(x, -1.0))
    out = g.vadd(g.scale(m["c0"], g.clamp0(x)), g.scale(m["c2"], neg))
    if t == "trilight":
        out = g.vadd(out, g.scale(m["c1"], g.math("SUBTRACT", 1.0, g.math("ABSOLUTE", x))))
    return out


def model_colour(g, scene, P, N, V, C):
    m = scene["material"]["model"]
    A = ambient_sum(scene)
    NV = g.vmath("DOT_PRODUCT", N, V)
    lights = [LightTerm(g, l, P, N, V, NV) for l in scene["lights"] if l["type"] != "ambient"]
    t = m["type"]
    if t == "classic_phong":
        ka, kd, ks, n = m["ka"], m["kd"], m["ks"], m["shininess"]
        if m["variant"] == "course":
            acc = tuple(ka * a for a in A)
            for lt in lights:
                # att (ka + [lit] (kd clamp(N.L) + ks clamp(R.V)^n)): outside a
                # spot's cone the per-light ambient term remains.
                term = g.mul(kd, g.clamp0(lt.x))
                if ks != 0.0:
                    term = g.add(term, g.mul(ks, g.math("POWER", g.clamp0(lt.rv()), n)))
                scalar = g.add(ka, term if lt.lit is None else g.mul(lt.lit, term))
                if lt.att is not None:
                    scalar = g.mul(lt.att, scalar)
                acc = g.vadd(acc, g.scale(lt.light["color"], scalar))
            return g.vmul(C, acc)
        diff = (0.0, 0.0, 0.0)
        spec = (0.0, 0.0, 0.0)
        for lt in lights:
            diff = g.vadd(diff, g.scale(lt.light["color"], lt.weighted(g.clamp0(lt.x))))
            if ks != 0.0:
                s = lt.weighted(g.math("POWER", g.clamp0(lt.rv()), n))
                spec = g.vadd(spec, g.scale(lt.light["color"], s))
        base = g.vadd(tuple(ka * a for a in A), g.scale(diff, kd))
        out = g.vmul(C, base)
        return g.vadd(out, g.scale(spec, ks)) if ks != 0.0 else out
    if t == "yiq_luma":
        kd, ks, n, off = m["kd"], m["ks"], m["shininess"], m["luma_offset"]
        dsum, ssum = 0.0, 0.0
        for lt in lights:
            y = light_luma(lt.light["color"])
            dsum = g.add(dsum, lt.weighted(g.mul(y, g.saturate(lt.x))))
            if ks != 0.0:
                ssum = g.add(ssum, lt.weighted(g.mul(y, g.math("POWER", g.saturate(lt.rv()), n))))
        dl = g.add(light_luma(A), g.mul(kd, dsum), clamp=True)
        Y = g.vmath("DOT_PRODUCT", C, YIQ_Y)
        dy = g.add(g.mul(Y, g.math("SUBTRACT", dl, 1.0)), g.math("SUBTRACT", g.mul(ks, ssum), off))
        return g.vadd(C, g.vec(dy, dy, dy))
    acc = tuple(A)
    for lt in lights:
        term = g.vmul(lt.light["color"], forsyth(g, m, lt.x))
        acc = g.vadd(acc, term if lt.w is None else g.scale(term, lt.w))
    return g.vmul(C, acc)


# ------------------------------------------------------------ scene setup
# Cycles places its single sample (Box filter of width 0.01) at a constant
# offset from the pixel centre: +0.000488758 px right and up, the same for
# every pixel, resolution, seed and sampling pattern (measured by rendering
# an orthographic plane whose emission is its position). The camera shift
# below moves it back to the centre (residual < 2e-6 px); without it,
# sharp texture edges differ by up to ~3000/65535.
SAMPLE_OFFSET_PX = 0.000488758


def centre_samples(camera, width, height):
    camera.data.shift_x = -SAMPLE_OFFSET_PX / max(width, height)
    camera.data.shift_y = -SAMPLE_OFFSET_PX / max(width, height)


def setup_render(scene, width, height, out, multilayer):
    r = scene.render
    r.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.samples = 1
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.max_bounces = 0
    c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = 0
    c.volume_bounces = c.transparent_max_bounces = 0
    c.pixel_filter_type = "BOX"
    c.filter_width = 0.01
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.seed = 0
    c.light_sampling_threshold = 0.0  # no stochastic culling of weak lights
    r.film_transparent = True
    r.resolution_x, r.resolution_y = width, height
    r.resolution_percentage = 100
    r.pixel_aspect_x = r.pixel_aspect_y = 1.0
    r.dither_intensity = 0.0
    r.use_compositing = False
    r.use_sequencer = False
    v = scene.view_settings
    v.view_transform = "Standard"
    v.look = "None"
    v.exposure = 0.0
    v.gamma = 1.0
    s = r.image_settings
    s.file_format = "OPEN_EXR_MULTILAYER" if multilayer else "OPEN_EXR"
    s.color_depth = "32"
    s.color_mode = "RGBA"
    s.exr_codec = "ZIP"
    r.filepath = out
    r.use_file_extension = False


def main():
    args = parse_args()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    if "FINISHED" not in bpy.ops.import_scene.gltf(filepath=args.gltf, convert_lighting_mode="RAW"):
        fail("the glTF importer failed on " + args.gltf)
    scene = bpy.context.scene
    if "xval" not in scene.keys():
        fail("no xval scene description in the glTF scene extras")
    desc = json.loads(scene["xval"])
    data = GltfData(args.gltf)
    scene.world = None
    cams = [o for o in scene.objects if o.type == "CAMERA"]
    if len(cams) != 1:
        fail("expected one camera, found %d" % len(cams))
    scene.camera = cams[0]
    cams[0].data.sensor_fit = "VERTICAL"
    centre_samples(cams[0], desc["camera"]["width"], desc["camera"]["height"])

    meshes = [o for o in scene.objects if o.type == "MESH"]
    if args.mode == "native-lambert":
        for o in scene.objects:
            if o.type == "LIGHT":
                o.data.shadow_soft_size = 0.0  # a point, not the importer's 0.25 sphere
                o.data.cycles.cast_shadow = False  # local illumination, as the reference
        mat = bpy.data.materials.new("xval_native_lambert")
        mat.use_nodes = True
        nt = mat.node_tree
        nt.nodes.clear()
        bsdf = nt.nodes.new("ShaderNodeBsdfDiffuse")
        bsdf.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
        bsdf.inputs["Roughness"].default_value = 0.0
        out = nt.nodes.new("ShaderNodeOutputMaterial")
        nt.links.new(bsdf.outputs[0], out.inputs["Surface"])
        for o in meshes:
            o.data.materials.clear()
            o.data.materials.append(mat)
        bpy.context.view_layer.use_pass_diffuse_direct = True
        setup_render(scene, desc["camera"]["width"], desc["camera"]["height"], args.out, True)
        bpy.ops.render.render(write_still=True)
        return

    # Model mode: lights are evaluated in the nodes; Blender's lights go.
    for o in list(scene.objects):
        if o.type == "LIGHT":
            bpy.data.objects.remove(o, do_unlink=True)
    shading = desc["shading"]
    tex = desc["material"].get("texture")
    image = None
    if tex is not None:
        folder = os.path.dirname(os.path.abspath(args.gltf))
        image = bpy.data.images.load(os.path.join(folder, "texture.png"), check_existing=True)
        image.colorspace_settings.name = "Non-Color"
        image.alpha_mode = "NONE"

    for o in meshes:
        me = o.data
        prim = data.primitive(me.name)
        idx = data.accessor(prim["indices"])
        if len(me.loops) != len(idx):
            fail("mesh %s: %d corners in Blender, %d indices in the glTF" % (me.name, len(me.loops), len(idx)))
        normals = data.accessor(prim["attributes"]["NORMAL"]).astype(numpy.float64)
        corner = normals[idx]
        conv = numpy.stack([corner[:, 0], -corner[:, 2], corner[:, 1]], axis=1).astype(numpy.float32)
        attr = me.attributes.new("xval_normal", "FLOAT_VECTOR", "CORNER")
        attr.data.foreach_set("vector", conv.ravel())
        if shading == "flat":
            pos = data.accessor(prim["attributes"]["POSITION"]).astype(numpy.float64)
            tri = idx.reshape(-1, 3)
            g = numpy.cross(pos[tri[:, 1]] - pos[tri[:, 0]], pos[tri[:, 2]] - pos[tri[:, 0]])
            ln = numpy.linalg.norm(g, axis=1)
            g = numpy.where(ln[:, None] > 0, g / numpy.where(ln > 0, ln, 1.0)[:, None], 0.0)
            nsum = normals[tri[:, 0]] + normals[tri[:, 1]] + normals[tri[:, 2]]
            g = numpy.where((numpy.sum(g * nsum, axis=1) < 0)[:, None], -g, g)
            if len(me.polygons) != len(tri):
                fail("mesh %s: %d faces in Blender, %d triangles in the glTF" % (me.name, len(me.polygons), len(tri)))
            fconv = numpy.stack([g[:, 0], -g[:, 2], g[:, 1]], axis=1).astype(numpy.float32)
            fa = me.attributes.new("xval_face_normal", "FLOAT_VECTOR", "FACE")
            fa.data.foreach_set("vector", fconv.ravel())
        if shading == "gouraud":
            cols = data.accessor(prim["attributes"]["_XVAL_GOURAUD"]).astype(numpy.float32)[idx]
            ga = me.attributes.new("xval_gouraud", "FLOAT_VECTOR", "CORNER")
            ga.data.foreach_set("vector", cols.ravel())

    mat = bpy.data.materials.new("xval_model")
    mat.use_nodes = True
    nt = mat.node_tree
    nt.nodes.clear()
    g = Nodes(nt)
    if shading == "gouraud":
        a = nt.nodes.new("ShaderNodeAttribute")
        a.attribute_type = "GEOMETRY"
        a.attribute_name = "xval_gouraud"
        colour = a.outputs["Vector"]
    else:
        geo = nt.nodes.new("ShaderNodeNewGeometry")
        P = geo.outputs["Position"]
        V = g.vmath("NORMALIZE", g.vmath("SUBTRACT", to_blender(desc["camera"]["position"]), P))
        a = nt.nodes.new("ShaderNodeAttribute")
        a.attribute_type = "GEOMETRY"
        a.attribute_name = "xval_face_normal" if shading == "flat" else "xval_normal"
        N = g.vmath("NORMALIZE", a.outputs["Vector"])
        if image is not None:
            uv = nt.nodes.new("ShaderNodeTexCoord")
            it = nt.nodes.new("ShaderNodeTexImage")
            it.image = image
            it.interpolation = "Closest" if tex["filter"] == "nearest" else "Linear"
            it.extension = "REPEAT"
            nt.links.new(uv.outputs["UV"], it.inputs["Vector"])
            C = it.outputs["Color"]
        else:
            C = g.const(desc["material"]["base_color"])
        colour = model_colour(g, desc, P, N, V, C)
    em = nt.nodes.new("ShaderNodeEmission")
    em.inputs["Strength"].default_value = 1.0
    g._set(em.inputs["Color"], colour)
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    nt.links.new(em.outputs[0], out.inputs["Surface"])
    for o in meshes:
        o.data.materials.clear()
        o.data.materials.append(mat)
    setup_render(scene, desc["camera"]["width"], desc["camera"]["height"], args.out, False)
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
