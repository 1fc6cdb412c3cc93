"""ParaView's own XDMF reader on halfeti's field series (run with pvpython under xvfb-run; the files are those of
tools_fields_xdmf). Each series must load with the points, cells and arrays that its HDF5 files hold: vectors with
three components, ids as integers, cell fields on the cells.

usage: xvfb-run -a pvpython test_fields_paraview.py FIELDS_DIR
"""
import os
import sys

import h5py  # Debian's pvpython runs the system's python3, which has h5py
from paraview import servermanager as sm
from paraview.simple import XDMFReader

fields = sys.argv[1]
failures = []


def check(ok, message):
    if not ok:
        failures.append(message)


for name, vectors, ids, cell_fields in (("fluid", ["velocity"], ["gid"], []),
                                        ("plate", ["displacement", "velocity"], ["element"],
                                         ["von_mises", "strain_energy_density", "element"]),
                                        ("cables", [], ["cable"], []),
                                        ("tank", [], [], [])):
    reader = XDMFReader(FileNames=[os.path.join(fields, f"{name}.xdmf")])
    times = list(reader.TimestepValues) if hasattr(reader.TimestepValues, "__len__") else [reader.TimestepValues]
    last = sorted(f for f in os.listdir(fields) if f.startswith(name + "_") and f.endswith(".h5"))[-1]
    reader.UpdatePipeline(times[-1])
    data = sm.Fetch(reader)
    with h5py.File(os.path.join(fields, last), "r") as h5:
        points = len(h5["x"])
        cells = len(h5["cells"]) if "cells" in h5 else points
    check(data.GetNumberOfPoints() == points, f"{name}: ParaView reads {data.GetNumberOfPoints()} points, {points} stored")
    check(data.GetNumberOfCells() == cells, f"{name}: ParaView reads {data.GetNumberOfCells()} cells, {cells} stored")
    for v in vectors:
        array = data.GetPointData().GetArray(v)
        check(array is not None and array.GetNumberOfComponents() == 3, f"{name}: {v} is not a 3-component vector")
    for i in ids:
        array = data.GetPointData().GetArray(i) or data.GetCellData().GetArray(i)
        check(array is not None and array.GetDataTypeAsString() in ("long", "long long", "idtype", "vtkIdType"),
              f"{name}: {i} is {array.GetDataTypeAsString() if array else 'missing'}, not an integer")
    for c in cell_fields:
        check(data.GetCellData().GetArray(c) is not None, f"{name}: {c} is not a cell field")
    print(f"{name}: {len(times)} time(s), {data.GetNumberOfPoints()} points, {data.GetNumberOfCells()} cells")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("paraview: every series loads as stored")
