#!/usr/bin/env python3
"""Writes scenes/meshes/cylinder.gltf: an open cylinder of radius 0.5 and length 4 along x, smooth
normals, uv with u along the axis (so dp/du, the ridge direction of a diffraction grating, runs
along the body like the ridges of a snake's scales) and v around it. Deterministic; run from the
repository root: python3 tools/make_cylinder_gltf.py"""
import base64
import json
import math
import struct

RADIUS, LENGTH, AROUND = 0.5, 4.0, 96

positions, normals, uvs = [], [], []
for ring in range(2):
    x = -LENGTH / 2 + ring * LENGTH
    for i in range(AROUND + 1):  # the seam vertex is repeated so v runs 0..1
        phi = 2 * math.pi * i / AROUND
        n = (0.0, math.cos(phi), math.sin(phi))
        positions.append((x, RADIUS * n[1], RADIUS * n[2]))
        normals.append(n)
        uvs.append((float(ring), i / AROUND))
indices = []
row = AROUND + 1
for i in range(AROUND):
    a, b, c, d = i, i + 1, row + i, row + i + 1
    # Counter-clockwise seen from outside (normal = cross(e1, e2) points outward).
    indices += [a, b, c, b, d, c]

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
    "asset": {"version": "2.0", "generator": "facet tools/make_cylinder_gltf.py"},
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [{"name": "cylinder", "mesh": 0}],
    "meshes": [{"name": "cylinder", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                                    "indices": 3, "mode": 4}]}],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3",
         "min": [-LENGTH / 2, -RADIUS, -RADIUS], "max": [LENGTH / 2, RADIUS, RADIUS]},
        {"bufferView": 1, "componentType": 5126, "count": count, "type": "VEC3"},
        {"bufferView": 2, "componentType": 5126, "count": count, "type": "VEC2"},
        {"bufferView": 3, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
    ],
    "bufferViews": views,
    "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
}
with open("scenes/meshes/cylinder.gltf", "w") as f:
    json.dump(gltf, f, indent=1)
    f.write("\n")
