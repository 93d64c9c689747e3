"""One indexed triangle mesh (positions, normals, uvs) as a self-contained glTF 2.0 file with its buffer
embedded as a data URI: what tools/make_*_gltf.py write into scenes/meshes/."""
import base64
import json
import struct


def _pack(fmt, items):
    return b"".join(struct.pack(fmt, *item) for item in items)


def write_mesh_gltf(path, name, generator, positions, normals, uvs, indices, bounds):
    """bounds: (min, max) of the positions, as the POSITION accessor states them."""
    blobs = [_pack("<3f", positions), _pack("<3f", normals), _pack("<2f", uvs),
             struct.pack(f"<{len(indices)}H", *indices)]
    views, offset = [], 0
    for blob, target in zip(blobs, [34962, 34962, 34962, 34963]):
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(blob), "target": target})
        offset += len(blob)
    data = b"".join(blobs)
    count = len(positions)
    gltf = {
        "asset": {"version": "2.0", "generator": "facet " + generator},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": name, "mesh": 0}],
        "meshes": [{"name": name, "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                                  "indices": 3, "mode": 4}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3",
             "min": list(bounds[0]), "max": list(bounds[1])},
            {"bufferView": 1, "componentType": 5126, "count": count, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": count, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        ],
        "bufferViews": views,
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
    }
    with open(path, "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")
