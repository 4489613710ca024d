#!/usr/bin/env python3
"""Writes tests/data/tangent_quad.gltf: one quad with POSITION, NORMAL, TEXCOORD_0 and a TANGENT
attribute that deliberately disagrees with the UVs (it points along +Z, the UVs' u runs along +X),
so a test can tell the file's tangents from generated ones. usage: tools/make_tangent_quad.py OUT"""
import base64, json, struct, sys

positions = [(-1, 0, -1), (1, 0, -1), (1, 0, 1), (-1, 0, 1)]
normals = [(0, 1, 0)] * 4
uvs = [(0, 0), (1, 0), (1, 1), (0, 1)]
tangents = [(0, 0, 1, 1)] * 4
indices = [0, 2, 1, 0, 3, 2]
blob = b"".join(struct.pack("<3f", *p) for p in positions) + b"".join(struct.pack("<3f", *n) for n in normals) \
    + b"".join(struct.pack("<2f", *t) for t in uvs) + b"".join(struct.pack("<4f", *t) for t in tangents) \
    + b"".join(struct.pack("<H", i) for i in indices)
views, offset = [], 0
for size in (48, 48, 32, 64, 12):
    views.append({"buffer": 0, "byteOffset": offset, "byteLength": size})
    offset += size
accessors = [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, 0, -1], "max": [1, 0, 1]},
    {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
    {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
    {"bufferView": 3, "componentType": 5126, "count": 4, "type": "VEC4"},
    {"bufferView": 4, "componentType": 5123, "count": 6, "type": "SCALAR"},
]
gltf = {
    "asset": {"version": "2.0", "generator": "tools/make_tangent_quad.py"},
    "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2, "TANGENT": 3},
                                "indices": 4}]}],
    "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
    "bufferViews": views, "accessors": accessors,
}
with open(sys.argv[1], "w") as f:
    json.dump(gltf, f, indent=1)
    f.write("\n")
