"""Checks that Blender reads a "surface_vdb" level set and meshes it where upf's mesh lies: run
    blender -b --factory-startup --python-exit-code 1 --python check_blender_level_set.py -- RUN_DIR

RUN_DIR is a upf run with "formats": ["surface", "surface_vdb"]. For frame 0: File > Import >
OpenVDB (bpy.ops.object.volume_import) gives a volume with one grid named "surface"; a Volume to
Mesh modifier at threshold 0 on it gives a mesh whose bounding box matches that of
frames/surface_00000.ply (parsed here) within one voxel (h/2) on every side. Raises on the
first failure (exit code 1 with --python-exit-code), prints "blender level set ok" at the end.
"""
import os
import struct
import sys

import bpy


def ply_vertex_bounds(path):
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    count = 0
    for line in data[:end].decode("ascii").split("\n"):
        if line.startswith("element vertex"):
            count = int(line.split()[-1])
    xyz = struct.unpack_from("<%df" % (3 * count), data, end)
    lo = [min(xyz[a::3]) for a in range(3)]
    hi = [max(xyz[a::3]) for a in range(3)]
    return lo, hi


def main():
    run = sys.argv[sys.argv.index("--") + 1]
    vdb = os.path.join(run, "frames", "surface_00000.vdb")
    bpy.ops.object.volume_import(filepath=vdb)
    volume = bpy.context.active_object
    if volume is None or volume.type != "VOLUME":
        raise RuntimeError("no volume object from " + vdb)
    volume.data.grids.load()
    names = [g.name for g in volume.data.grids]
    if names != ["surface"]:
        raise RuntimeError("grids %r, expected ['surface']" % names)
    voxel = volume.data.grids[0].matrix_object.to_3x3().col[0].length
    bpy.ops.mesh.primitive_cube_add()
    holder = bpy.context.active_object
    modifier = holder.modifiers.new("surface", "VOLUME_TO_MESH")
    modifier.object = volume
    modifier.grid_name = "surface"
    modifier.threshold = 0.0
    modifier.resolution_mode = "GRID"
    evaluated = holder.evaluated_get(bpy.context.evaluated_depsgraph_get())
    mesh = evaluated.to_mesh()
    if len(mesh.vertices) == 0:
        raise RuntimeError("Volume to Mesh gave no vertices")
    world = holder.matrix_world
    points = [world @ v.co for v in mesh.vertices]
    lo = [min(p[a] for p in points) for a in range(3)]
    hi = [max(p[a] for p in points) for a in range(3)]
    ply_lo, ply_hi = ply_vertex_bounds(os.path.join(run, "frames", "surface_00000.ply"))
    for a in range(3):
        for got, want in ((lo[a], ply_lo[a]), (hi[a], ply_hi[a])):
            if abs(got - want) > voxel:
                raise RuntimeError("axis %d: Blender's mesh reaches %.5f, upf's %.5f (voxel %.5f)"
                                   % (a, got, want, voxel))
    print("blender level set ok: %d vertices, voxel %.5f m, bounds %s to %s"
          % (len(mesh.vertices), voxel, [round(x, 4) for x in lo], [round(x, 4) for x in hi]))


main()
