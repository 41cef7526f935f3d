#!/usr/bin/env python3
"""Opens a split run's frames, written as one piece per rank, with VTK's own parallel reader, as
ParaView does, and checks them against the one-rank run's frames.

Usage: python3 check_pvtp_frames.py SPLIT_DIR ALONE_DIR RANKS

SPLIT_DIR is what `mpirun -n RANKS upf run SCENE --set /output/pieces=per_rank` wrote, ALONE_DIR
what `upf run SCENE` wrote on one rank. Checks, for every time step of SPLIT_DIR/particles.pvd:
- its parts are .pvtp files (frames/frame_NNNNN.pvtp, and frames/frozen.pvtp when the walls are
  written once), at the times ALONE_DIR/particles.pvd lists;
- vtkXMLPPolyDataReader reads each as RANKS pieces, one data set;
- that data set holds the particles of the one-rank part (vtkXMLPolyDataReader): the same ids,
  and for each id the same position, velocity and every other point array, value for value.

It exits with 1 when a check fails (each failure printed), 2 on bad usage and 3 without VTK's
Python bindings (python3-vtk9), else 0.
"""
import importlib
import os
import sys
import xml.etree.ElementTree as ET


def vtk_xml_readers():
    """VTK's XML readers, or exit code 3 naming the package that has them."""
    try:
        io_xml = importlib.import_module("vtkmodules.vtkIOXML")
    except ImportError as error:
        sys.stderr.write(f"no VTK Python bindings for {sys.executable} ({error}): "
                         "apt-get install python3-vtk9\n")
        sys.exit(3)
    return io_xml.vtkXMLPolyDataReader, io_xml.vtkXMLPPolyDataReader


vtkXMLPolyDataReader, vtkXMLPPolyDataReader = vtk_xml_readers()

failures = []


def fail(message):
    failures.append(message)
    print("FAIL: " + message)


def series(run_dir):
    """(time, [part file, ...]) per time step of particles.pvd, parts in order."""
    steps = {}
    for ds in ET.parse(os.path.join(run_dir, "particles.pvd")).getroot().iter("DataSet"):
        steps.setdefault(float(ds.get("timestep")), []).append(
            (int(ds.get("part", "0")), ds.get("file")))
    return [(t, [f for _, f in sorted(parts)]) for t, parts in sorted(steps.items())]


def by_id(output):
    """{id: (point, {array name: tuple})} of a vtkPolyData."""
    data = output.GetPointData()
    arrays = [data.GetArray(k) for k in range(data.GetNumberOfArrays())]
    ids = data.GetArray("id")
    out = {}
    for i in range(output.GetNumberOfPoints()):
        values = {a.GetName(): a.GetTuple(i) for a in arrays}
        out[int(ids.GetTuple1(i))] = (output.GetPoint(i), values)
    return out


def read(reader_type, path):
    reader = reader_type()
    reader.SetFileName(path)
    reader.Update()
    return reader


def main():
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    split_dir, alone_dir, ranks = sys.argv[1], sys.argv[2], int(sys.argv[3])
    split, alone = series(split_dir), series(alone_dir)
    if [t for t, _ in split] != [t for t, _ in alone]:
        fail(f"time steps differ: {[t for t, _ in split]} against {[t for t, _ in alone]}")
        return 1
    for (t, parts), (_, alone_parts) in zip(split, alone):
        if len(parts) != len(alone_parts):
            fail(f"t = {t}: {len(parts)} parts against {len(alone_parts)}")
            continue
        for part, alone_part in zip(parts, alone_parts):
            if not part.endswith(".pvtp"):
                fail(f"t = {t}: part {part} is not a .pvtp")
                continue
            reader = read(vtkXMLPPolyDataReader, os.path.join(split_dir, part))
            if reader.GetNumberOfPieces() != ranks:
                fail(f"{part}: {reader.GetNumberOfPieces()} pieces, not {ranks}")
            joined = by_id(reader.GetOutput())
            expected = by_id(read(vtkXMLPolyDataReader, os.path.join(alone_dir, alone_part))
                             .GetOutput())
            if len(joined) != reader.GetOutput().GetNumberOfPoints():
                fail(f"{part}: repeated ids")
            if sorted(joined) != sorted(expected):
                fail(f"{part}: {len(joined)} ids against {len(expected)} in {alone_part}")
                continue
            differing = [i for i in expected if joined[i] != expected[i]]
            if differing:
                fail(f"{part}: {len(differing)} particles differ from {alone_part}, "
                     f"first id {differing[0]}")
    print(f"{len(split)} time steps checked")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
