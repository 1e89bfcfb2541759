#!/usr/bin/env python3
"""Checks that no module of xval includes a module above it.

A module is a folder of renderer/ or exporters/ (renderer/shading/model and
each folder of renderer/validate/ are modules of their own). LAYERS below
lists them bottom up: a file may include headers of its own module and of
modules listed before it, never of one listed after it. The data flow of
README.md reads upwards: scene data, images, geometry, the scene file's
reader, shading, the reference render, the exporters and renderers, the
validation, the commands.

Usage: scripts/check-layers.py [REPO]   (exit 1 and one line per include
that climbs; exit 2 when a folder is in no layer, so a new folder must be
placed on purpose.)
"""
import os
import re
import sys

# Bottom up; each entry is one layer (modules in one layer must not include
# each other's headers in both directions: the check also refuses that).
LAYERS = [
    ["files", "text", "colour"],   # files, numbers as text, colour matrices
    ["process"],                   # processes and the job pool
    ["shading/model"],             # the lighting models' parameter structs
    ["scene"],                     # Scene (data), its limits, the JSON reader
    ["image"],                     # images, their I/O, compare and metrics
    ["oiio_module"],               # OpenImageIO in a module of its own (image/other_formats.h opens it)
    ["camera"],                    # projection; triangle-edge distances
    ["texture"],                   # textures, filters, mip chains
    ["geometry"],                  # meshes, shapes, model files
    ["scene_file"],                # scene file -> Scene; writer, sets, generator
    ["shading"],                   # the models' math and the shaders
    ["render"],                    # the reference renderer
    ["lint"],                      # scene warnings (ray casts over the meshes)
    ["golden"],                    # stored image sets
    ["exporters/common"],
    ["exporters/gltf", "exporters/povray"],
    ["exporters/blender"],
    ["gl"],                        # the GLSL renderer on OpenGL
    ["shader_file"],               # users' shaders on the gl context
    ["renderers"],                 # the registry of renderers
    ["validate/common"],           # provenance, timing, HTML text
    ["validate"],                  # tolerances, geometry checks, crops, claims
    ["validate/results"],          # results.json as types, verdicts
    ["validate/extremes", "validate/tradeoff"],
    ["validate/report"],           # the report and JUnit
    ["validate/golden", "validate/bench", "validate/validation"],
    ["pack"],
    ["cli"],
]


def module_of(rel):
    parts = rel.split("/")
    if parts[0] == "renderer":
        if len(parts) == 2:
            return None  # renderer/CMakeLists.txt and the like
        if parts[1] == "shading" and len(parts) > 3 and parts[2] == "model":
            return "shading/model"
        if parts[1] == "validate" and len(parts) > 3:
            return "validate/" + parts[2]
        return parts[1]
    if parts[0] == "exporters" and len(parts) > 2:
        return "exporters/" + parts[1]
    return None


def main():
    repo = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    rank = {m: i for i, layer in enumerate(LAYERS) for m in layer}
    climbs, unplaced = [], set()
    include = re.compile(r'\s*#\s*include\s+"([^"]+)"')
    for top in ("renderer", "exporters"):
        for folder, _, files in os.walk(os.path.join(repo, top)):
            for name in sorted(files):
                if not name.endswith((".h", ".cpp")):
                    continue
                path = os.path.join(folder, name)
                rel = os.path.relpath(path, repo)
                src = module_of(rel)
                if src is None:
                    continue
                if src not in rank:
                    unplaced.add(src)
                    continue
                with open(path, encoding="utf-8", errors="replace") as f:
                    for number, line in enumerate(f, 1):
                        m = include.match(line)
                        if not m:
                            continue
                        target = None
                        for base in ("renderer", "exporters"):
                            if os.path.exists(os.path.join(repo, base, m.group(1))):
                                target = module_of(base + "/" + m.group(1))
                                break
                        if target is None or target == src:
                            continue
                        if target not in rank:
                            unplaced.add(target)
                        elif rank[target] >= rank[src]:
                            climbs.append(f"{rel}:{number}: module {src} (layer {rank[src]}) includes "
                                          f"{m.group(1)} of module {target} (layer {rank[target]})")
    for u in sorted(unplaced):
        print(f"check-layers: the module {u} is in no layer of scripts/check-layers.py's LAYERS: place it")
    for c in climbs:
        print(c)
    if unplaced:
        return 2
    if climbs:
        print(f"check-layers: {len(climbs)} includes climb to a module at or above their own layer")
        return 1
    print(f"check-layers: {len(rank)} modules in {len(LAYERS)} layers; no include climbs")
    return 0


if __name__ == "__main__":
    sys.exit(main())
