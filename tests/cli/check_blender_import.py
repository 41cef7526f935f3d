"""Checks scripts/blender_upf.py inside Blender: run with
    blender -b --factory-startup --python-exit-code 1 --python check_blender_import.py -- RUN_DIR

RUN_DIR is a upf run with "formats": ["ply"] (at least three frames). Checks, against the PLY
files parsed here without Blender (struct): the object "upf particles" has one vertex per
particle at the frame's positions; its colour attribute "Col" is on the point domain and holds
the PLY's red, green and blue (sRGB bytes) as linear floats; "id", "type" and "velocity" are point attributes with the
PLY's values; setting the scene to frame 2 loads frame 2's positions. Raises (exit code 1 with
--python-exit-code) on the first failure, prints "blender import ok" at the end.
"""
import os
import struct
import sys

import bpy

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(SOURCE, "scripts"))
import blender_upf  # noqa: E402

TYPES = {"float": "f", "uint8": "B", "uint16": "H", "uint32": "I", "uchar": "B",
         "ushort": "H", "uint": "I"}


def ply_records(path):
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    props, count = [], 0
    for line in data[:end].decode("ascii").split("\n"):
        words = line.split()
        if words[:2] == ["element", "vertex"]:
            count = int(words[2])
        elif words[:1] == ["property"]:
            props.append((words[2], TYPES[words[1]]))
    fmt = "<" + "".join(t for _, t in props)
    names = [n for n, _ in props]
    return [dict(zip(names, r)) for r in struct.iter_unpack(fmt, data[end:end + count *
                                                                         struct.calcsize(fmt)])]


def expect(ok, message):
    if not ok:
        raise AssertionError(message)


def check_frame(obj, records, frame):
    mesh = obj.data
    expect(len(mesh.vertices) == len(records),
           f"frame {frame}: {len(mesh.vertices)} vertices for {len(records)} particles")
    for i in (0, len(records) // 2, len(records) - 1):
        r, v = records[i], mesh.vertices[i].co
        expect(all(abs(a - b) < 1e-6 for a, b in zip(v, (r["x"], r["y"], r["z"]))),
               f"frame {frame}: vertex {i} at {tuple(v)}, the PLY says {r['x'], r['y'], r['z']}")


def main():
    run_dir = sys.argv[sys.argv.index("--") + 1]
    frames = blender_upf.run_frames(run_dir)
    expect(len(frames) >= 3, f"{run_dir}: {len(frames)} PLY frames, the check needs 3")
    obj = blender_upf.load_run(run_dir)
    first = ply_records(frames[0])
    check_frame(obj, first, 0)
    mesh = obj.data
    col = mesh.color_attributes.get("Col")
    expect(col is not None and col.domain == "POINT", "no point-domain colour attribute 'Col'")
    for i in range(len(first)):
        c = col.data[i].color
        want = tuple(float(blender_upf.srgb_to_linear(first[i][k] / 255))
                     for k in ("red", "green", "blue"))
        expect(all(abs(a - b) < 1e-5 for a, b in zip(c[:3], want)),
               f"vertex {i}: colour {tuple(c)}, the PLY says {want}")
    for name, key in (("id", "id"), ("type", "type")):
        a = mesh.attributes.get(name)
        expect(a is not None and a.domain == "POINT" and a.data_type == "INT",
               f"no integer point attribute '{name}'")
        expect([d.value for d in a.data] == [r[key] for r in first],
               f"attribute '{name}' differs from the PLY")
    velocity = mesh.attributes.get("velocity")
    expect(velocity is not None and velocity.data_type == "FLOAT_VECTOR", "no 'velocity' vector")
    expect(len(mesh.attributes.get("density").data) == len(first), "no 'density' attribute")
    expect(obj.modifiers.get("upf points") is not None, "no Geometry Nodes points modifier")

    bpy.context.scene.frame_set(2)
    expect(obj["upf_frame"] == 2, f"frame 2 shows upf frame {obj['upf_frame']}")
    later = ply_records(frames[2])
    check_frame(obj, later, 2)
    expect(any(abs(a["y"] - b["y"]) > 1e-7 for a, b in zip(first, later)),
           "frames 0 and 2 have the same positions: the check could not see a frame change")
    print(f"blender import ok: {len(first)} particles, {len(frames)} frames")


main()
