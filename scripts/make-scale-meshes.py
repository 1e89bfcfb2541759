#!/usr/bin/python3
"""Writes finely tessellated (2, 3) torus knots as binary PLY and GLB, for
the model-loading benchmark (tests/bench/model_load_bench.cpp,
docs/model-files.md "Scale").

    scripts/make-scale-meshes.py OUT_DIR [ALONGxAROUND ...]

(Debian's /usr/bin/python3 with python3-numpy, which scripts/install-deps.sh
installs.)

A grid of ALONG x AROUND quads gives 2 x ALONG x AROUND triangles; the
default, 500x100 1000x500 2000x1000, gives 0.1, 1 and 4 million. Files: knot_<T>.ply and
knot_<T>.glb, each with positions and unit normals (float32), shared
vertices (along x around of them) and uint32 indices; the GLB also passes
through one node with the identity transform.

The curve: c(t) = ((R + r cos qt) cos pt, (R + r cos qt) sin pt, r sin qt),
p = 2, q = 3, R = 1, r = 0.4, tube radius 0.12, with the Frenet frame
(N = normalized component of c'' orthogonal to c'; c'' never vanishes on
this knot). The surface point at angle a: c + rho (cos a N + sin a B), its
normal cos a N + sin a B. Quads (i, j) -> (i+1, j) -> (i+1, j+1) -> (i, j+1)
split into two triangles wound counter-clockwise seen from outside.
"""
import json
import math
import os
import struct
import sys

import numpy as np


def knot(along, around, p=2, q=3, R=1.0, r=0.4, rho=0.12):
    # Rings at the middle of each step: the first vertex is then not at
    # x = 1.28, whose float begins with byte 0x0A, which the PLY reader of
    # Assimp 5.2 skips after the header (renderer/geometry/model_file.cpp).
    t = (np.arange(along) + 0.5) * (2.0 * math.pi / along)
    cq, sq, cp, sp = np.cos(q * t), np.sin(q * t), np.cos(p * t), np.sin(p * t)
    rad = R + r * cq
    c = np.stack([rad * cp, rad * sp, r * sq], axis=1)
    d1 = np.stack([-r * q * sq * cp - rad * p * sp, -r * q * sq * sp + rad * p * cp, r * q * cq], axis=1)
    d2 = np.stack([-r * q * q * cq * cp + 2 * r * q * p * sq * sp - rad * p * p * cp,
                   -r * q * q * cq * sp - 2 * r * q * p * sq * cp - rad * p * p * sp,
                   -r * q * q * sq], axis=1)
    T = d1 / np.linalg.norm(d1, axis=1, keepdims=True)
    n = d2 - np.sum(d2 * T, axis=1, keepdims=True) * T
    N = n / np.linalg.norm(n, axis=1, keepdims=True)
    B = np.cross(T, N)
    a = np.linspace(0.0, 2.0 * math.pi, around, endpoint=False)
    ca, sa = np.cos(a)[None, :, None], np.sin(a)[None, :, None]
    normal = ca * N[:, None, :] + sa * B[:, None, :]          # along x around x 3
    pos = c[:, None, :] + rho * normal
    i = np.arange(along)[:, None]
    j = np.arange(around)[None, :]
    v00 = i * around + j
    v10 = ((i + 1) % along) * around + j
    v11 = ((i + 1) % along) * around + (j + 1) % around
    v01 = i * around + (j + 1) % around
    # Outward: the quad's edges along t and along a; (dP/dt x dP/da) . normal
    # decides the order, checked once below.
    tris = np.concatenate([np.stack([v00, v10, v11], -1).reshape(-1, 3),
                           np.stack([v00, v11, v01], -1).reshape(-1, 3)])
    pos = pos.reshape(-1, 3).astype(np.float32)
    normal = normal.reshape(-1, 3).astype(np.float32)
    g = np.cross(pos[tris[0, 1]] - pos[tris[0, 0]], pos[tris[0, 2]] - pos[tris[0, 0]])
    if np.dot(g, normal[tris[0, 0]]) < 0:
        tris = tris[:, [0, 2, 1]]
    return pos, normal, tris.astype(np.uint32)


def write_ply(path, pos, normal, tris):
    head = ("ply\nformat binary_little_endian 1.0\ncomment (2,3) torus knot, scripts/make-scale-meshes.py\n"
            f"element vertex {len(pos)}\nproperty float x\nproperty float y\nproperty float z\n"
            "property float nx\nproperty float ny\nproperty float nz\n"
            f"element face {len(tris)}\nproperty list uchar uint vertex_indices\nend_header\n")
    verts = np.concatenate([pos, normal], axis=1).astype('<f4')
    faces = np.zeros(len(tris), dtype=[('n', 'u1'), ('i', '<u4', (3,))])
    faces['n'] = 3
    faces['i'] = tris
    if verts.tobytes()[:1] == b"\n":
        sys.exit(f"make-scale-meshes: {path}: the binary data would begin with 0x0A (misread by Assimp 5.2)")
    with open(path + ".part", "wb") as f:
        f.write(head.encode("ascii"))
        f.write(verts.tobytes())
        f.write(faces.tobytes())
    os.replace(path + ".part", path)


def write_glb(path, pos, normal, tris):
    pb, nb, ib = pos.astype('<f4').tobytes(), normal.astype('<f4').tobytes(), tris.astype('<u4').tobytes()
    bin_ = pb + nb + ib
    gltf = {
        "asset": {"version": "2.0", "generator": "xval scripts/make-scale-meshes.py"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"name": "knot", "mesh": 0}],
        "meshes": [{"name": "knot", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2}]}],
        "buffers": [{"byteLength": len(bin_)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(pb), "target": 34962},
                        {"buffer": 0, "byteOffset": len(pb), "byteLength": len(nb), "target": 34962},
                        {"buffer": 0, "byteOffset": len(pb) + len(nb), "byteLength": len(ib), "target": 34963}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(pos), "type": "VEC3",
             "min": pos.min(axis=0).tolist(), "max": pos.max(axis=0).tolist()},
            {"bufferView": 1, "componentType": 5126, "count": len(normal), "type": "VEC3"},
            {"bufferView": 2, "componentType": 5125, "count": tris.size, "type": "SCALAR"}],
    }
    js = json.dumps(gltf, separators=(",", ":")).encode()
    js += b" " * (-len(js) % 4)
    bin_ += b"\0" * (-len(bin_) % 4)
    total = 12 + 8 + len(js) + 8 + len(bin_)
    with open(path + ".part", "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, total))
        f.write(struct.pack("<I4s", len(js), b"JSON") + js)
        f.write(struct.pack("<I4s", len(bin_), b"BIN\0") + bin_)
    os.replace(path + ".part", path)


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    sizes = sys.argv[2:] or ["500x100", "1000x500", "2000x1000"]
    os.makedirs(out, exist_ok=True)
    for size in sizes:
        along, around = (int(k) for k in size.split("x"))
        if along < 3 or around < 3:
            sys.exit(f"make-scale-meshes: {size}: both counts must be at least 3")
        pos, normal, tris = knot(along, around)
        base = os.path.join(out, f"knot_{len(tris)}")
        write_ply(base + ".ply", pos, normal, tris)
        write_glb(base + ".glb", pos, normal, tris)
        print(f"{base}.ply/.glb: {along} x {around}: {len(tris)} triangles, {len(pos)} vertices")


if __name__ == "__main__":
    main()
