#!/usr/bin/env python3
"""Opens a run's frames with VTK's own readers, as ParaView does, and checks what they hold.

Usage: python3 check_vtk_series.py RUN_DIR SCENE_JSON DENSITY_FRAME DENSITY_TOLERANCE

RUN_DIR is what `upf run SCENE_JSON --out RUN_DIR` wrote, with "formats": ["vtp", "ply"] and
"fields" naming at least "density" and "pressure". The scene must hold one container and one
liquid block (the liquid gets ids in lattice order, after the walls). With the default
"frozen": "once" the walls are in frames/frozen.vtp, part 1 of every time step, and the scene
must leave them out of the PLY files too ("types": {"ply": [...]} without "frozen"), so that
frame and point cloud hold the same particles in the same order.

Checks:
- particles.pvd (parsed with xml.etree) lists summary.json's frame count, at increasing times
  from 0, and frames/ holds exactly those .vtp files and one .ply per frame;
- frames/frozen.vtp, when the .pvd lists it: part 1 of every time step, frozen particles only,
  whose ids and the frames' make up summary.json's particle count without overlap;
- each .vtp, read by vtk.vtkXMLPolyDataReader, has summary.json's particle count as points and
  as vertex cells, the arrays id, type, material (one component, integer types), velocity
  (three), density and pressure (one); unique ids, types 0..3, as many liquid as summary.json says;
- each frame's .ply, read by vtk.vtkPLYReader, has the same points in the same order, with one
  colour per type; its header, parsed here, lists the properties the docs give, and its binary
  records carry the same ids, types, materials, velocities, densities and pressures; meshio
  (when installed) reads the same points, colours and ids;
- frame 0: the liquid sits on the block's lattice, min + (i + 1/2, j + 1/2, k + 1/2) * spacing,
  i fastest (framework/scene/scene_builder.cpp, docs/scene-format.md "Fluid lattice"), to float
  precision, at rest;
- frame DENSITY_FRAME: every liquid density is within DENSITY_TOLERANCE (relative) of the rest
  density for particles at least one support radius (2 spacings) from the free faces of the
  block, and none exceeds rest density by more than that. (A frame's density is the SPH sum the
  solver evaluated at the start of the step that ended at that frame; frame 0 is written before
  any step. When the first step ends at the first frame time, frame 1 holds the density of the
  initial lattice.)

Exit codes: 0 all good, 1 a check failed (every failure is printed), 2 usage, 3 vtk missing.
"""
import json
import math
import os
import struct
import sys
import xml.etree.ElementTree as ET

try:
    from vtkmodules.vtkCommonCore import vtkCommand
    from vtkmodules.vtkIOPLY import vtkPLYReader
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    import vtkmodules.vtkCommonCore as vtk_core
except ImportError as error:
    print(f"VTK's Python bindings are not installed for {sys.executable} ({error}); "
          "Debian: apt-get install python3-vtk9", file=sys.stderr)
    sys.exit(3)

# float32 holds 24 significant bits: a coordinate computed in double and stored as float is off
# by at most half an ulp, 2^-24 relative; the spacing is rounded to float before the lattice is
# built (upf::Real), which adds a few ulps more. Four ulps of the largest coordinate covers both.
FLOAT_REL = 4 * 2.0 ** -23

PLY_FIXED = ["x", "y", "z", "red", "green", "blue", "id", "type", "material", "vx", "vy", "vz"]
PLY_TYPES = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I",
             "float": "f", "double": "d", "int8": "b", "uint8": "B", "int16": "h",
             "uint16": "H", "int32": "i", "uint32": "I", "float32": "f", "float64": "d"}

try:
    import meshio
except ImportError:
    meshio = None


class Failures:
    def __init__(self):
        self.messages = []

    def check(self, ok, message):
        if not ok:
            self.messages.append(message)
        return ok


class ErrorCatcher:
    """VTK readers report bad files through ErrorEvent, not exceptions."""

    def __init__(self, reader):
        self.errors = []
        reader.AddObserver(vtkCommand.ErrorEvent, self.on_error)

    def on_error(self, caller, event, data=None):
        self.errors.append(str(data) if data else event)

    on_error.CallDataType = vtk_core.VTK_STRING


def f32(x):
    """`x` rounded to float32, as the PLY files store every real."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def read_vtp(path):
    reader = vtkXMLPolyDataReader()
    catcher = ErrorCatcher(reader)
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput(), catcher.errors


def read_ply_vtk(path):
    reader = vtkPLYReader()
    catcher = ErrorCatcher(reader)
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput(), catcher.errors


def read_ply_raw(path):
    """Header properties [(type, name)] and the records as tuples, parsed with struct."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.find(b"end_header\n")
    if end < 0:
        raise ValueError("no end_header line")
    lines = data[:end].decode("ascii").split("\n")
    if lines[0] != "ply" or lines[1] != "format binary_little_endian 1.0":
        raise ValueError(f"header starts {lines[:2]}")
    count, props = None, []
    for line in lines[2:]:
        words = line.split()
        if not words or words[0] == "comment":
            continue
        if words[0] == "element":
            if words[1] != "vertex" or count is not None:
                raise ValueError(f"unexpected element line '{line}'")
            count = int(words[2])
        elif words[0] == "property" and len(words) == 3:
            props.append((words[1], words[2]))
        else:
            raise ValueError(f"unexpected header line '{line}'")
    fmt = "<" + "".join(PLY_TYPES[t] for t, _ in props)
    body = data[end + len(b"end_header\n"):]
    if len(body) != count * struct.calcsize(fmt):
        raise ValueError(f"{len(body)} data bytes for {count} vertices of "
                         f"{struct.calcsize(fmt)} bytes")
    return props, list(struct.iter_unpack(fmt, body))


def point_array(data, name, components, failures, where):
    array = data.GetPointData().GetArray(name)
    if not failures.check(array is not None, f"{where}: no point array '{name}'"):
        return None
    failures.check(array.GetNumberOfComponents() == components,
                   f"{where}: '{name}' has {array.GetNumberOfComponents()} components, "
                   f"expected {components}")
    failures.check(array.GetNumberOfTuples() == data.GetNumberOfPoints(),
                   f"{where}: '{name}' has {array.GetNumberOfTuples()} tuples for "
                   f"{data.GetNumberOfPoints()} points")
    return array


def values(array):
    n, c = array.GetNumberOfTuples(), array.GetNumberOfComponents()
    if c == 1:
        return [array.GetValue(i) for i in range(n)]
    return [array.GetTuple(i) for i in range(n)]


def fluid_lattice(block, spacing):
    """The liquid positions in id order, as framework/scene/scene_builder.cpp places them."""
    lo, hi = block["min"], block["max"]
    n = [max(0, math.floor((hi[a] - lo[a]) / spacing + 1e-6)) for a in range(3)]
    return [(lo[0] + (i + 0.5) * spacing, lo[1] + (j + 0.5) * spacing,
             lo[2] + (k + 0.5) * spacing)
            for k in range(n[2]) for j in range(n[1]) for i in range(n[0])]


def free_faces(block, container):
    """(axis, coordinate) of each block face that does not lie on a container face."""
    faces = []
    for a in range(3):
        if abs(block["min"][a] - container["min"][a]) > 1e-9:
            faces.append((a, block["min"][a]))
        if abs(block["max"][a] - container["max"][a]) > 1e-9:
            faces.append((a, block["max"][a]))
    return faces


def check_frame(k, vtp_path, ply_path, expect, failures):
    """Checks one frame; returns its positions and point arrays from the .vtp, or None."""
    where = os.path.relpath(vtp_path, expect["run_dir"])
    data, errors = read_vtp(vtp_path)
    failures.check(not errors, f"{where}: vtkXMLPolyDataReader reported {errors}")
    n = data.GetNumberOfPoints()
    if not failures.check(n == expect["particles"],
                          f"{where}: {n} points, summary.json says {expect['particles']}"):
        return None
    failures.check(data.GetNumberOfVerts() == n,
                   f"{where}: {data.GetNumberOfVerts()} vertex cells for {n} points")
    arrays = {}
    for name, components, vtk_type in [("id", 1, vtk_core.VTK_UNSIGNED_INT),
                                       ("type", 1, vtk_core.VTK_UNSIGNED_CHAR),
                                       ("material", 1, vtk_core.VTK_UNSIGNED_SHORT),
                                       ("velocity", 3, None), ("density", 1, None),
                                       ("pressure", 1, None)]:
        array = point_array(data, name, components, failures, where)
        if array is None:
            return None
        if vtk_type is not None:
            failures.check(array.GetDataType() == vtk_type,
                           f"{where}: '{name}' is {array.GetDataTypeAsString()}")
        arrays[name] = values(array)
    positions = [data.GetPoint(i) for i in range(n)]
    ids, types = arrays["id"], arrays["type"]
    failures.check(len(set(ids)) == n, f"{where}: {n - len(set(ids))} repeated ids")
    bad_types = sorted({t for t in types if t not in expect["types"]})
    failures.check(not bad_types, f"{where}: invalid type values {bad_types}")
    shared = expect["frozen_ids"] & set(ids)
    failures.check(not shared, f"{where}: {len(shared)} ids also in frames/frozen.vtp")
    liquid = sum(1 for t in types if t == 0)
    failures.check(liquid == expect["liquid"],
                   f"{where}: {liquid} liquid particles, summary.json says {expect['liquid']}")
    failures.check(all(math.isfinite(c) for p in positions for c in p),
                   f"{where}: non-finite positions")

    # The PLY frame, first through VTK, then through its own header.
    pwhere = os.path.relpath(ply_path, expect["run_dir"])
    ply, errors = read_ply_vtk(ply_path)
    failures.check(not errors, f"{pwhere}: vtkPLYReader reported {errors}")
    if failures.check(ply.GetNumberOfPoints() == n,
                      f"{pwhere}: {ply.GetNumberOfPoints()} points, the .vtp has {n}"):
        moved = [i for i in range(n) if ply.GetPoint(i) != tuple(map(f32, positions[i]))]
        failures.check(not moved, f"{pwhere}: {len(moved)} positions differ from the .vtp, "
                       f"first at point {moved[:1]}")
        rgb = ply.GetPointData().GetArray("RGB")
        if failures.check(rgb is not None, f"{pwhere}: vtkPLYReader found no colours"):
            colour_of = {}
            for i in range(n):
                colour_of.setdefault(types[i], set()).add(rgb.GetTuple3(i))
            failures.check(all(len(c) == 1 for c in colour_of.values()),
                           f"{pwhere}: a type with several colours: {colour_of}")
            colours = [next(iter(c)) for c in colour_of.values()]
            failures.check(len(set(colours)) == len(colours),
                           f"{pwhere}: two types share a colour: {colour_of}")
    if meshio is not None:
        mesh = meshio.read(ply_path)
        if failures.check(len(mesh.points) == n, f"{pwhere}: meshio reads {len(mesh.points)} "
                          f"points, the .vtp has {n}"):
            moved = [i for i in range(n)
                     if tuple(float(c) for c in mesh.points[i]) != tuple(map(f32, positions[i]))]
            failures.check(not moved, f"{pwhere}: meshio: {len(moved)} positions differ")
            data = mesh.point_data
            failures.check(all(k in data for k in ("red", "green", "blue", "id", "type")),
                           f"{pwhere}: meshio reads the properties {sorted(data)}")
            if "id" in data:
                failures.check([int(v) for v in data["id"]] == [int(v) for v in ids],
                               f"{pwhere}: meshio reads other ids than the .vtp's")
            if "red" in data:
                failures.check(min(int(v) for v in data["red"]) >= 0,
                               f"{pwhere}: meshio reads negative colours")
    try:
        props, records = read_ply_raw(ply_path)
    except (ValueError, KeyError, UnicodeDecodeError, struct.error) as error:
        failures.check(False, f"{pwhere}: {error}")
        return positions, arrays
    names = [name for _, name in props]
    expected_names = PLY_FIXED + ["density", "pressure"]
    failures.check(names == expected_names, f"{pwhere}: properties {names}, "
                   f"expected {expected_names}")
    if names == expected_names and failures.check(len(records) == n,
                                                  f"{pwhere}: {len(records)} vertices"):
        # The same values written twice: equal once the .vtp's Real is rounded to float32.
        column = {name: c for c, name in enumerate(names)}
        for name, vtp_values in [("id", ids), ("type", types), ("material", arrays["material"]),
                                 ("density", [f32(v) for v in arrays["density"]]),
                                 ("pressure", [f32(v) for v in arrays["pressure"]])]:
            bad = [i for i in range(n) if records[i][column[name]] != vtp_values[i]]
            failures.check(not bad, f"{pwhere}: '{name}' differs from the .vtp at {len(bad)} "
                           f"points, first {bad[:1]}")
        bad = [i for i in range(n) if tuple(records[i][column["vx"]:column["vz"] + 1]) !=
               tuple(map(f32, arrays["velocity"][i]))]
        failures.check(not bad, f"{pwhere}: velocity differs from the .vtp at {len(bad)} points")
    return positions, arrays


def main(argv):
    if len(argv) != 5:
        print(__doc__, file=sys.stderr)
        return 2
    run_dir, scene_path = argv[1], argv[2]
    density_frame, density_tolerance = int(argv[3]), float(argv[4])
    failures = Failures()

    with open(scene_path) as f:
        scene = json.load(f)
    with open(os.path.join(run_dir, "summary.json")) as f:
        summary = json.load(f)
    spacing = scene["particle_spacing"]
    (block,), (container,) = scene["fluid_blocks"], scene["containers"]
    rest_density = scene["materials"][block["material"]]["density"]
    expect = {"run_dir": run_dir, "particles": summary["particles"]["total"],
              "liquid": summary["particles"]["liquid"], "types": (0, 1, 2, 3),
              "frozen_ids": set()}
    failures.check(summary["status"] == "completed", f"summary.json: status {summary['status']}")

    # The series as ParaView's .pvd reader sees it: part 0 is the particles.
    root = ET.parse(os.path.join(run_dir, "particles.pvd")).getroot()
    frozen_sets = [d for d in root.iter("DataSet") if d.get("file") == "frames/frozen.vtp"]
    if frozen_sets:
        failures.check(all(d.get("part") == "1" for d in frozen_sets),
                       "particles.pvd: frames/frozen.vtp is not always part 1")
        frozen, errors = read_vtp(os.path.join(run_dir, "frames", "frozen.vtp"))
        failures.check(not errors, f"frames/frozen.vtp: vtkXMLPolyDataReader reported {errors}")
        frozen_types = point_array(frozen, "type", 1, failures, "frames/frozen.vtp")
        frozen_ids = point_array(frozen, "id", 1, failures, "frames/frozen.vtp")
        if frozen_types is not None and frozen_ids is not None:
            failures.check(set(values(frozen_types)) <= {3},
                           "frames/frozen.vtp holds particles that are not frozen")
            expect["frozen_ids"] = set(values(frozen_ids))
            expect["particles"] -= frozen.GetNumberOfPoints()
            expect["types"] = (0, 1, 2)
    failures.check(root.get("type") == "Collection", f"particles.pvd: type {root.get('type')}")
    sets = [d for d in root.iter("DataSet") if d.get("part", "0") == "0"]
    times = [float(d.get("timestep")) for d in sets]
    files = [d.get("file") for d in sets]
    failures.check(len(sets) == summary["frames"],
                   f"particles.pvd lists {len(sets)} frames, summary.json says {summary['frames']}")
    failures.check(not frozen_sets or len(frozen_sets) == len(sets),
                   f"particles.pvd lists frames/frozen.vtp in {len(frozen_sets)} of "
                   f"{len(sets)} time steps")
    failures.check(times[:1] == [0.0] and all(a < b for a, b in zip(times, times[1:])),
                   f"particles.pvd: times not increasing from 0: {times[:5]}...")
    on_disk = sorted(os.listdir(os.path.join(run_dir, "frames")))
    frames_on_disk = [f for f in on_disk if f.startswith("frame_")]  # not surface_*, say
    vtp_on_disk = [f"frames/{f}" for f in frames_on_disk if f.endswith(".vtp")]
    failures.check(vtp_on_disk == sorted(files),
                   f"frames/ holds {len(vtp_on_disk)} .vtp files, the .pvd lists {len(files)}")
    ply_on_disk = [f for f in frames_on_disk if f.endswith(".ply")]
    failures.check(len(ply_on_disk) == len(files) and not any(f.endswith(".ply") for f in files),
                   f"frames/ holds {len(ply_on_disk)} .ply files for {len(files)} frames "
                   "(and the .pvd must not list them)")

    lattice = fluid_lattice(block, spacing)
    failures.check(len(lattice) == expect["liquid"],
                   f"the block's lattice has {len(lattice)} sites, summary.json says "
                   f"{expect['liquid']} liquid particles")
    for k, file in enumerate(files):
        vtp_path = os.path.join(run_dir, file)
        ply_path = os.path.splitext(vtp_path)[0] + ".ply"
        if not failures.check(os.path.exists(ply_path), f"no {ply_path} for {file}"):
            continue
        frame = check_frame(k, vtp_path, ply_path, expect, failures)
        if frame is None:
            continue
        positions, arrays = frame
        ids, types, density = arrays["id"], arrays["type"], arrays["density"]
        liquid = sorted((ids[i], i) for i in range(len(ids)) if types[i] == 0)
        if k == 0 and len(liquid) == len(lattice):
            scale = max(abs(c) for site in lattice for c in site) or 1.0
            off = [(pid, positions[i], site) for (pid, i), site in zip(liquid, lattice)
                   if any(abs(a - b) > FLOAT_REL * scale for a, b in zip(positions[i], site))]
            failures.check(not off, f"{file}: {len(off)} liquid particles off the block's "
                           f"lattice, first (id, position, lattice site) {off[:1]}")
            moving = [pid for pid, i in liquid if any(arrays["velocity"][i])]
            failures.check(not moving, f"{file}: liquid moving at t = 0, ids {moving[:5]}")
        if k == density_frame:
            faces = free_faces(block, container)
            support = 2 * spacing
            worst_inner, worst_any, inner = 0.0, 0.0, 0
            for _, i in liquid:
                error = density[i] / rest_density - 1
                worst_any = max(worst_any, error)
                if all(abs(positions[i][a] - c) >= support - 1e-9 for a, c in faces):
                    inner += 1
                    worst_inner = max(worst_inner, abs(error))
            failures.check(inner > 0, f"{file}: no liquid particle a support radius inside")
            failures.check(worst_inner <= density_tolerance,
                           f"{file}: inner liquid density off rest density by "
                           f"{worst_inner:.3%} (tolerance {density_tolerance:.3%})")
            failures.check(worst_any <= density_tolerance,
                           f"{file}: liquid density above rest density by {worst_any:.3%} "
                           f"(tolerance {density_tolerance:.3%})")
            print(f"{file}: {inner} inner liquid particles, worst density error "
                  f"{worst_inner:.4%}; largest excess anywhere {worst_any:.4%}")
    failures.check(0 <= density_frame < len(files),
                   f"density frame {density_frame} not among {len(files)} frames")

    shown = 20  # a systematic fault fails every frame: its first reports tell the story
    for m in failures.messages[:shown]:
        print(m, file=sys.stderr)
    if len(failures.messages) > shown:
        print(f"... and {len(failures.messages) - shown} more failures", file=sys.stderr)
    if not failures.messages:
        print(f"{len(files)} frames, {expect['particles']} particles each: .pvd, .vtp and .ply "
              "agree")
    return 1 if failures.messages else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
