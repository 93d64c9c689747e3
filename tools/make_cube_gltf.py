#!/usr/bin/env python3
"""Writes scenes/meshes/cube.gltf: a unit cube centred on the origin, flat normals, each face its own
cell of a 4 x 3 cross-shaped uv chart (cells 1/4 x 1/3), so uv jumps across most edges: a mesh with
uv seams. Deterministic; run from the repository root: python3 tools/make_cube_gltf.py"""
import base64
import json
import struct

# Per face: normal n, in-face axes s, t with s x t = n, and the chart cell (column, row) it occupies.
FACES = [
    ((-1, 0, 0), (0, 0, 1), (0, 1, 0), (0, 1)),
    ((0, 0, 1), (1, 0, 0), (0, 1, 0), (1, 1)),
    ((1, 0, 0), (0, 0, -1), (0, 1, 0), (2, 1)),
    ((0, 0, -1), (-1, 0, 0), (0, 1, 0), (3, 1)),
    ((0, 1, 0), (1, 0, 0), (0, 0, -1), (1, 2)),
    ((0, -1, 0), (1, 0, 0), (0, 0, 1), (1, 0)),
]

positions, normals, uvs, indices = [], [], [], []
for n, s, t, (col, row) in FACES:
    base = len(positions)
    for a, b in ((0, 0), (1, 0), (1, 1), (0, 1)):  # counter-clockwise seen from outside
        positions.append(tuple(0.5 * n[k] + (a - 0.5) * s[k] + (b - 0.5) * t[k] for k in range(3)))
        normals.append(tuple(float(x) for x in n))
        uvs.append(((col + a) / 4, (row + b) / 3))
    indices += [base, base + 1, base + 2, base, base + 2, base + 3]

def pack(fmt, items):
    return b"".join(struct.pack(fmt, *item) for item in items)

blobs = [pack("<3f", positions), pack("<3f", normals), pack("<2f", uvs), struct.pack(f"<{len(indices)}H", *indices)]
views, offset = [], 0
for blob, target in zip(blobs, [34962, 34962, 34962, 34963]):
    views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(blob), "target": target})
    offset += len(blob)
data = b"".join(blobs)
count = len(positions)
gltf = {
    "asset": {"version": "2.0", "generator": "facet tools/make_cube_gltf.py"},
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [{"name": "cube", "mesh": 0}],
    "meshes": [{"name": "cube", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                                "indices": 3, "mode": 4}]}],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3",
         "min": [-0.5, -0.5, -0.5], "max": [0.5, 0.5, 0.5]},
        {"bufferView": 1, "componentType": 5126, "count": count, "type": "VEC3"},
        {"bufferView": 2, "componentType": 5126, "count": count, "type": "VEC2"},
        {"bufferView": 3, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
    ],
    "bufferViews": views,
    "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
}
with open("scenes/meshes/cube.gltf", "w") as f:
    json.dump(gltf, f, indent=1)
    f.write("\n")
