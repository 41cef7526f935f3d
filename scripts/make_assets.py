#!/usr/bin/env python3
"""Writes the meshes upf ships (assets/meshes/) and the broken meshes its tests read
(tests/data/meshes/). Plain Python, no packages, no network; the output is byte-for-byte the same
on every run, so `git diff` after re-running shows nothing.

Shipped meshes (all closed, consistently oriented, counter-clockwise seen from outside):
  unit_box.obj       side 1 m, centred at the origin, 6 quads (the loader triangulates them)
  icosphere.ply      radius 0.5 m, icosahedron subdivided 4 times (2562 vertices, 5120 triangles),
                     binary PLY. Its volume is 0.22 % and its inertia 0.36 % below the true sphere's.
  torus.glb          non-convex: major radius 0.35 m, minor radius 0.15 m, 96 x 48 segments,
                     binary glTF 2.0. Its volume is 0.36 % below the true torus's (2 pi^2 R r^2).
  l_block_mm.stl     non-convex L-shaped block in MILLIMETRES (40 x 40 x 20 mm with a 20 x 20 mm
                     notch), binary STL, as CAD programs write them. Exact mass properties.
Test meshes (tests/data/meshes/):
  open_box.obj       unit box without its top face: not closed
  empty.obj          vertices but no faces
  flat.obj           triangles whose vertices lie on one line: zero area everywhere
  not_a_mesh.txt     text in a format no mesh reader knows
  garbage.stl        pseudo-random bytes
  two_boxes.gltf     one box mesh instanced by two nodes under a translated parent; the second node
                     mirrors (scale -1 in x) and stretches (2 in y): tests node transforms, merging
                     and winding repair. Text glTF with the buffer embedded as a base64 data URI.

Usage: scripts/make_assets.py   (from anywhere; paths are relative to the repository)
"""
import base64
import json
import math
import pathlib
import struct

ROOT = pathlib.Path(__file__).resolve().parent.parent
ASSETS = ROOT / "assets" / "meshes"
TEST_DATA = ROOT / "tests" / "data" / "meshes"


# ---- shapes: (vertices, faces); faces are tuples of vertex indices, counter-clockwise from outside


def box(half=0.5):
    h = half
    v = [(-h, -h, -h), (h, -h, -h), (h, h, -h), (-h, h, -h),
         (-h, -h, h), (h, -h, h), (h, h, h), (-h, h, h)]
    quads = [(0, 3, 2, 1),  # z = -h
             (4, 5, 6, 7),  # z = +h
             (0, 1, 5, 4),  # y = -h
             (2, 3, 7, 6),  # y = +h
             (0, 4, 7, 3),  # x = -h
             (1, 2, 6, 5)]  # x = +h
    return v, quads


def triangulate(faces):
    return [(f[0], f[i], f[i + 1]) for f in faces for i in range(1, len(f) - 1)]


def icosphere(level, radius):
    t = (1 + 5 ** 0.5) / 2
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
         (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    v = [normalized(p) for p in v]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(level):
        midpoints = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoints:
                v.append(normalized([(v[a][i] + v[b][i]) / 2 for i in range(3)]))
                midpoints[key] = len(v) - 1
            return midpoints[key]

        split = []
        for a, b, c in f:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            split += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = split
    return [tuple(radius * x for x in p) for p in v], f


def normalized(p):
    n = math.sqrt(sum(x * x for x in p))
    return tuple(x / n for x in p)


def torus(major, minor, n_major, n_minor):
    v = []
    for i in range(n_major):
        u = 2 * math.pi * i / n_major
        for j in range(n_minor):
            w = 2 * math.pi * j / n_minor
            ring = major + minor * math.cos(w)
            v.append((ring * math.cos(u), ring * math.sin(u), minor * math.sin(w)))
    f = []
    for i in range(n_major):
        for j in range(n_minor):
            a = i * n_minor + j
            b = ((i + 1) % n_major) * n_minor + j
            c = ((i + 1) % n_major) * n_minor + (j + 1) % n_minor
            d = i * n_minor + (j + 1) % n_minor
            f += [(a, b, c), (a, c, d)]
    return v, f


def l_block():
    """The L-shaped outline (counter-clockwise in xy) extruded from z = 0 to 20, in mm."""
    outline = [(0, 0), (40, 0), (40, 20), (20, 20), (20, 40), (0, 40)]
    n = len(outline)
    v = [(x, y, 0) for x, y in outline] + [(x, y, 20) for x, y in outline]
    # A fan from (0, 0) stays inside the L: the only reflex corner is (20, 20).
    bottom = [(0, i + 1, i) for i in range(1, n - 1)]
    top = [(n, n + i, n + i + 1) for i in range(1, n - 1)]
    sides = [(i, (i + 1) % n, n + (i + 1) % n, n + i) for i in range(n)]
    return v, bottom + top + triangulate(sides)


# ---- writers


def write(path, data):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data)
    print(f"wrote {path.relative_to(ROOT)} ({len(data)} bytes)")


def number(x):
    return f"{x:.9g}"


def obj_text(vertices, faces, comment):
    lines = [f"# {comment}"]
    lines += ["v " + " ".join(number(x) for x in p) for p in vertices]
    lines += ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    return ("\n".join(lines) + "\n").encode()


def ply_binary(vertices, triangles, comment):
    header = ("ply\nformat binary_little_endian 1.0\n"
              f"comment {comment}\n"
              f"element vertex {len(vertices)}\n"
              "property float x\nproperty float y\nproperty float z\n"
              f"element face {len(triangles)}\n"
              "property list uchar int vertex_indices\nend_header\n").encode()
    body = b"".join(struct.pack("<3f", *p) for p in vertices)
    body += b"".join(struct.pack("<B3i", 3, *t) for t in triangles)
    return header + body


def stl_binary(vertices, triangles, comment):
    # The 80-byte header must not start with "solid", or readers take the file for ASCII STL.
    out = comment.encode()[:80].ljust(80, b" ") + struct.pack("<I", len(triangles))
    for t in triangles:
        a, b, c = (vertices[i] for i in t)
        out += struct.pack("<3f", *normalized(cross(sub(b, a), sub(c, a))))
        out += struct.pack("<9f", *a, *b, *c) + struct.pack("<H", 0)
    return out


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def gltf_document(vertices, triangles, nodes):
    """glTF 2.0 (https://registry.khronos.org/glTF/specs/2.0/glTF-2.0.html): one mesh with float
    positions and uint16 indices in one buffer; `nodes` are the scene's nodes (they refer to mesh
    0); node 0 is the scene's root."""
    positions = b"".join(struct.pack("<3f", *p) for p in vertices)
    indices = b"".join(struct.pack("<3H", *t) for t in triangles)
    buffer = positions + indices + b"\0" * (-len(indices) % 4)
    lo = [min(p[i] for p in vertices) for i in range(3)]
    hi = [max(p[i] for p in vertices) for i in range(3)]
    document = {
        "asset": {"version": "2.0", "generator": "upf scripts/make_assets.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": nodes,
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
        "buffers": [{"byteLength": len(buffer)}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": len(positions), "target": 34962},
            {"buffer": 0, "byteOffset": len(positions), "byteLength": len(indices),
             "target": 34963}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(vertices), "type": "VEC3",
             "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5123, "count": 3 * len(triangles),
             "type": "SCALAR"}],
    }
    return document, buffer


def glb(document, buffer):
    text = json.dumps(document, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    chunks = struct.pack("<I4s", len(text), b"JSON") + text
    chunks += struct.pack("<I4s", len(buffer), b"BIN\0") + buffer
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


def gltf_text(document, buffer):
    document["buffers"][0]["uri"] = ("data:application/octet-stream;base64," +
                                     base64.b64encode(buffer).decode())
    return (json.dumps(document, indent=1) + "\n").encode()


def pseudo_random_bytes(count, seed):
    out = bytearray()
    state = seed
    for _ in range(count):
        state = (6364136223846793005 * state + 1442695040888963407) % 2 ** 64
        out.append(state >> 56)
    return bytes(out)


def main():
    v, quads = box()
    write(ASSETS / "unit_box.obj", obj_text(v, quads, "upf unit box: side 1 m, centred at 0"))
    v, f = icosphere(4, 0.5)
    write(ASSETS / "icosphere.ply", ply_binary(v, f, "upf icosphere: radius 0.5 m, level 4"))
    v, f = torus(0.35, 0.15, 96, 48)
    document, buffer = gltf_document(v, f, [{"name": "torus", "mesh": 0}])
    write(ASSETS / "torus.glb", glb(document, buffer))
    v, f = l_block()
    write(ASSETS / "l_block_mm.stl", stl_binary(v, f, "upf L-shaped block, millimetres"))

    v, quads = box()
    write(TEST_DATA / "open_box.obj", obj_text(v, quads[:1] + quads[2:], "box without its top"))
    write(TEST_DATA / "empty.obj", obj_text(v, [], "vertices but no faces"))
    line = [(0, 0, 0), (1, 0, 0), (2, 0, 0), (3, 0, 0)]
    write(TEST_DATA / "flat.obj", obj_text(line, [(0, 1, 2), (1, 2, 3)], "collinear triangles"))
    write(TEST_DATA / "not_a_mesh.txt", b"This is a note, not a mesh.\n")
    write(TEST_DATA / "garbage.stl", pseudo_random_bytes(1000, 7))
    v, quads = box()
    nodes = [{"name": "parent", "translation": [0, 0, 5], "children": [1, 2]},
             {"name": "left", "mesh": 0, "translation": [-1, 0, 0]},
             {"name": "right_mirrored", "mesh": 0, "translation": [1, 0, 0], "scale": [-1, 2, 1]}]
    document, buffer = gltf_document(v, triangulate(quads), nodes)
    write(TEST_DATA / "two_boxes.gltf", gltf_text(document, buffer))


if __name__ == "__main__":
    main()
