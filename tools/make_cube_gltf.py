#!/usr/bin/env python3
"""Writes scenes/meshes/cube.gltf: a unit cube centred on the origin, flat normals, each face its own
cell of a 4 x 3 cross-shaped uv chart (cells 1/4 x 1/3), so uv jumps across most edges: a mesh with
uv seams. Deterministic; run from the repository root: python3 tools/make_cube_gltf.py"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gltf_mesh import write_mesh_gltf  # noqa: E402

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

write_mesh_gltf("scenes/meshes/cube.gltf", "cube", "tools/make_cube_gltf.py", positions, normals, uvs, indices,
                ([-0.5, -0.5, -0.5], [0.5, 0.5, 0.5]))
