"""A numeric stand-in for the part of Blender's `bpy` that
exporters/blender/render_gltf.py uses to build its shader nodes: node trees
whose nodes compute their outputs, in double precision, with the semantics
of Blender 3.4's Cycles SVM nodes (intern/cycles/kernel/svm/math_util.h):

  Math      ADD a+b, SUBTRACT a-b, MULTIPLY a*b, DIVIDE b != 0 ? a/b : 0,
            POWER: 0 for a < 0 with b not whole, else a^b (0^0 = 1),
            MAXIMUM fmax, MINIMUM fmin, ABSOLUTE |a|, LESS_THAN a < b,
            GREATER_THAN a > b (1 or 0: both 0 at equality), EXPONENT e^a,
            SQRT sqrt(max(a, 0)); use_clamp: the result clamped to [0, 1]
  Vector Math  ADD, SUBTRACT, MULTIPLY (per component), SCALE a * Scale,
            DOT_PRODUCT (x x + y y) + z z, LENGTH sqrt(a.a),
            NORMALIZE a / |a| (0 stays 0), CROSS_PRODUCT a x b
  Combine XYZ, Emission (Color x Strength), Material Output.
Inputs of the render come from an evaluation context (Context): Geometry >
Position (Blender frame), named attributes, the Image Texture's colour.

Links between a scalar and a vector socket raise (Blender would convert
silently: a vector's average, a scalar's splat), as do unknown node types,
operations and socket names: the script must use the nodes as written.
Blender stores socket values as float32; this stand-in keeps doubles, so it
checks the graph's formulas and constants, not float32 rounding.
"""

import math


class NodeSocket:
    def __init__(self, node, name, kind, is_output, default=None):
        self.node, self.name, self.kind, self.is_output = node, name, kind, is_output
        self._default = default
        self.link = None

    @property
    def default_value(self):
        return self._default

    @default_value.setter
    def default_value(self, v):
        if self.is_output:
            raise TypeError("%s.%s: an output has no default value" % (self.node.bl_idname, self.name))
        if self.kind == "VALUE":
            if isinstance(v, (tuple, list)):
                raise TypeError("%s.%s: scalar socket given %r" % (self.node.bl_idname, self.name, v))
            self._default = float(v)
        else:
            v = tuple(float(c) for c in v)
            if len(v) not in (3, 4):
                raise TypeError("%s.%s: vector socket given %r" % (self.node.bl_idname, self.name, v))
            self._default = v[:3]

    def value(self, ctx):
        if self.is_output:
            return self.node.output(self, ctx)
        if self.link is not None:
            return self.link.value(ctx)
        if self._default is None:
            raise ValueError("%s.%s: neither linked nor set" % (self.node.bl_idname, self.name))
        return self._default


class types:
    NodeSocket = NodeSocket


class Sockets(list):
    def __getitem__(self, key):
        if isinstance(key, str):
            for s in self:
                if s.name == key:
                    return s
            raise KeyError(key)
        return list.__getitem__(self, key)


VEC0 = (0.0, 0.0, 0.0)


def add(a, b): return (a[0] + b[0], a[1] + b[1], a[2] + b[2])
def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def normalize(a):
    t = math.sqrt(dot(a, a))
    return (a[0] / t, a[1] / t, a[2] / t) if t != 0.0 else a


def power(a, b):
    if a < 0.0 and b != float(int(b)):
        return 0.0
    return math.pow(a, b)


MATH = {
    "ADD": lambda a, b: a + b,
    "SUBTRACT": lambda a, b: a - b,
    "MULTIPLY": lambda a, b: a * b,
    "DIVIDE": lambda a, b: a / b if b != 0.0 else 0.0,
    "POWER": power,
    "MAXIMUM": lambda a, b: max(a, b),
    "ABSOLUTE": lambda a, b: abs(a),
    "LESS_THAN": lambda a, b: 1.0 if a < b else 0.0,
    "GREATER_THAN": lambda a, b: 1.0 if a > b else 0.0,
    "MINIMUM": lambda a, b: min(a, b),
    "EXPONENT": lambda a, b: math.exp(a),
    "SQRT": lambda a, b: math.sqrt(a) if a > 0.0 else 0.0,
}

VMATH = {
    "ADD": lambda a, b, s: ("Vector", add(a, b)),
    "SUBTRACT": lambda a, b, s: ("Vector", sub(a, b)),
    "MULTIPLY": lambda a, b, s: ("Vector", (a[0] * b[0], a[1] * b[1], a[2] * b[2])),
    "SCALE": lambda a, b, s: ("Vector", (a[0] * s, a[1] * s, a[2] * s)),
    "DOT_PRODUCT": lambda a, b, s: ("Value", dot(a, b)),
    "LENGTH": lambda a, b, s: ("Value", math.sqrt(dot(a, a))),
    "NORMALIZE": lambda a, b, s: ("Vector", normalize(a)),
    "CROSS_PRODUCT": lambda a, b, s: ("Vector", (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                                 a[0] * b[1] - a[1] * b[0])),
}


class Node:
    # bl_idname -> (inputs, outputs) as (name, kind, default)
    LAYOUT = {
        "ShaderNodeMath": ([("Value", "VALUE", 0.5), ("Value_001", "VALUE", 0.5),
                            ("Value_002", "VALUE", 0.5)], [("Value", "VALUE")]),
        "ShaderNodeVectorMath": ([("Vector", "VECTOR", VEC0), ("Vector_001", "VECTOR", VEC0),
                                  ("Vector_002", "VECTOR", VEC0), ("Scale", "VALUE", 1.0)],
                                 [("Vector", "VECTOR"), ("Value", "VALUE")]),
        "ShaderNodeCombineXYZ": ([("X", "VALUE", 0.0), ("Y", "VALUE", 0.0), ("Z", "VALUE", 0.0)],
                                 [("Vector", "VECTOR")]),
        "ShaderNodeAttribute": ([], [("Color", "RGBA"), ("Vector", "VECTOR"), ("Fac", "VALUE")]),
        "ShaderNodeNewGeometry": ([], [("Position", "VECTOR"), ("Normal", "VECTOR"),
                                       ("Incoming", "VECTOR")]),
        "ShaderNodeTexCoord": ([], [("UV", "VECTOR")]),
        "ShaderNodeTexImage": ([("Vector", "VECTOR", None)], [("Color", "RGBA"), ("Alpha", "VALUE")]),
        "ShaderNodeEmission": ([("Color", "RGBA", (1.0, 1.0, 1.0)), ("Strength", "VALUE", 1.0)],
                               [("Emission", "SHADER")]),
        "ShaderNodeOutputMaterial": ([("Surface", "SHADER", None)], []),
    }

    def __init__(self, bl_idname):
        if bl_idname not in self.LAYOUT:
            raise TypeError("node type %s is not modelled by the stand-in" % bl_idname)
        self.bl_idname = bl_idname
        ins, outs = self.LAYOUT[bl_idname]
        self.inputs = Sockets(NodeSocket(self, n, k, False, d) for n, k, d in ins)
        self.outputs = Sockets(NodeSocket(self, n, k, True) for n, k in outs)
        self.operation = "ADD"
        self.use_clamp = False
        self.attribute_type = "GEOMETRY"
        self.attribute_name = ""
        self.image = None
        self.interpolation = "Linear"
        self.extension = "REPEAT"

    def output(self, sock, ctx):
        key = (id(self), sock.name)
        if key not in ctx.memo:
            ctx.memo[key] = self._compute(sock.name, ctx)
        return ctx.memo[key]

    def _in(self, i, ctx):
        return self.inputs[i].value(ctx)

    def _compute(self, name, ctx):
        t = self.bl_idname
        if t == "ShaderNodeMath":
            if self.operation not in MATH:
                raise ValueError("Math operation %s is not modelled" % self.operation)
            r = MATH[self.operation](self._in(0, ctx), self._in(1, ctx))
            return min(max(r, 0.0), 1.0) if self.use_clamp else r
        if t == "ShaderNodeVectorMath":
            if self.operation not in VMATH:
                raise ValueError("Vector Math operation %s is not modelled" % self.operation)
            out, r = VMATH[self.operation](self._in(0, ctx), self._in(1, ctx), self._in(3, ctx))
            if out != name:
                raise ValueError("Vector Math %s has no meaningful output %s" % (self.operation, name))
            return r
        if t == "ShaderNodeCombineXYZ":
            return (self._in(0, ctx), self._in(1, ctx), self._in(2, ctx))
        if t == "ShaderNodeAttribute":
            if name not in ("Vector", "Color") or self.attribute_type != "GEOMETRY":
                raise ValueError("attribute node: only the GEOMETRY Vector/Color output is modelled")
            return ctx.attributes[self.attribute_name]
        if t == "ShaderNodeNewGeometry":
            if name != "Position":
                raise ValueError("Geometry > %s is not modelled (the script must not use it)" % name)
            return ctx.position_blender
        if t == "ShaderNodeTexImage":
            if name != "Color" or self.image is None:
                raise ValueError("Image Texture: only Color of a set image is modelled")
            self.inputs["Vector"].value(ctx)  # must be linked (UV)
            return ctx.texture_colour
        if t == "ShaderNodeTexCoord":
            return ctx.uv
        if t == "ShaderNodeEmission":
            c, s = self._in(0, ctx), self._in(1, ctx)
            return (c[0] * s, c[1] * s, c[2] * s)
        raise ValueError("%s has no output %s" % (t, name))


class Nodes(list):
    def new(self, bl_idname):
        n = Node(bl_idname)
        self.append(n)
        return n


class Links(list):
    def new(self, from_socket, to_socket):
        if not from_socket.is_output or to_socket.is_output:
            raise TypeError("a link goes from an output to an input")
        vectorish = ("VECTOR", "RGBA")
        if (from_socket.kind in vectorish) != (to_socket.kind in vectorish) or \
                (from_socket.kind == "SHADER") != (to_socket.kind == "SHADER"):
            raise TypeError("link %s.%s (%s) -> %s.%s (%s): Blender would convert implicitly" % (
                from_socket.node.bl_idname, from_socket.name, from_socket.kind,
                to_socket.node.bl_idname, to_socket.name, to_socket.kind))
        to_socket.link = from_socket
        self.append((from_socket, to_socket))


class NodeTree:
    def __init__(self):
        self.nodes = Nodes()
        self.links = Links()


class Context:
    """One shading point: Geometry > Position (Blender frame), the named
    attributes' values there, the texture colour."""

    def __init__(self, position_blender, attributes, texture_colour=None, uv=(0.0, 0.0, 0.0)):
        self.position_blender = position_blender
        self.attributes = attributes
        self.texture_colour = texture_colour
        self.uv = uv
        self.memo = {}


def evaluate(tree, ctx):
    """The colour reaching the Material Output's Surface."""
    outs = [n for n in tree.nodes if n.bl_idname == "ShaderNodeOutputMaterial"]
    if len(outs) != 1:
        raise ValueError("%d Material Output nodes" % len(outs))
    emission = outs[0].inputs["Surface"].link
    if emission is None or emission.node.bl_idname != "ShaderNodeEmission":
        raise ValueError("the Surface is not an Emission shader")
    return emission.node._compute("Emission", ctx)
