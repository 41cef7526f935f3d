"""Opens a upf run in Blender as an animated point cloud with its attributes.

Blender 3.4's PLY importer keeps vertex colours only on faces, and drops every other property,
so a upf point cloud (frames/frame_NNNNN.ply, "formats": ["ply"]) comes in grey and bare. This
script reads the same files itself and builds, for the current frame, one mesh of vertices whose
point-domain attributes are every PLY property: the colour by type as the colour attribute
"Col", "id", "type" and "material" as integers, velocity as the vector "velocity", and each
exported field as a float (a vector field as one vector attribute). A frame-change handler loads
the frame of the scene's current frame number, so the timeline plays the run; a Geometry Nodes
modifier turns the vertices into spheres of half the particle spacing, shaded with "Col" (Cycles
renders them; EEVEE in Blender 3.x does not draw point clouds).

Usage, from a shell (the run's frames, with "ply_up": "z" if you want Blender's Z-up):
    blender --python scripts/blender_upf.py -- out/dam_break
or inside Blender, run this file in the Text Editor after setting RUN_DIR below, or
    import blender_upf; blender_upf.load_run("/path/to/out/dam_break")

Blender frame f shows upf frame f (frame 0 is the initial state); the scene's frame range and
frame rate are set to the run's (upf_scene.json's /output/fps). Format of the files read: G. Turk's
PLY as upf writes it (framework/output/ply_points_writer.h): binary little endian, one "vertex"
element, no faces.
"""
import json
import os
import re
import sys

import bpy
import numpy as np

RUN_DIR = None  # set when running this file from Blender's Text Editor

PLY_DTYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "<i2",
              "int16": "<i2", "ushort": "<u2", "uint16": "<u2", "int": "<i4", "int32": "<i4",
              "uint": "<u4", "uint32": "<u4", "float": "<f4", "float32": "<f4",
              "double": "<f8", "float64": "<f8"}
FRAME_NAME = re.compile(r"^frame_(\d{5})\.ply$")
OBJECT_NAME = "upf particles"


def read_ply_points(path):
    """The vertex properties of a upf PLY point cloud, as a NumPy structured array."""
    with open(path, "rb") as f:
        if f.readline().strip() != b"ply":
            raise ValueError(f"{path}: not a PLY file")
        fmt = f.readline().split()
        if fmt[:2] != [b"format", b"binary_little_endian"]:
            raise ValueError(f"{path}: only binary_little_endian PLY is read")
        count, fields, element = 0, [], None
        while True:
            line = f.readline()
            if not line:
                raise ValueError(f"{path}: the header has no end_header")
            words = line.decode("ascii").split()
            if not words or words[0] == "comment":
                continue
            if words[0] == "end_header":
                break
            if words[0] == "element":
                element = words[1]
                if element == "vertex":
                    count = int(words[2])
                elif int(words[2]) > 0:
                    raise ValueError(f"{path}: element {element} is not a point cloud's")
            elif words[0] == "property" and element == "vertex":
                if words[1] == "list":
                    raise ValueError(f"{path}: list properties are not a point cloud's")
                fields.append((words[2], PLY_DTYPES[words[1]]))
        data = np.frombuffer(f.read(), dtype=np.dtype(fields), count=count)
    return data


def run_frames(run_dir):
    """{frame number: path} of the run's PLY point clouds."""
    frames = {}
    folder = os.path.join(run_dir, "frames")
    for name in os.listdir(folder):
        m = FRAME_NAME.match(name)
        if m:
            frames[int(m.group(1))] = os.path.join(folder, name)
    if not frames:
        raise ValueError(f"{folder}: no frame_NNNNN.ply (does the scene's /output/formats "
                         "list \"ply\"?)")
    return frames


def srgb_to_linear(c):
    """The PLY's 8-bit colours are sRGB; Blender's float colours are linear (IEC 61966-2-1)."""
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def _vector_groups(names):
    """Fields written as NAME_x, NAME_y, NAME_z: {NAME: [the three names]}."""
    groups = {}
    for n in names:
        if n.endswith("_x") and n[:-2] + "_y" in names and n[:-2] + "_z" in names:
            groups[n[:-2]] = [n, n[:-2] + "_y", n[:-2] + "_z"]
    return groups


def build_mesh(data, name):
    """A mesh of one vertex per particle with the PLY properties as point attributes."""
    mesh = bpy.data.meshes.new(name)
    n = len(data)
    mesh.vertices.add(n)
    xyz = np.column_stack([data["x"], data["y"], data["z"]]).astype(np.float32)
    mesh.vertices.foreach_set("co", xyz.ravel())
    names = list(data.dtype.names)
    used = {"x", "y", "z", "red", "green", "blue"}
    if {"red", "green", "blue"} <= set(names):
        rgba = np.ones((n, 4), dtype=np.float32)
        for k, c in enumerate(("red", "green", "blue")):
            rgba[:, k] = srgb_to_linear(data[c].astype(np.float32) / 255.0)
        # Float colours: Cycles 3.4 reads no byte colours on the points Geometry Nodes make.
        col = mesh.color_attributes.new("Col", "FLOAT_COLOR", "POINT")
        col.data.foreach_set("color", rgba.ravel())
    vectors = {"velocity": ["vx", "vy", "vz"]} if {"vx", "vy", "vz"} <= set(names) else {}
    vectors.update(_vector_groups(names))
    for vname, parts in vectors.items():
        a = mesh.attributes.new(vname, "FLOAT_VECTOR", "POINT")
        a.data.foreach_set("vector", np.column_stack([data[p] for p in parts])
                           .astype(np.float32).ravel())
        used.update(parts)
    for pname in names:
        if pname in used:
            continue
        kind = data.dtype[pname].kind
        if kind in "iu":
            a = mesh.attributes.new(pname, "INT", "POINT")
            a.data.foreach_set("value", data[pname].astype(np.int32))
        else:
            a = mesh.attributes.new(pname, "FLOAT", "POINT")
            a.data.foreach_set("value", data[pname].astype(np.float32))
    mesh.update()
    return mesh


def _points_modifier(obj, radius):
    """Geometry Nodes: vertices to spheres of `radius`, with a material shaded by "Col"."""
    material = bpy.data.materials.new("upf particles")
    material.use_nodes = True
    nodes = material.node_tree.nodes
    attribute = nodes.new("ShaderNodeAttribute")
    attribute.attribute_name = "Col"
    bsdf = nodes["Principled BSDF"]
    material.node_tree.links.new(attribute.outputs["Color"], bsdf.inputs["Base Color"])

    tree = bpy.data.node_groups.new("upf points", "GeometryNodeTree")
    tree.inputs.new("NodeSocketGeometry", "Geometry")
    tree.outputs.new("NodeSocketGeometry", "Geometry")
    group_in = tree.nodes.new("NodeGroupInput")
    group_out = tree.nodes.new("NodeGroupOutput")
    to_points = tree.nodes.new("GeometryNodeMeshToPoints")
    to_points.inputs["Radius"].default_value = radius
    set_material = tree.nodes.new("GeometryNodeSetMaterial")
    set_material.inputs["Material"].default_value = material
    tree.links.new(group_in.outputs["Geometry"], to_points.inputs["Mesh"])
    tree.links.new(to_points.outputs["Points"], set_material.inputs["Geometry"])
    tree.links.new(set_material.outputs["Geometry"], group_out.inputs["Geometry"])
    modifier = obj.modifiers.new("upf points", "NODES")
    modifier.node_group = tree


def _run_settings(run_dir):
    """(fps, spacing) from the run's upf_scene.json (scene.json in older runs); (30, 0.02) when it
    is missing."""
    record = os.path.join(run_dir, "upf_scene.json")
    if not os.path.exists(record):
        record = os.path.join(run_dir, "scene.json")
    try:
        with open(record) as f:
            scene = json.load(f)
        return (float(scene.get("output", {}).get("fps", 30)),
                float(scene.get("particle_spacing", 0.02)))
    except (OSError, ValueError):
        return 30.0, 0.02


def show_frame(obj, frames, frame):
    """Replaces the object's mesh with upf frame `frame` (the nearest earlier one written)."""
    available = [f for f in frames if f <= frame]
    number = max(available) if available else min(frames)
    old = obj.data
    obj.data = build_mesh(read_ply_points(frames[number]), f"upf frame {number}")
    obj["upf_frame"] = number
    if old is not None and old.users == 0:
        bpy.data.meshes.remove(old)


def load_run(run_dir):
    """Adds the run as object "upf particles", animated by the timeline. Returns the object."""
    run_dir = os.path.abspath(run_dir)
    frames = run_frames(run_dir)
    fps, spacing = _run_settings(run_dir)
    scene = bpy.context.scene
    mesh = build_mesh(read_ply_points(frames[min(frames)]), f"upf frame {min(frames)}")
    obj = bpy.data.objects.new(OBJECT_NAME, mesh)
    obj["upf_run"] = run_dir
    obj["upf_frame"] = min(frames)
    scene.collection.objects.link(obj)
    _points_modifier(obj, 0.5 * spacing)
    scene.frame_start, scene.frame_end = min(frames), max(frames)
    scene.render.fps = max(1, round(fps))
    scene.render.fps_base = scene.render.fps / fps

    def on_frame(scene_now, *_):
        for o in scene_now.objects:
            if o.get("upf_run") == run_dir:
                show_frame(o, frames, scene_now.frame_current)

    bpy.app.handlers.frame_change_pre.append(on_frame)
    return obj


if __name__ == "__main__":
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    target = argv[0] if argv else RUN_DIR
    if not target:
        print("usage: blender --python scripts/blender_upf.py -- RUN_DIR", file=sys.stderr)
    else:
        load_run(target)
