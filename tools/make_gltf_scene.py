#!/usr/bin/env python3
"""Writes scenes/gltf_courtyard.gltf: a small glTF 2.0 scene laid out as a DCC tool exports one
(+y up, metres, a node hierarchy), rendered by `facet render scenes/gltf_courtyard.gltf` without a
JSON scene (scenes/README.md, "glTF scenes"). A parent "Stage" node turns and moves a floor and two
boxes; a "CameraRig" carries an animated perspective camera (2 s at 24 fps: 49 frames for
`facet batch`); a "Sun" node carries a KHR_lights_punctual directional light. Materials: a
colour-mapped fBm floor and GGX microflake gold through `extras.facet`, and a clay box with only a
glTF base colour (facet's fallback: Lambert with that albedo). Deterministic; run from the
repository root: python3 tools/make_gltf_scene.py"""
import base64
import json
import math
import struct


def quat(axis, degrees):
    """(x, y, z, w) of a rotation by `degrees` about the unit `axis`."""
    s = math.sin(math.radians(degrees) / 2)
    return [axis[0] * s, axis[1] * s, axis[2] * s, math.cos(math.radians(degrees) / 2)]


def qmul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz]


# Geometry: a floor quad (8 x 8 m, uv 0..2) and a unit cube with one normal per face, counter-clockwise
# seen from outside.
floor = {"P": [(-4, 0, 4), (4, 0, 4), (4, 0, -4), (-4, 0, -4)], "N": [(0, 1, 0)] * 4,
         "T": [(0, 0), (2, 0), (2, 2), (0, 2)], "I": [0, 1, 2, 0, 2, 3]}
cube = {"P": [], "N": [], "T": [], "I": []}
for axis in range(3):
    for sign in (1, -1):
        n = [0, 0, 0]
        n[axis] = sign
        u = [0, 0, 0]
        u[(axis + 1) % 3] = 1
        v = [n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]]  # n x u
        base = len(cube["P"])
        for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            cube["P"].append(tuple(0.5 * (n[k] + a * u[k] + b * v[k]) for k in range(3)))
            cube["N"].append(tuple(n))
            cube["T"].append(((a + 1) / 2, (b + 1) / 2))
        cube["I"] += [base, base + 1, base + 2, base, base + 2, base + 3]

blob = bytearray()
views, accessors = [], []


def add(values, fmt, component_type, gltf_type, minmax=False):
    while len(blob) % 4:
        blob.append(0)
    offset = len(blob)
    for v in values:
        blob.extend(struct.pack(fmt, *(v if isinstance(v, (tuple, list)) else (v,))))
    views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(blob) - offset})
    accessor = {"bufferView": len(views) - 1, "componentType": component_type, "count": len(values), "type": gltf_type}
    if minmax:
        accessor["min"] = [min(v[k] for v in values) for k in range(len(values[0]))]
        accessor["max"] = [max(v[k] for v in values) for k in range(len(values[0]))]
    accessors.append(accessor)
    return len(accessors) - 1


def primitive(mesh, material):
    return {"attributes": {"POSITION": add(mesh["P"], "<3f", 5126, "VEC3", True),
                           "NORMAL": add(mesh["N"], "<3f", 5126, "VEC3"),
                           "TEXCOORD_0": add(mesh["T"], "<2f", 5126, "VEC2")},
            "indices": add(mesh["I"], "<H", 5123, "SCALAR"), "mode": 4, "material": material}


meshes = [{"name": "Floor", "primitives": [primitive(floor, 0)]},
          {"name": "Crate", "primitives": [primitive(cube, 1)]},
          {"name": "Pedestal", "primitives": [primitive(cube, 2)]}]

# The camera: 2 s, keys at 0, 1, 2 s; it swings right and comes closer, yawing about the world's +y
# then pitching down about its own x (no roll, as a camera path requires).
times = [0.0, 1.0, 2.0]
positions = [(0.0, 0.4, 6.0), (2.0, 0.6, 5.2), (3.5, 0.9, 3.8)]
yaws, pitch = [0.0, 18.0, 38.0], -12.0
rotations = [qmul(quat((0, 1, 0), y), quat((1, 0, 0), pitch)) for y in yaws]
animation = {"name": "CameraMove", "samplers": [
    {"input": add(times, "<f", 5126, "SCALAR", False), "output": add(positions, "<3f", 5126, "VEC3"),
     "interpolation": "LINEAR"},
    {"input": len(accessors) - 2, "output": add(rotations, "<4f", 5126, "VEC4"), "interpolation": "LINEAR"}],
    "channels": [{"sampler": 0, "target": {"node": 6, "path": "translation"}},
                 {"sampler": 1, "target": {"node": 6, "path": "rotation"}}]}
accessors[animation["samplers"][0]["input"]].update({"min": [times[0]], "max": [times[-1]]})

gltf = {
    "asset": {"version": "2.0", "generator": "facet tools/make_gltf_scene.py"},
    "extensionsUsed": ["KHR_lights_punctual"],
    "extensions": {"KHR_lights_punctual": {"lights": [
        {"name": "Sun", "type": "directional", "color": [1.0, 0.95, 0.85], "intensity": 2.6}]}},
    "extras": {"facet": {"ambient": [0.18, 0.18, 0.22], "background": [0.55, 0.65, 0.8]}},
    "scene": 0,
    "scenes": [{"name": "Courtyard", "nodes": [0, 4, 7]}],
    "nodes": [
        {"name": "Stage", "children": [1, 2, 3], "translation": [0, 0, -0.5], "rotation": quat((0, 1, 0), 15)},
        {"name": "Floor", "mesh": 0},
        {"name": "Crate", "mesh": 1, "translation": [-1.0, 0.5, 0.0], "rotation": quat((0, 1, 0), 25)},
        {"name": "Pedestal", "mesh": 2, "translation": [1.4, 0.6, -0.5], "scale": [0.6, 1.2, 0.6]},
        {"name": "CameraRig", "children": [5, 6], "translation": [0, 1.2, 0]},
        {"name": "RigMarker"},
        {"name": "Camera", "camera": 0, "translation": list(positions[0]), "rotation": rotations[0]},
        {"name": "Sun", "rotation": qmul(quat((0, 1, 0), 35), quat((1, 0, 0), -50)),
         "extensions": {"KHR_lights_punctual": {"light": 0}}},
    ],
    "cameras": [{"name": "Lens", "type": "perspective",
                 "perspective": {"yfov": math.radians(40), "aspectRatio": 16 / 9, "znear": 0.05, "zfar": 100}}],
    "materials": [
        {"name": "Ground", "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.5, 1]},
         "extras": {"facet": {"type": "colormap_texture",
                              "texture": {"noise": {"width": 128, "height": 128, "octaves": 5, "base_frequency": 4,
                                                    "seed": 3}},
                              "colormap": {"points": [[0.0, [0.1, 0.1, 0.35]], [0.5, [0.9, 0.85, 0.7]],
                                                      [0.6, [0.6, 0.2, 0.05]]], "interpolation": "steps"}}}},
        {"name": "Gold", "pbrMetallicRoughness": {"baseColorFactor": [1.0, 0.77, 0.34, 1], "metallicFactor": 1},
         "extras": {"facet": {"type": "microflake", "ndf": "ggx", "param": 0.25, "albedo": [1.0, 0.77, 0.34]}}},
        {"name": "Clay", "pbrMetallicRoughness": {"baseColorFactor": [0.7, 0.35, 0.25, 1]}},
    ],
    "meshes": meshes,
    "animations": [animation],
    "accessors": accessors,
    "bufferViews": views,
    "buffers": [{"byteLength": len(blob),
                 "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode()}],
}
with open("scenes/gltf_courtyard.gltf", "w") as f:
    json.dump(gltf, f, indent=1)
    f.write("\n")
