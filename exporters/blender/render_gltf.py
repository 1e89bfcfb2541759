"""Render an xval glTF export in Blender 3.4 (Cycles, or EEVEE) with the scene's
lighting model evaluated as shader-node math.

    blender -b --factory-startup -P render_gltf.py -- \
        --gltf DIR/scene.gltf --out OUT.exr [--mode model|native]
        [--engine cycles|eevee] [--diffuse-roughness R]
        [--glossy none|ggx|beckmann] [--glossy-roughness R]
        [--diffuse-colour G] [--glossy-colour G]
    blender -b --factory-startup -P render_gltf.py -- \
        --batch JOBS.json --results RESULTS.jsonl

batch (the persistent worker, blender/blender_render.h renderBlenderBatch):
JOBS.json is {"jobs": [{"gltf", "out", "log", "engine"}, ...]} (model mode);
the scenes are rendered one after the other in this one process, each
from factory settings (read_factory_settings: every datablock, the
preferences and the scene settings reset, so a scene renders as it would in
a fresh process), with Blender's stdout and stderr sent to the job's own
log. Before a job, {"start": i} is appended to RESULTS.jsonl, after it
{"done": i, "ok": bool, "error": text, "seconds": wall}, each line flushed
and synced: a process that dies leaves the index it died on as the last
"start" without its "done".

mode model (default): every mesh gets an Emission shader (strength 1) whose
colour is the model of docs/models.md built from Math / Vector Math nodes
(build_model_material). Every constant it needs (light directions, cos of
the spot cutoff, per-light luma, attenuation flags, the ambient sum and its
luma, the luma row, ...) is read from the `xval_shading` extras of the
mesh's glTF material (exporters/gltf/shading_constants.h; one node tree per
material, its texture the file named by the material's `xval_texture`);
this script derives none:
  P = Geometry > Position, taken to the scene's world frame with the
      exported `blender_to_world` rows (the shading is in world frame),
  N = the glTF NORMAL accessor copied into a float corner attribute
      (`xval_normal`) in index order, normalised (the importer's custom
      split normals are compressed, up to 0.034 degrees off), or as
      interpolated with normalize_normal false (the listing); flat shading
      reads a face attribute (`xval_face_normal`) holding the exported
      per-triangle normals, the reference renderer's own;
  C = the texture through an Image Texture node (Non-Color: stored values,
      Closest or Linear as the glTF sampler, Repeat), or the base colour;
  Gouraud reads the `_XVAL_GOURAUD` vertex colours of the export.
V is normalize(eye - P) from the exported camera position (Geometry >
Incoming is up to 4.3e-6 off, which pow(R.V, 55) turns into ~15/65535).
The node graph is checked numerically against the reference shader by
tests/unit/blender_graph (plain python3 with a numeric stand-in for bpy).
The resolution is the export's `xval_render` scene extras (width, height):
for render.spp = n^2 the exporter asks for n times the camera's resolution,
one sample through each pixel centre (the harness box-filters n x n blocks).
The render settings make Cycles evaluate that exactly once per pixel
centre: 1 sample, no adaptive sampling, no denoising, 0 bounces, Box filter
of width 0.01, transparent film (alpha = hit mask), no clamping, Standard
view transform, no dither; output 32-bit float OpenEXR, unsaturated.

engine eevee (model mode only): the same node tree rendered by EEVEE,
Blender's real-time rasteriser (headless: Blender falls back by itself to
Mesa's surfaceless EGL, no X server). What makes its output exact:
  - one sample per pixel (taa_render_samples = 1, filter size 0): EEVEE's
    one sample lies exactly on the pixel centre, so no camera shift;
  - the camera's clip range fitted to the meshes' bounds (the glTF export's
    4.2e-6 .. 4.2e9 leaves EEVEE's 24-bit depth buffer unable to resolve
    the scene: most pixels then show the wrong surface);
  - a Linear texture lookup rebuilt from four Closest lookups at the texel
    centres and the reference's bilinear weights (EEVEE's Linear mip-maps
    and, with default preferences, filters anisotropically; Mesa's
    llvmpipe filters 8-bit textures in 8-bit fixed point); anisotropic
    filtering is turned off in the preferences all the same;
  - texture filter trilinear (the paper's MIN_MAG_MIP_LINEAR) is EEVEE's
    own Linear lookup, trilinear on the GPU's mip chain, with the texture
    copied into a float32 image first (float32 on the GPU, so neither the
    lookups nor the mip-maps are 8-bit); Cycles refuses it (the C++ side,
    before anything is exported);
  - a 16-bit texture uploaded as float32, not half float (the image's
    use_half_precision off: half's 11-bit mantissa moves a 16-bit code by
    up to ~31/65535);
  - bloom, ambient occlusion, screen-space reflections, soft shadows and
    motion blur off; 64-pixel shadow maps and light probes (speed only: the
    emission has no shadows and no probes);
  - nothing asks the GPU module anything before the first render (in -b
    mode Blender 3.4 crashes when gpu.platform is queried that early).

mode native: Blender's own BSDFs (blender/native_bsdf.h chooses them): a
white Diffuse BSDF of Roughness --diffuse-roughness, plus a white Glossy
BSDF (--glossy ggx|beckmann, Roughness --glossy-roughness) unless --glossy
none, lit by the imported point light (radius 0), direct light only;
Cycles writes the diffuse- and glossy-direct passes (DiffDir, GlossDir; the
BSDFs white) to a multilayer EXR; EEVEE, whose passes do not exclude its
BSDFs' colours as Cycles' do, writes the combined image with the BSDFs'
grey colours --diffuse-colour and --glossy-colour (render_native).

The scene description is read as data only: json.loads of the glTF scene
extras ("xval", "xval_shading") and of the .gltf file, array.frombytes of
the .bin buffer. Nothing
from the scene is evaluated or formatted into code.
"""

import argparse
import array
import json
import math
import os
import sys

import bpy  # noqa: E402  (in the unit test: a numeric stand-in, tests/unit/blender_graph)
try:
    import mathutils  # Blender's; absent from the unit test's stand-in (only eevee uses it)
except ImportError:
    mathutils = None


def fail(msg):
    print("xval render_gltf.py: error: " + msg, file=sys.stderr)
    sys.exit(3)


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="render_gltf.py")
    p.add_argument("--gltf")
    p.add_argument("--out")
    p.add_argument("--mode", choices=["model", "native"], default="model")
    p.add_argument("--diffuse-roughness", type=float, default=0.0)
    p.add_argument("--glossy", choices=["none", "ggx", "beckmann"], default="none")
    p.add_argument("--glossy-roughness", type=float, default=0.0)
    p.add_argument("--diffuse-colour", type=float, default=1.0)
    p.add_argument("--glossy-colour", type=float, default=1.0)
    p.add_argument("--engine", choices=["cycles", "eevee"], default="cycles")
    p.add_argument("--batch")
    p.add_argument("--results")
    args = p.parse_args(argv)
    if args.batch is not None:
        if args.results is None or args.gltf is not None or args.out is not None:
            fail("--batch needs --results, and takes no --gltf or --out")
    elif args.gltf is None or args.out is None:
        fail("--gltf and --out are required (or --batch)")
    return args


# ---------------------------------------------------------------- glTF data
class GltfData:
    """Reads accessors of the exported .gltf/.bin (little-endian float32 and
    uint32, as the exporter writes them) into flat arrays."""

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
        """The accessor's values as a flat array ('f' or 'I') and its width."""
        a = self.doc["accessors"][index]
        v = self.doc["bufferViews"][a["bufferView"]]
        code = {5126: "f", 5125: "I"}[a["componentType"]]
        width = {"SCALAR": 1, "VEC2": 2, "VEC3": 3}[a["type"]]
        start = v.get("byteOffset", 0) + a.get("byteOffset", 0)
        out = array.array(code)
        if out.itemsize != 4 or sys.byteorder != "little":
            fail("this platform's array types are not little-endian 32-bit")
        n = a["count"] * width
        out.frombytes(self.buffers[v["buffer"]][start:start + 4 * n])
        if len(out) != n:
            fail("accessor %d: %d values in the buffer, %d expected" % (index, len(out), n))
        return out, width

    def primitive(self, mesh_name):
        for m in self.doc["meshes"]:
            if m.get("name") == mesh_name:
                return m["primitives"][0]
        fail("mesh %r not in the glTF" % mesh_name)


def per_corner(values, width, idx):
    """values[idx[i]] for every corner i, flattened (Blender's corner order is
    the glTF index order)."""
    if len(idx) and max(idx) >= len(values) // width:
        fail("index %d out of range of an accessor of %d values" % (max(idx), len(values) // width))
    out = array.array("f", bytes(4 * width * len(idx)))
    for i, v in enumerate(idx):
        out[width * i:width * i + width] = values[width * v:width * v + width]
    return out


def mesh_attributes(data, prim, shading):
    """The float attributes the model's nodes read, as
    {name: (domain, flat float32 array)}: the glTF NORMAL per corner; for
    flat shading the exported per-triangle normals (flat_normals.h, named by
    the primitive's extras); for Gouraud the exported vertex colours."""
    idx, _ = data.accessor(prim["indices"])
    normals, w = data.accessor(prim["attributes"]["NORMAL"])
    out = {"xval_normal": ("CORNER", per_corner(normals, w, idx))}
    if shading == "flat":
        faces, _ = data.accessor(prim["extras"]["xval_face_normals"])
        if len(faces) != len(idx):
            fail("%d face normals for %d triangles" % (len(faces) // 3, len(idx) // 3))
        out["xval_face_normal"] = ("FACE", faces)
    if shading == "gouraud":
        cols, w = data.accessor(prim["attributes"]["_XVAL_GOURAUD"])
        out["xval_gouraud"] = ("CORNER", per_corner(cols, w, idx))
    return out, len(idx)


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

    def at_least(self, a, b):
        """1 where a >= b, else 0: Blender's LESS_THAN is a < b (and
        GREATER_THAN a > b, 0 at equality), so 1 - LESS_THAN is exactly >=."""
        return self.math("SUBTRACT", 1.0, self.math("LESS_THAN", a, b))

    def scale(self, v, s):
        return self.vmath("SCALE", v, scale=s)

    def vadd(self, a, b):
        return self.vmath("ADD", a, b)

    def vmul(self, a, b):
        return self.vmath("MULTIPLY", a, b)


# ------------------------------------------------------------- the models
# Every constant comes from the export's `xval_shading` extras
# (exporters/gltf/shading_constants.h); nothing is derived here.
class LightTerm:
    """Per light: L, x = N.L, att and lit (None when 1), w = att lit, and
    R.V (built on first use)."""

    def __init__(self, g, light, P, N, V, NV):
        self.g, self.light, self.V, self.NV, self.N = g, light, V, NV, N
        self.att = self.lit = None
        if light["kind"] == "directional":
            self.L = g.const(light["to_light"])
        else:
            Lvec = g.vmath("SUBTRACT", g.const(light["position"]), P)
            self.L = g.vmath("NORMALIZE", Lvec)
            if light["attenuated"]:
                # 1 / (c + l d + q d^2)
                c, l, q = light["attenuation"]
                dist = g.vmath("LENGTH", Lvec)
                den = g.add(c, g.add(g.mul(l, dist), g.mul(q, g.mul(dist, dist))))
                self.att = g.math("DIVIDE", 1.0, den)
            if light["kind"] == "spot":
                # lit where dot(L, -axis) >= cos(cutoff)
                self.lit = g.at_least(g.vmath("DOT_PRODUCT", self.L, light["minus_axis"]),
                                      light["cos_cutoff"])
        if self.att is not None and self.lit is not None:
            self.w = g.mul(self.att, self.lit)
        else:
            self.w = self.att if self.att is not None else self.lit
        self.x = g.vmath("DOT_PRODUCT", N, self.L)
        self._rv = None
        self.unit_r_of = None  # N, when R is to be normalised (normalize_normal false)

    def rv(self):
        # R.V = 2 (N.L)(N.V) - L.V
        if self._rv is None:
            g = self.g
            lv = g.vmath("DOT_PRODUCT", self.L, self.V)
            self._rv = g.math("SUBTRACT", g.mul(2.0, g.mul(self.x, self.NV)), lv)
            if self.unit_r_of is not None:
                # normalize(R).V, the listing's R for a non-unit N:
                # |R|^2 = 1 + 4 (N.L)^2 (N.N - 1)
                nn = g.vmath("DOT_PRODUCT", self.unit_r_of, self.unit_r_of)
                r2 = g.add(1.0, g.mul(4.0, g.mul(g.mul(self.x, self.x), g.math("SUBTRACT", nn, 1.0))))
                self._rv = g.math("DIVIDE", self._rv, g.math("SQRT", r2))
        return self._rv

    def weighted(self, value):
        return value if self.w is None else self.g.mul(self.w, value)


# The models this harness builds, by their `model` name in the extras (the
# registry's names, renderer/shading/model/registry.h); any other name is an
# error, never another model's graph. tests/unit/lighting_models_test.cpp
# checks these lists against the registry.
PHONG_MODELS = ("classic_phong", "yiq_luma")
FORSYTH_MODELS = ("lambert", "wrap_around", "hemispherical", "bidirectional", "trilight")
MINNAERT_BLINN_OREN_NAYAR_MODELS = ("minnaert", "blinn_phong", "oren_nayar")
MICROFACET_MODELS = ("cook_torrance",)


def unknown_model(t):
    fail("lighting model %r: this harness builds no node graph for it (it knows %s)"
         % (t, ", ".join(PHONG_MODELS + FORSYTH_MODELS + MINNAERT_BLINN_OREN_NAYAR_MODELS
                              + MICROFACET_MODELS)))


def forsyth(g, k, x):
    t = k["model"]
    if t == "lambert":
        return g.scale(k["c0"], g.clamp0(x))
    if t == "wrap_around":
        return g.scale(k["c0"], g.math("DIVIDE", g.clamp0(g.add(x, k["factor"])), k["wrap_divisor"]))
    if t == "hemispherical":
        return g.vadd(k["c2"], g.scale(k["c0_minus_c2"], g.mul(g.add(x, 1.0), 0.5)))
    if t not in ("bidirectional", "trilight"):
        unknown_model(t)
    neg = g.clamp0(g.mul(x, -1.0))
    out = g.vadd(g.scale(k["c0"], g.clamp0(x)), g.scale(k["c2"], neg))
    if t == "trilight":
        out = g.vadd(out, g.scale(k["c1"], g.math("SUBTRACT", 1.0, g.math("ABSOLUTE", x))))
    return out


def minnaert_blinn_oren_nayar_colour(g, k, lights, NV, C):
    """minnaert, blinn_phong and oren_nayar (docs/models.md) as nodes."""
    t = k["model"]
    if t == "blinn_phong":
        # C (x) (ka A + kd sum att Lc clamp(N.L)) + ks sum att Lc clamp(N.H)^n,
        # H = normalize(L + V): N.H = (N.L + N.V) / |L + V|, |L + V| =
        # sqrt(2 + 2 L.V); 0 where L + V = 0 (the reference's zero H).
        ka, kd, ks, n = k["ka"], k["kd"], k["ks"], k["shininess"]
        diff = (0.0, 0.0, 0.0)
        spec = (0.0, 0.0, 0.0)
        for lt in lights:
            diff = g.vadd(diff, g.scale(lt.light["colour"], lt.weighted(g.clamp0(lt.x))))
            if k["specular"]:
                H = g.vmath("NORMALIZE", g.vadd(lt.L, lt.V))  # Blender's normalize: 0 stays 0
                nh = g.vmath("DOT_PRODUCT", H, lt.N)
                s = g.math("POWER", g.clamp0(nh), n) if n != 0.0 else 1.0
                spec = g.vadd(spec, g.scale(lt.light["colour"], lt.weighted(s)))
        out = g.vmul(C, g.vadd(tuple(k["ka_ambient"]), g.scale(diff, kd)))
        return g.vadd(out, g.scale(spec, ks)) if k["specular"] else out
    acc = (0.0, 0.0, 0.0)
    for lt in lights:
        x = lt.x
        xc = g.clamp0(x)
        lit = g.math("GREATER_THAN", x, 0.0)  # 0 where N.L <= 0
        if t == "minnaert":
            # clamp(x)^k clamp(y)^(k-1); x where k = 1; 0 where y <= 0 otherwise
            kk = k["k"]
            if kk == 1.0:
                o = xc
            else:
                seen = g.math("GREATER_THAN", NV, 0.0)
                yc = g.math("MAXIMUM", NV, 1e-30)  # keeps POWER finite where seen is 0
                o = g.mul(g.mul(g.math("POWER", xc, kk), g.math("POWER", yc, kk - 1.0)), g.mul(lit, seen))
        else:
            # s = L.V - x clamp(y); qualitative x (a + b max(s, 0) / max(x, y)),
            # cycles x (a + b t), t = s / max(x, y) where s > 0, else s
            yc = g.clamp0(NV)
            s = g.math("SUBTRACT", g.vmath("DOT_PRODUCT", lt.L, lt.V), g.mul(xc, yc))
            pos = g.math("GREATER_THAN", s, 0.0)
            m = g.math("MAXIMUM", g.math("MAXIMUM", xc, yc), 1e-30)  # > 0 where it matters (x > 0)
            tpos = g.mul(pos, g.math("DIVIDE", s, m))
            tt = g.add(tpos, g.mul(g.math("SUBTRACT", 1.0, pos), s)) if k["cycles"] else tpos
            o = g.mul(xc, g.add(k["a"], g.mul(k["b"], tt)))
        term = g.scale(lt.light["colour"], lt.weighted(o))
        acc = g.vadd(acc, term)
    return g.vmul(C, g.vadd(tuple(k["ambient"]), g.scale(acc, k["kd"])))


def cook_torrance_specular(g, k, lt, N, V, NV):
    """S = pi F D G / (4 N.V) of shading/models.h cookTorranceSpecular, 0
    unless N.L, N.V, N.H and V.H are > 0. Blender's Divide gives 0 for a
    zero divisor and its Square Root 0 for a negative argument, so the
    gated-off branches stay finite (and are multiplied by the gate's 0)."""
    nl, nv = lt.x, NV
    LV = g.vadd(lt.L, V)
    H = g.vmath("NORMALIZE", LV)
    nh = g.vmath("DOT_PRODUCT", N, H)
    # V.H = |L + V| / 2 for unit L and V, as models.h: dot(V, H) cancels to
    # noise near L = -V.
    vh = g.mul(0.5, g.vmath("LENGTH", LV))

    def sin2(X):  # |N x X|^2, without the cancellation of 1 - (N.X)^2
        c = g.vmath("CROSS_PRODUCT", N, X)
        return g.vmath("DOT_PRODUCT", c, c)

    alpha = k["roughness"]  # alpha itself (docs/models.md)
    a2 = alpha * alpha
    ggx = k["distribution"] == "ggx"
    c2 = g.mul(nh, nh)
    s2 = sin2(H)
    if ggx:
        q = g.add(g.mul(c2, a2), s2)
        D = g.math("DIVIDE", a2, g.mul(math.pi, g.mul(q, q)))
    else:
        e = g.math("EXPONENT", g.mul(-1.0, g.math("DIVIDE", s2, g.mul(c2, a2))))
        D = g.math("DIVIDE", e, g.mul(math.pi * a2, g.mul(c2, c2)))

    def g1_over_cos(x, X):
        if ggx:
            root = g.math("SQRT", g.add(g.mul(x, x), g.mul(a2, sin2(X))))
            return g.math("DIVIDE", 2.0, g.add(x, root))
        a_s = g.mul(alpha, g.math("SQRT", sin2(X)))
        a = g.math("DIVIDE", x, a_s)
        num = g.add(3.535, g.mul(2.181, a))
        den = g.mul(g.add(1.0, g.add(g.mul(2.276, a), g.mul(2.577, g.mul(a, a)))), a_s)
        flat = g.at_least(x, g.mul(1.6, a_s))  # G1 = 1
        return g.add(g.mul(flat, g.math("DIVIDE", 1.0, x)),
                     g.mul(g.math("SUBTRACT", 1.0, flat), g.math("DIVIDE", num, den)))

    if k["geometry"] == "smith":
        G = g.mul(nl, g.mul(g1_over_cos(nl, lt.L), g1_over_cos(nv, V)))
    else:
        kk = g.math("DIVIDE", g.mul(2.0, nh), g.math("MAXIMUM", vh, k["vgroove_min_vh"]))
        G = g.math("MINIMUM", g.math("DIVIDE", 1.0, nv),
                   g.math("MINIMUM", kk, g.math("DIVIDE", g.mul(kk, nl), nv)))
    S = g.mul(math.pi * 0.25, g.mul(D, G))
    if k["fresnel"] == "schlick":
        m = g.math("SUBTRACT", 1.0, vh)
        m2 = g.mul(m, m)
        f0 = k["f0"]
        S = g.mul(S, g.add(f0, g.mul(1.0 - f0, g.mul(g.mul(m2, m2), m))))
    gate = g.mul(g.mul(g.math("GREATER_THAN", nl, 0.0), g.math("GREATER_THAN", nv, 0.0)),
                 g.mul(g.math("GREATER_THAN", nh, 0.0), g.math("GREATER_THAN", vh, 0.0)))
    return g.mul(gate, S)


def cook_torrance(g, k, lights, N, V, NV, C):
    """C (x) (A + kd sum att Lc clamp(N.L)) + ks sum att Lc S."""
    diff = (0.0, 0.0, 0.0)
    spec = (0.0, 0.0, 0.0)
    for lt in lights:
        diff = g.vadd(diff, g.scale(lt.light["colour"], lt.weighted(g.clamp0(lt.x))))
        if k["specular"]:
            s = lt.weighted(cook_torrance_specular(g, k, lt, N, V, NV))
            spec = g.vadd(spec, g.scale(lt.light["colour"], s))
    out = g.vmul(C, g.vadd(tuple(k["ambient"]), g.scale(diff, k["kd"])))
    return g.vadd(out, g.scale(spec, k["ks"])) if k["specular"] else out


def model_colour(g, k, P, N, V, C):
    """The colour of docs/models.md as nodes, from the constants k."""
    NV = g.vmath("DOT_PRODUCT", N, V)
    lights = [LightTerm(g, l, P, N, V, NV) for l in k["lights"]]
    if k["shading"] == "phong" and not k.get("normalize_normal", True):
        for lt in lights:
            lt.unit_r_of = N
    t = k["model"]
    if t not in PHONG_MODELS + FORSYTH_MODELS + MINNAERT_BLINN_OREN_NAYAR_MODELS + MICROFACET_MODELS:
        unknown_model(t)
    if t in MINNAERT_BLINN_OREN_NAYAR_MODELS:
        return minnaert_blinn_oren_nayar_colour(g, k, lights, NV, C)
    if t == "cook_torrance":
        return cook_torrance(g, k, lights, N, V, NV, C)
    if t == "classic_phong":
        ka, kd, ks, n = k["ka"], k["kd"], k["ks"], k["shininess"]
        if k["course"]:
            acc = tuple(k["ka_ambient"])
            for lt in lights:
                # att (ka + [lit] (kd clamp(N.L) + ks clamp(R.V)^n)): outside a
                # spot's cone the per-light ambient term remains.
                term = g.mul(kd, g.clamp0(lt.x))
                if k["specular"]:
                    term = g.add(term, g.mul(ks, g.math("POWER", g.clamp0(lt.rv()), n)))
                scalar = g.add(ka, term if lt.lit is None else g.mul(lt.lit, term))
                if lt.att is not None:
                    scalar = g.mul(lt.att, scalar)
                acc = g.vadd(acc, g.scale(lt.light["colour"], scalar))
            return g.vmul(C, acc)
        diff = (0.0, 0.0, 0.0)
        spec = (0.0, 0.0, 0.0)
        for lt in lights:
            diff = g.vadd(diff, g.scale(lt.light["colour"], lt.weighted(g.clamp0(lt.x))))
            if k["specular"]:
                s = lt.weighted(g.math("POWER", g.clamp0(lt.rv()), n))
                spec = g.vadd(spec, g.scale(lt.light["colour"], s))
        base = g.vadd(tuple(k["ka_ambient"]), g.scale(diff, kd))
        out = g.vmul(C, base)
        return g.vadd(out, g.scale(spec, ks)) if k["specular"] else out
    if t == "yiq_luma":
        kd, ks, n, off = k["kd"], k["ks"], k["shininess"], k["luma_offset"]
        dsum, ssum = 0.0, 0.0
        for lt in lights:
            y = lt.light["luma"]
            dsum = g.add(dsum, lt.weighted(g.mul(y, g.saturate(lt.x))))
            if k["specular"]:
                ssum = g.add(ssum, lt.weighted(g.mul(y, g.math("POWER", g.saturate(lt.rv()), n))))
        dl = g.add(k["ambient_luma"], g.mul(kd, dsum), clamp=True)
        Y = g.vmath("DOT_PRODUCT", C, tuple(k["luma_row"]))
        dy = g.add(g.mul(Y, g.math("SUBTRACT", dl, 1.0)), g.math("SUBTRACT", g.mul(ks, ssum), off))
        return g.vadd(C, g.vec(dy, dy, dy))
    acc = tuple(k["ambient"])
    for lt in lights:
        term = g.vmul(lt.light["colour"], forsyth(g, k, lt.x))
        acc = g.vadd(acc, term if lt.w is None else g.scale(term, lt.w))
    return g.vmul(C, acc)


def luma_only_colour(g, k, P, N, V, C):
    """The material's colour: the model's, or in the luma-only mode
    (renderer/colour/luma_only.h) the model lit in grey (k's lights and
    ambients are the greys already) with its luma replacing C's, C's chroma
    kept: yiq F = C + (Y_out - Y_C)(1,1,1); cie_lstar the relative XYZ t of C
    with f(t) + f(Y_out) - f(Y_C) in each of its three f."""
    space = k.get("luma_only")
    if space is None:
        return model_colour(g, k, P, N, V, C)
    lc = k["luma_only_constants"]
    yc = g.vmath("DOT_PRODUCT", C, tuple(lc["surface_row"]))
    grey = model_colour(g, k, P, N, V, g.vec(yc, yc, yc))
    yout = g.vmath("DOT_PRODUCT", grey, tuple(lc["light_row"]))
    if space == "yiq":
        dy = g.math("SUBTRACT", yout, yc)
        return g.vadd(C, g.vec(dy, dy, dy))
    if space != "cie_lstar":
        fail("luma_only %r: this harness knows yiq and cie_lstar" % (space,))

    def select(cond, a, b):  # cond in {0, 1}: a where 1, else b
        return g.add(g.mul(cond, a), g.mul(g.math("SUBTRACT", 1.0, cond), b))

    def lab_f(t):  # t > knee: cube root (of a positive t), else the line
        above = g.math("GREATER_THAN", t, lc["knee"])
        root = g.math("POWER", g.clamp0(t), 1.0 / 3.0)
        return select(above, root, g.add(g.mul(t, lc["slope"]), lc["offset"]))

    def lab_f_inverse(u):
        above = g.math("GREATER_THAN", u, lc["inverse_knee"])
        cube = g.mul(g.mul(u, u), u)
        return select(above, cube, g.math("DIVIDE", g.math("SUBTRACT", u, lc["offset"]), lc["slope"]))

    d = g.math("SUBTRACT", lab_f(yout), lab_f(yc))
    t = [g.vmath("DOT_PRODUCT", C, tuple(row)) for row in lc["to_relative_xyz"]]
    moved = g.vec(*(lab_f_inverse(g.add(lab_f(ti), d)) for ti in t))
    return g.vec(*(g.vmath("DOT_PRODUCT", moved, tuple(row)) for row in lc["from_relative_xyz"]))


def float_copy(image):
    """The image's stored values in a float32 image of the same size (EEVEE
    uploads it as float32 and mip-maps it in float)."""
    w, h = image.size[0], image.size[1]
    f = bpy.data.images.new("xval_texture_float", w, h, alpha=False, float_buffer=True, is_data=True)
    f.colorspace_settings.name = "Non-Color"
    f.use_half_precision = False
    f.pixels.foreach_set(array.array("f", image.pixels[:]))
    return f


def closest_lookup(nt, image, uv):
    """The texel under uv (a vector socket): Image Texture, Closest, Repeat."""
    it = nt.nodes.new("ShaderNodeTexImage")
    it.image = image
    it.interpolation = "Closest"
    it.extension = "REPEAT"
    nt.links.new(uv, it.inputs["Vector"])
    return it.outputs["Color"]


def texel_bilinear(g, nt, image, uv):
    """The bilinear lookup of texture.h, from four Closest lookups (EEVEE's
    Linear mip-maps). In Blender's uv (v up, row 0 at the bottom; the glTF
    importer flips v), per axis: x = frac(u) W - 0.5, x0 = floor(x),
    w = x - x0; the texels x0 and x0 + 1 are looked up at their centres
    (x0 + 0.5) / W and (x0 + 1.5) / W, Repeat wrapping -1 and W; then
    lerp(lerp(c00, c10, wx), lerp(c01, c11, wx), wy). Flipping v mirrors the
    rows and their weights together: the same four texels and weights."""
    w, h = image.size[0], image.size[1]
    sep = nt.nodes.new("ShaderNodeSeparateXYZ")
    nt.links.new(uv, sep.inputs[0])

    def axis(coord, size):
        x = g.math("SUBTRACT", g.mul(g.math("FRACT", coord), float(size)), 0.5)
        x0 = g.math("FLOOR", x)
        wt = g.math("SUBTRACT", x, x0)
        c0 = g.math("DIVIDE", g.add(x0, 0.5), float(size))
        c1 = g.math("DIVIDE", g.add(x0, 1.5), float(size))
        return wt, c0, c1

    wx, x0, x1 = axis(sep.outputs[0], w)
    wy, y0, y1 = axis(sep.outputs[1], h)
    c = {(i, j): closest_lookup(nt, image, g.vec(xc, yc, 0.0))
         for i, xc in enumerate((x0, x1)) for j, yc in enumerate((y0, y1))}

    def lerp(a, b, t):
        return g.vadd(g.scale(a, g.math("SUBTRACT", 1.0, t)), g.scale(b, t))

    return lerp(lerp(c[0, 0], c[1, 0], wx), lerp(c[0, 1], c[1, 1], wx), wy)


def build_model_material(nt, k, image, bilinear_from_closest=False):
    """Fills the node tree nt with the model's Emission shader (strength 1)
    from the constants k; image: the texture (or None: the base colour).
    bilinear_from_closest: a bilinear lookup as texel_bilinear (EEVEE)
    instead of the Image Texture node's Linear."""
    nt.nodes.clear()
    g = Nodes(nt)
    if k["shading"] == "gouraud":
        a = nt.nodes.new("ShaderNodeAttribute")
        a.attribute_type = "GEOMETRY"
        a.attribute_name = "xval_gouraud"
        colour = a.outputs["Vector"]
    else:
        geo = nt.nodes.new("ShaderNodeNewGeometry")
        Pb = geo.outputs["Position"]
        P = g.vec(*(g.vmath("DOT_PRODUCT", Pb, tuple(row)) for row in k["blender_to_world"]))
        V = g.vmath("NORMALIZE", g.vmath("SUBTRACT", g.const(k["eye"]), P))
        a = nt.nodes.new("ShaderNodeAttribute")
        a.attribute_type = "GEOMETRY"
        a.attribute_name = "xval_face_normal" if k["shading"] == "flat" else "xval_normal"
        N = a.outputs["Vector"]
        if k["shading"] == "flat" or k.get("normalize_normal", True):
            N = g.vmath("NORMALIZE", N)
        if image is not None and bilinear_from_closest and k["texture_filter"] == "bilinear":
            uv = nt.nodes.new("ShaderNodeTexCoord")
            C = texel_bilinear(g, nt, image, uv.outputs["UV"])
        elif image is not None:
            uv = nt.nodes.new("ShaderNodeTexCoord")
            it = nt.nodes.new("ShaderNodeTexImage")
            it.image = image
            it.interpolation = "Closest" if k["texture_filter"] == "nearest" else "Linear"
            it.extension = "REPEAT"
            nt.links.new(uv.outputs["UV"], it.inputs["Vector"])
            C = it.outputs["Color"]
        else:
            C = g.const(k["base_colour"])
        colour = luma_only_colour(g, k, P, N, V, C)
    em = nt.nodes.new("ShaderNodeEmission")
    em.inputs["Strength"].default_value = 1.0
    g._set(em.inputs["Color"], colour)
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    nt.links.new(em.outputs[0], out.inputs["Surface"])
    return out


# ------------------------------------------------------------ scene setup
# Cycles places its single sample (Box filter of width 0.01) at a constant
# offset from the pixel centre: +0.000488758 px right and up, the same for
# every pixel, resolution, seed and sampling pattern (measured by rendering
# an orthographic plane whose emission is its position, at 64, 256 and 1024
# pixels a side: 2^-11 px each time). The camera shift below, in units of
# the larger side of the image actually rendered (n W x n H when
# supersampling), moves it back to the centre (residual < 2e-6 px); without
# it, sharp texture edges differ by up to ~3000/65535.
# Cycles' unit of shift is the image's side along the sensor fit, in x and
# in y alike (a shift s moves the view by s * H pixels for VERTICAL, s * W
# for HORIZONTAL, s * max(W, H) for AUTO): with the harness's VERTICAL fit,
# the height. Dividing by max(W, H) instead left a landscape image's samples
# 0.000488758 (1 - H/W) px off, which on a 400 x 300 knot put 8.7% of the
# pixels beyond 2/65535 (max 32.6/65535); tests/cross/cycles_sample_offset.py
# measures it at square, landscape and portrait sizes.
SAMPLE_OFFSET_PX = 0.000488758


def centre_samples(camera, width, height):
    fit = camera.data.sensor_fit
    side = height if fit == "VERTICAL" else width if fit == "HORIZONTAL" else max(width, height)
    camera.data.shift_x = -SAMPLE_OFFSET_PX / side
    camera.data.shift_y = -SAMPLE_OFFSET_PX / side


def setup_output(scene, width, height, out, multilayer):
    """What both engines share: resolution, transparent film (alpha = hit
    mask), Standard view transform, no dither, 32-bit float EXR."""
    r = scene.render
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


def fit_clip_range(camera, meshes):
    """The camera's clip range fitted to the meshes' world bounding boxes:
    from the nearest to the farthest box corner along the view axis
    (camera -z), widened by 1% each way; where a box reaches behind or onto
    the camera the near plane is 1e-4 of the far one."""
    bpy.context.view_layer.update()
    inv = camera.matrix_world.inverted()
    depths = []
    for o in meshes:
        for corner in o.bound_box:
            p = inv @ (o.matrix_world @ mathutils.Vector(corner))
            depths.append(-p.z)
    if not depths:
        return
    far = max(depths) * 1.01
    if not far > 0.0:
        fail("every mesh lies behind the camera")
    near = min(depths) * 0.99
    camera.data.clip_start = near if near > far * 1e-4 else far * 1e-4
    camera.data.clip_end = far


def setup_eevee(scene):
    """EEVEE: one sample on each pixel centre, no effect of its own; small
    shadow and probe buffers (speed only)."""
    scene.render.engine = "BLENDER_EEVEE"
    scene.render.filter_size = 0.0
    e = scene.eevee
    e.taa_render_samples = 1
    e.taa_samples = 1
    e.use_bloom = False
    e.use_gtao = False
    e.use_ssr = False
    e.use_motion_blur = False
    e.use_soft_shadows = False
    e.use_volumetric_lights = False
    e.shadow_cube_size = "64"
    e.shadow_cascade_size = "64"
    e.gi_cubemap_resolution = "64"
    e.gi_visibility_resolution = "8"
    e.gi_diffuse_bounces = 0
    bpy.context.preferences.system.anisotropic_filter = "FILTER_0"


def setup_render(scene, width, height, out, multilayer):
    setup_output(scene, width, height, out, multilayer)
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


def build_native_material(nt, args, blender_to_world):
    """Fills nt with Blender's own BSDFs (native mode): a Diffuse BSDF of
    Roughness args.diffuse_roughness and grey colour args.diffuse_colour,
    plus, unless args.glossy is "none", a Glossy BSDF (GGX or Beckmann) of
    Roughness args.glossy_roughness and colour args.glossy_colour, added; each BSDF's Normal the exact glTF normal
    (xval_normal, in the scene's world frame) taken to Blender's frame by
    the transpose of the export's blender_to_world rotation and normalised,
    not the importer's compressed custom normals. The C++ side
    (blender/native_bsdf.h) chose the values and weighs the passes; nothing
    is derived here."""
    nt.nodes.clear()
    g = Nodes(nt)
    a = nt.nodes.new("ShaderNodeAttribute")
    a.attribute_type = "GEOMETRY"
    a.attribute_name = "xval_normal"
    sep = nt.nodes.new("ShaderNodeSeparateXYZ")
    nt.links.new(a.outputs["Vector"], sep.inputs[0])
    # N_blender = sum_i N_world[i] row_i (the rotation's transpose)
    rows = [g.scale(g.const(row), sep.outputs[i]) for i, row in enumerate(blender_to_world)]
    N = g.vmath("NORMALIZE", g.vadd(g.vadd(rows[0], rows[1]), rows[2]))
    diffuse = nt.nodes.new("ShaderNodeBsdfDiffuse")
    dc = args.diffuse_colour
    diffuse.inputs["Color"].default_value = (dc, dc, dc, 1.0)
    diffuse.inputs["Roughness"].default_value = args.diffuse_roughness
    nt.links.new(N, diffuse.inputs["Normal"])
    surface = diffuse.outputs[0]
    if args.glossy != "none":
        glossy = nt.nodes.new("ShaderNodeBsdfGlossy")
        glossy.distribution = {"ggx": "GGX", "beckmann": "BECKMANN"}[args.glossy]
        gc = args.glossy_colour
        glossy.inputs["Color"].default_value = (gc, gc, gc, 1.0)
        glossy.inputs["Roughness"].default_value = args.glossy_roughness
        nt.links.new(N, glossy.inputs["Normal"])
        add = nt.nodes.new("ShaderNodeAddShader")
        nt.links.new(surface, add.inputs[0])
        nt.links.new(glossy.outputs[0], add.inputs[1])
        surface = add.outputs[0]
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    nt.links.new(surface, out.inputs["Surface"])


def render_native(args, scene, data, meshes, width, height):
    """Native mode: Blender's own BSDFs lit by the imported point light
    (radius 0: a point, as the reference's; no shadows: local illumination),
    direct light only. Cycles writes the diffuse- and glossy-direct passes
    (DiffDir, GlossDir; both without the BSDFs' colour) to a multilayer
    EXR; EEVEE the combined image (its light's radius is at least 0.001
    whatever is set, a factor 1 / (1 + r^2 / d^2) on its Lambert: 1 - 3e-7
    at d = 1.8; its influence distance is made huge so that it cuts no
    light off)."""
    for o in scene.objects:
        if o.type == "LIGHT":
            o.data.shadow_soft_size = 0.0  # a point, not the importer's 0.25 sphere
            o.data.cycles.cast_shadow = False  # local illumination, as the reference
            o.data.use_shadow = False  # EEVEE's
            o.data.use_contact_shadow = False
            o.data.use_custom_distance = True  # EEVEE's influence cut-off, out of reach
            o.data.cutoff_distance = 1e6
    docs = data.doc.get("materials", [])
    if not docs or "xval_shading" not in docs[0].get("extras", {}):
        fail("no xval_shading constants in the extras of glTF material 0")
    k = json.loads(docs[0]["extras"]["xval_shading"])
    mat = bpy.data.materials.new("xval_native")
    mat.use_nodes = True
    build_native_material(mat.node_tree, args, k["blender_to_world"])
    for o in meshes:
        me = o.data
        attrs, corners = mesh_attributes(data, data.primitive(me.name), "phong")
        if len(me.loops) != corners:
            fail("mesh %s: %d corners in Blender, %d indices in the glTF (Blender's importer changed the mesh)"
                 % (me.name, len(me.loops), corners))
        domain, values = attrs["xval_normal"]
        me.attributes.new("xval_normal", "FLOAT_VECTOR", domain).data.foreach_set("vector", values)
        me.materials.clear()
        me.materials.append(mat)
    if args.engine == "eevee":
        fit_clip_range(scene.camera, meshes)
        setup_output(scene, width, height, args.out, False)
        setup_eevee(scene)
    else:
        bpy.context.view_layer.use_pass_diffuse_direct = True
        bpy.context.view_layer.use_pass_glossy_direct = True
        setup_render(scene, width, height, args.out, True)
    bpy.ops.render.render(write_still=True)


def render_scene(args):
    """Renders one scene (args: gltf, out, mode, engine) from factory
    settings."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    if "FINISHED" not in bpy.ops.import_scene.gltf(filepath=args.gltf, convert_lighting_mode="RAW"):
        fail("the glTF importer failed on " + args.gltf)
    scene = bpy.context.scene
    if "xval" not in scene.keys():
        fail("no xval scene description in the glTF scene extras")
    data = GltfData(args.gltf)
    scene.world = None
    cams = [o for o in scene.objects if o.type == "CAMERA"]
    if len(cams) != 1:
        fail("expected one camera, found %d" % len(cams))
    scene.camera = cams[0]
    cams[0].data.sensor_fit = "VERTICAL"
    if "xval_render" not in scene.keys():
        fail("no xval_render resolution in the glTF scene extras")
    size = json.loads(scene["xval_render"])
    width, height = int(size["width"]), int(size["height"])
    if width < 1 or height < 1:
        fail("xval_render resolution %dx%d" % (width, height))
    if args.engine == "cycles":
        centre_samples(cams[0], width, height)

    meshes = [o for o in scene.objects if o.type == "MESH"]
    if args.mode == "native":
        render_native(args, scene, data, meshes, width, height)
        return

    # Model mode: lights are evaluated in the nodes; Blender's lights go.
    for o in list(scene.objects):
        if o.type == "LIGHT":
            bpy.data.objects.remove(o, do_unlink=True)
    # One node tree per glTF material, from the constants in its extras
    # (every object of one material shares it).
    folder = os.path.dirname(os.path.abspath(args.gltf))
    materials = {}

    def model_material(index):
        if index in materials:
            return materials[index]
        docs = data.doc.get("materials", [])
        if not isinstance(index, int) or not 0 <= index < len(docs):
            fail("material %r not in the glTF" % (index,))
        extras = docs[index].get("extras", {})
        if "xval_shading" not in extras:
            fail("no xval_shading constants in the extras of glTF material %d" % index)
        k = json.loads(extras["xval_shading"])
        image = None
        if k["texture_filter"] is not None:
            name = extras.get("xval_texture")
            if not isinstance(name, str) or not name or "/" in name or "\\" in name or name.startswith("."):
                fail("glTF material %d: texture file %r is not a file of the export folder" % (index, name))
            image = bpy.data.images.load(os.path.join(folder, name), check_existing=True)
            image.colorspace_settings.name = "Non-Color"
            image.alpha_mode = "NONE"
            if args.engine == "eevee":
                image.use_half_precision = False  # a 16-bit texture as float32 on the GPU, not half
            if args.engine == "eevee" and k["texture_filter"] == "trilinear":
                image = float_copy(image)
        mat = bpy.data.materials.new("xval_model_%d" % index)
        mat.use_nodes = True
        build_model_material(mat.node_tree, k, image, bilinear_from_closest=args.engine == "eevee")
        materials[index] = (mat, k)
        return materials[index]

    for o in meshes:
        me = o.data
        prim = data.primitive(me.name)
        mat, k = model_material(prim.get("material"))
        attrs, corners = mesh_attributes(data, prim, k["shading"])
        if len(me.loops) != corners:
            # Blender's import dropped triangles; the export refuses those it
            # knows of (geometry/degenerate_triangles.h), so this is a new kind.
            fail("mesh %s: %d corners in Blender, %d indices in the glTF (Blender's importer changed the mesh)"
                 % (me.name, len(me.loops), corners))
        if len(me.polygons) * 3 != corners:
            fail("mesh %s: %d faces in Blender, %d triangles in the glTF" % (me.name, len(me.polygons), corners // 3))
        for name, (domain, values) in attrs.items():
            me.attributes.new(name, "FLOAT_VECTOR", domain).data.foreach_set("vector", values)
        me.materials.clear()
        me.materials.append(mat)
    if args.engine == "eevee":
        fit_clip_range(cams[0], meshes)
        setup_output(scene, width, height, args.out, False)
        setup_eevee(scene)
    else:
        setup_render(scene, width, height, args.out, False)
    bpy.ops.render.render(write_still=True)


def patch_numpy():
    import numpy  # Blender 3.4's glTF importer uses numpy.bool, removed in numpy 1.24.
    if not hasattr(numpy, "bool"):
        numpy.bool = bool


def append_line(path, record):
    with open(path, "a", encoding="utf-8") as f:
        f.write(json.dumps(record) + "\n")
        f.flush()
        os.fsync(f.fileno())


def run_batch(args):
    """The jobs of args.batch one after the other; a job's failure is its
    own "done" record (its message and traceback in its log), never the
    next job's."""
    with open(args.batch, "r", encoding="utf-8") as f:
        jobs = json.load(f)["jobs"]
    import ctypes
    import time
    import traceback
    libc = ctypes.CDLL(None)

    def flush_all():
        # Python's streams and C's stdio buffers (Blender prints the render
        # time with printf): nothing of one job may reach the next one's log.
        sys.stdout.flush()
        sys.stderr.flush()
        libc.fflush(None)

    for i, job in enumerate(jobs):
        append_line(args.results, {"start": i})
        t0 = time.monotonic()
        flush_all()
        saved = os.dup(1), os.dup(2)
        fd = os.open(job["log"], os.O_WRONLY | os.O_CREAT | os.O_TRUNC | os.O_NOFOLLOW, 0o644)
        os.dup2(fd, 1)
        os.dup2(fd, 2)
        os.close(fd)
        error = ""
        try:
            render_scene(argparse.Namespace(gltf=job["gltf"], out=job["out"], mode="model",
                                            engine=job["engine"]))
        except SystemExit as e:  # fail(): the message is in the log
            error = "the harness failed (exit %s)" % e.code
        except Exception as e:
            traceback.print_exc()
            error = "%s: %s" % (type(e).__name__, e)
            print("xval render_gltf.py: error: " + error, file=sys.stderr)
        flush_all()
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        os.close(saved[0])
        os.close(saved[1])
        append_line(args.results, {"done": i, "ok": not error, "error": error,
                                   "seconds": time.monotonic() - t0})


def main():
    args = parse_args()
    patch_numpy()
    if args.batch is not None:
        run_batch(args)
    else:
        render_scene(args)


if __name__ == "__main__":
    try:
        main()
    except SystemExit:
        raise
    except Exception as e:  # report, and make Blender exit non-zero
        import traceback
        traceback.print_exc()
        fail("%s: %s" % (type(e).__name__, e))
