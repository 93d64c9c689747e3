#!/usr/bin/env python3
"""Writes scenes/meshes/cylinder.gltf: an open cylinder of radius 0.5 and length 4 along x, smooth
normals, uv with u along the axis (so dp/du, the ridge direction of a diffraction grating, runs
along the body like the ridges of a snake's scales) and v around it. Deterministic; run from the
repository root: python3 tools/make_cylinder_gltf.py"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gltf_mesh import write_mesh_gltf  # noqa: E402
import math

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

write_mesh_gltf("scenes/meshes/cylinder.gltf", "cylinder", "tools/make_cylinder_gltf.py", positions, normals, uvs, indices,
                ([-LENGTH / 2, -RADIUS, -RADIUS], [LENGTH / 2, RADIUS, RADIUS]))
