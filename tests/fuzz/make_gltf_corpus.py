#!/usr/bin/env python3
"""Hand-made .gltf seeds for the gltf and vertex_locks fuzz targets (make_corpus.sh runs it):
buffers as data: URIs, node transforms, a strip with indices, and a _LOCK attribute.
Usage: make_gltf_corpus.py GLTF_DIR LOCKS_DIR"""
import base64
import json
import struct
import sys


def data_uri(data):
    return "data:application/octet-stream;base64," + base64.b64encode(data).decode()


def triangle():
    positions = struct.pack("9f", 0, 0, 0, 1, 0, 0, 0, 0, 1)
    return {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 0, 1]}],
            "bufferViews": [{"buffer": 0, "byteLength": 36}],
            "buffers": [{"byteLength": len(positions), "uri": data_uri(positions)}]}


def strip_with_nodes_and_locks():
    # 4 positions, 4 normals, a u16 strip of 4 indices and a u8 _LOCK, one buffer, two views.
    positions = struct.pack("12f", 0, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0, 1)
    normals = struct.pack("12f", *([0, 1, 0] * 4))
    indices = struct.pack("4H", 0, 1, 2, 3)
    locks = bytes([1, 0, 0, 1])
    buffer = positions + normals + indices + locks
    return {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
            "nodes": [{"children": [1], "translation": [10, 0, 0]}, {"mesh": 0, "scale": [2, 2, 2], "rotation": [0, 0.7071068, 0, 0.7071068]}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "_LOCK": 3}, "indices": 2, "mode": 5}]}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 0, 1]},
                          {"bufferView": 0, "byteOffset": 48, "componentType": 5126, "count": 4, "type": "VEC3"},
                          {"bufferView": 1, "componentType": 5123, "count": 4, "type": "SCALAR"},
                          {"bufferView": 1, "byteOffset": 8, "componentType": 5121, "count": 4, "type": "SCALAR"}],
            "bufferViews": [{"buffer": 0, "byteLength": 96, "byteStride": 12}, {"buffer": 0, "byteOffset": 96, "byteLength": 12}],
            "buffers": [{"byteLength": len(buffer), "uri": data_uri(buffer)}]}


gltf_dir, locks_dir = sys.argv[1], sys.argv[2]
json.dump(triangle(), open(f"{gltf_dir}/triangle.gltf", "w"))
json.dump(strip_with_nodes_and_locks(), open(f"{gltf_dir}/strip.gltf", "w"))
json.dump(strip_with_nodes_and_locks(), open(f"{locks_dir}/strip-locks.gltf", "w"))
# An OBJ whose red vertex colours lock vertices (Blender's "v x y z r g b").
open(f"{locks_dir}/locked.obj", "w").write("v 0 0 0 1 0 0\nv 1 0 0 0 0 0\nv 0 0 1 1 0 0\nv 1 0 1 0.2 0.2 0.2\nf 1 2 3\nf 2 4 3\n")
