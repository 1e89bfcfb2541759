#!/usr/bin/python3
"""A wrong renderer: the reference renderer with one realistic bug of small
effect (docs/mutation-test.md). Each renderer definition file beside this
script (`xval-renderer/1`, docs/renderer-file.md) runs it as

    ./mutant.py FAULT {scene} {output} {work}

with the environment variable XVAL naming the `xval` executable (the
mutation test sets it). Three kinds of fault:

* scene faults rewrite the resolved scene (every field given, paths
  absolute) and render it with `xval render`;
* texture faults write a changed copy of each image texture into {work} and
  render the scene pointing at the copies;
* image faults render the scene unchanged and change the image afterwards,
  using the reference's diagnostics channels where the fault needs them
  (triangle_edge, incidence: renderer/image/image.h).

The output holds R, G, B, A only (no diagnostics channels): the mutant is
compared as any renderer defined by a file is.

This file is /usr/bin/python3 on purpose: the OpenImageIO module
(python3-openimageio) and numpy are Debian's, installed for that Python.
"""
import json
import math
import os
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

# Each fault and its one-line description (the renderer files repeat it).
FAULTS = {
    # scene faults
    "shininess": "specular exponent 2% high (shininess x 1.02)",
    "kd": "diffuse weight 1% low (kd x 0.99, or c0 x 0.99 for the Forsyth models)",
    "ambient": "ambient light 1/255 too bright (every ambient light's colour + 1/255)",
    "light-moved": "point and spot lights moved by 1% of the scene's size (+x by 0.01 |camera target - position|); "
                   "directional lights turned by 0.01 rad about y",
    "spot-cutoff": "spot cone 0.5 degree wider (cutoff_deg + 0.5)",
    "attenuation-swap": "linear and quadratic attenuation coefficients swapped",
    "nearest": "nearest texture filtering instead of bilinear or trilinear",
    "gouraud": "Gouraud shading instead of Phong (per-vertex lighting; trilinear becomes bilinear, as Gouraud has no footprint)",
    # texture faults
    "texture-vflip": "image textures flipped vertically (v up instead of down)",
    "texture-srgb": "image textures linearised as if sRGB-encoded (the codes are display-referred, never linearised)",
    # image faults
    "output-srgb": "output encoded with the sRGB transfer function",
    "shift": "image shifted right by one pixel",
    "odd-rows": "every odd row missing (zero colour and coverage)",
    "cracks": "cracks along triangle edges: pixels with a sample within 0.02 px of a triangle edge are dropped (a tie-breaking rule that gives an edge to neither triangle)",
    "grazing-cull": "grazing pixels culled: pixels where a sample meets its triangle at |cos| < 0.1 are dropped",
    "edge-coverage-drop": "partly covered pixels dropped (coverage 0 < A < 1 set to nothing)",
    "edge-coverage-unassociated": "partly covered pixels written with unassociated colour (RGB / A) while the file says premultiplied",
}

SCENE_FAULTS = {"shininess", "kd", "ambient", "light-moved", "spot-cutoff", "attenuation-swap", "nearest", "gouraud"}
TEXTURE_FAULTS = {"texture-vflip", "texture-srgb"}


def fail(message):
    sys.stderr.write("mutant: " + message + "\n")
    sys.exit(2)


def materials(scene):
    """Every material of the scene: the scene's and each object's own."""
    out = [scene["material"]] if isinstance(scene.get("material"), dict) else []
    for obj in scene.get("objects", []):
        if isinstance(obj.get("material"), dict):
            out.append(obj["material"])
    return out


def mutate_scene(fault, scene):
    if fault == "shininess":
        for m in materials(scene):
            if "shininess" in m["model"]:
                m["model"]["shininess"] *= 1.02
    elif fault == "kd":
        for m in materials(scene):
            model = m["model"]
            if "kd" in model:
                model["kd"] *= 0.99
            elif "c0" in model:
                model["c0"] = [c * 0.99 for c in model["c0"]]
    elif fault == "ambient":
        for light in scene["lights"]:
            if light["type"] == "ambient":
                light["color"] = [c + 1.0 / 255.0 for c in light["color"]]
    elif fault == "light-moved":
        cam = scene["camera"]
        size = math.dist(cam["position"], cam["target"])
        for light in scene["lights"]:
            if "position" in light:
                light["position"][0] += 0.01 * size
            elif light["type"] == "directional":
                x, y, z = light["direction"]
                c, s = math.cos(0.01), math.sin(0.01)
                light["direction"] = [c * x + s * z, y, -s * x + c * z]
    elif fault == "spot-cutoff":
        for light in scene["lights"]:
            if light["type"] == "spot":
                light["cutoff_deg"] = min(90.0, light["cutoff_deg"] + 0.5)
    elif fault == "attenuation-swap":
        for light in scene["lights"]:
            a = light.get("attenuation")
            if a:
                a["linear"], a["quadratic"] = a["quadratic"], a["linear"]
    elif fault == "nearest":
        for m in materials(scene):
            if "texture" in m:
                m["texture"]["filter"] = "nearest"
    elif fault == "gouraud":
        if scene.get("shading", "phong") == "phong":
            scene["shading"] = "gouraud"
            scene["normalize_normal"] = True
            for m in materials(scene):
                if m.get("texture", {}).get("filter") == "trilinear":
                    m["texture"]["filter"] = "bilinear"


def srgb_to_linear(c):
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def linear_to_srgb(c):
    c = np.clip(c, 0.0, None)
    return np.where(c <= 0.0031308, c * 12.92, 1.055 * np.power(c, 1.0 / 2.4) - 0.055)


def read_pixels(path):
    buf = oiio.ImageBuf(path)
    pixels = buf.get_pixels(oiio.FLOAT)
    if buf.has_error or pixels is None:
        fail(path + ": cannot read: " + buf.geterror())
    return buf.spec(), pixels


def mutate_textures(fault, scene, work):
    """Each image texture copied into `work` with the fault, as a 16-bit PNG
    (its codes c / 65535 are the changed values within half a step)."""
    for k, m in enumerate(materials(scene)):
        tex = m.get("texture")
        if not tex or tex["source"] != "image":
            continue
        spec, pixels = read_pixels(tex["path"])
        if fault == "texture-vflip":
            pixels = pixels[::-1, :, :]
        else:
            pixels = srgb_to_linear(pixels)
        out = os.path.join(work, "texture%d.png" % k)
        write_pixels(out, pixels, oiio.UINT16)
        tex["path"] = out


def write_pixels(path, pixels, fmt):
    h, w, ch = pixels.shape
    out = oiio.ImageOutput.create(path)
    if out is None or not out.open(path, oiio.ImageSpec(w, h, ch, fmt)):
        fail(path + ": cannot write: " + oiio.geterror())
    ok = out.write_image(np.ascontiguousarray(pixels, dtype=np.float32))
    out.close()
    if not ok:
        fail(path + ": cannot write: " + oiio.geterror())


def channel(spec, pixels, name, path):
    if name not in spec.channelnames:
        fail(path + ": no channel " + name + " (the reference renderer writes it: renderer/image/image.h)")
    return pixels[:, :, spec.channelnames.index(name)]


def mutate_image(fault, spec, pixels, path):
    """RGBA (premultiplied) with the fault, from the reference's EXR."""
    rgba = np.stack([channel(spec, pixels, c, path) for c in "RGBA"], axis=-1).copy()
    alpha = rgba[:, :, 3:4]
    if fault == "output-srgb":
        straight = np.divide(rgba[:, :, :3], alpha, out=np.zeros_like(rgba[:, :, :3]), where=alpha > 0)
        rgba[:, :, :3] = linear_to_srgb(straight) * alpha
    elif fault == "shift":
        rgba[:, 1:, :] = rgba[:, :-1, :].copy()
        rgba[:, 0, :] = 0.0
    elif fault == "odd-rows":
        rgba[1::2, :, :] = 0.0
    elif fault == "cracks":
        rgba[channel(spec, pixels, "triangle_edge", path) < 0.02] = 0.0
    elif fault == "grazing-cull":
        covered = rgba[:, :, 3] > 0
        rgba[covered & (channel(spec, pixels, "incidence", path) < 0.1)] = 0.0
    elif fault == "edge-coverage-drop":
        rgba[(rgba[:, :, 3] > 0) & (rgba[:, :, 3] < 1)] = 0.0
    elif fault == "edge-coverage-unassociated":
        partial = (rgba[:, :, 3] > 0) & (rgba[:, :, 3] < 1)
        rgba[partial, :3] /= rgba[partial, 3:4]
    return rgba


def main(argv):
    if len(argv) == 2 and argv[1] == "--version":
        print("xval mutant version 1")
        return 0
    if len(argv) != 5 or argv[1] not in FAULTS:
        fail("usage: mutant.py FAULT SCENE OUTPUT WORK (FAULT one of " + ", ".join(FAULTS) + "); got " + repr(argv[1:]))
    fault, scene_file, output, work = argv[1:]
    xval = os.environ.get("XVAL")
    if not xval:
        fail("XVAL is not set: it must name the xval executable (the mutation test sets it)")
    os.makedirs(work, exist_ok=True)
    with open(scene_file, encoding="utf-8") as f:
        scene = json.load(f)
    if fault in SCENE_FAULTS:
        mutate_scene(fault, scene)
    elif fault in TEXTURE_FAULTS:
        mutate_textures(fault, scene, work)
    mutated = os.path.join(work, "mutated_scene.json")
    with open(mutated, "w", encoding="utf-8") as f:
        json.dump(scene, f)
    rendered = os.path.join(work, "reference.exr")
    run = subprocess.run([xval, "render", mutated, "-o", rendered, "-q"], stdin=subprocess.DEVNULL)
    if run.returncode != 0:
        fail("xval render " + mutated + " exited with " + str(run.returncode))
    spec, pixels = read_pixels(rendered)
    if fault in SCENE_FAULTS or fault in TEXTURE_FAULTS:
        rgba = np.stack([channel(spec, pixels, c, rendered) for c in "RGBA"], axis=-1)
    else:
        rgba = mutate_image(fault, spec, pixels, rendered)
    write_pixels(output, rgba, oiio.FLOAT)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
