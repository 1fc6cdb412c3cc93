#!/usr/bin/python3
"""The field files a user opens in ParaView, read back as a reader would: a short run of the paper's plate with
cables in water (dx 5 mm, 0.04 s), then every XDMF series (fluid, plate, cables, tank) parsed as XML and each of its
DataItems resolved in its HDF5 file with h5py: shape, number type and unit as the XDMF states them, cells within the
points, cell fields as many as cells. Then what the fields say against what the probes say at the same time (the
same solution, so equal to round-off): the cable stress at the plate end, the plate's top-right displacement, and
the largest element-mean von Mises stress below the largest point value. probes.json names a unit for every column,
and tools/plot --movie draws one frame per field file.

usage: test_fields_xdmf.py SOURCE_DIR BUILD_DIR
"""
import csv
import json
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

root, build = sys.argv[1], sys.argv[2]
work = os.path.join(build, "fields_xdmf_test")
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []


def check(ok, message):
    if not ok:
        failures.append(message)


scene = os.path.join(work, "scene.yaml")
with open(os.path.join(root, "inputs", "paper", "cosine_cable.yaml")) as f:
    text = f.read()
with open(scene, "w") as f:  # the paper's scene with a von Mises probe added
    f.write(text.rstrip() + "\n  - {name: max_vm, kind: max_von_mises}\n")
out = os.path.join(work, "run")
subprocess.run([os.path.join(build, "src", "app", "halfeti"), "run", scene, "--out", out, "--set",
                "fluid.spacing=0.005", "--set", "scene.end_time=0.04", "--set", "output.field_interval=0.02"],
               check=True, stdout=subprocess.DEVNULL)

NUMBER_TYPES = {"Float": "f", "Int": "i"}


def series(name):
    """Each grid of a series: (time, topology element, {attribute name: (attribute element, data)})."""
    path = os.path.join(out, "fields", f"{name}.xdmf")
    tree = ET.parse(path)
    grids = []
    for grid in tree.getroot().iter("Grid"):
        if grid.get("GridType") != "Uniform":
            continue
        time = float(grid.find("Time").get("Value"))

        def resolve(item, where):
            check(item.get("Format") == "HDF", f"{where}: format {item.get('Format')}")
            file, _, dataset = item.text.strip().partition(":/")
            with h5py.File(os.path.join(out, "fields", file), "r") as h5:
                check(dataset in h5, f"{where}: no dataset {dataset} in {file}")
                data = h5[dataset][()]
                unit = h5[dataset].attrs.get("unit")
            dims = tuple(int(d) for d in item.get("Dimensions").split())
            check(data.shape == dims, f"{where}: {dataset} has shape {data.shape}, the XDMF says {dims}")
            kind = NUMBER_TYPES[item.get("NumberType")]
            check(data.dtype.kind == kind and data.dtype.itemsize == int(item.get("Precision")),
                  f"{where}: {dataset} is {data.dtype}, the XDMF says {item.get('NumberType')}{item.get('Precision')}")
            return data, (unit.decode() if isinstance(unit, bytes) else unit)

        x, _ = resolve(grid.find("Geometry")[0], f"{name} t={time} x")
        topo = grid.find("Topology")
        cells = None
        if topo.get("TopologyType") != "Polyvertex":
            cells, _ = resolve(topo.find("DataItem"), f"{name} t={time} cells")
            check(cells.shape[0] == int(topo.get("NumberOfElements")), f"{name}: cell count")
            check(cells.min() >= 0 and cells.max() < len(x), f"{name} t={time}: a cell names a point past the last")
        attributes = {}
        for a in grid.findall("Attribute"):
            data, unit = resolve(a.find("DataItem"), f"{name} t={time} {a.get('Name')}")
            info = a.find("Information")
            stated = info.get("Value") if info is not None else ""
            check(stated == (unit or ""), f"{name}: {a.get('Name')} unit {stated!r} in the XDMF, {unit!r} in the file")
            rows = len(cells) if a.get("Center") == "Cell" else len(x)
            check(data.shape[0] == rows, f"{name}: {a.get('Name')} has {data.shape[0]} rows for {rows}")
            if a.get("AttributeType") == "Vector":
                check(data.ndim == 2 and data.shape[1] == 3, f"{name}: vector {a.get('Name')} has shape {data.shape}")
            attributes[a.get("Name")] = (a, data)
        grids.append((time, topo, attributes, x, cells))
    check(len(grids) > 0, f"{name}: no frames")
    return grids


fluid, plate, cables, tank = series("fluid"), series("plate"), series("cables"), series("tank")
check(len(fluid) == 3 and len(plate) == 3 and len(cables) == 3, "three frames each at 0, 0.02 and 0.04 s")
for t, _, a, x, _ in fluid:
    gid = a["gid"][1]
    check(np.array_equal(np.sort(gid), np.arange(len(x))), f"fluid t={t}: gid is not a permutation of 0..N-1")
    check(set(a) == {"velocity", "rho", "p", "gid"}, f"fluid fields {sorted(a)}")
for t, topo, a, _, _ in plate:
    check(topo.get("TopologyType") == "Quadrilateral", "plate topology")
    check({"displacement", "velocity", "von_mises", "strain_energy_density", "element"} <= set(a), f"plate {sorted(a)}")
(_, topo, _, x, cells), = tank
check(topo.get("TopologyType") == "Polyline" and len(cells) == 3, "the tank's outline: three segments")

with open(os.path.join(out, "probes.csv"), newline="") as f:
    rows = list(csv.reader(f))
probes = {n: np.array([float(r[j]) for r in rows[1:]]) for j, n in enumerate(rows[0])}
with open(os.path.join(out, "probes.json")) as f:
    columns = {c["name"]: c for c in json.load(f)["columns"]}
check(list(columns) == rows[0], f"probes.json columns {list(columns)} against probes.csv {rows[0]}")
expected = {"t": "s", "tip_x": "m", "left_stress": "Pa", "p_right_5mm": "Pa", "kinetic_energy": "J/m",
            "ground_acceleration": "m/s^2", "max_vm": "Pa"}
for n, unit in expected.items():
    check(columns.get(n, {}).get("unit") == unit, f"probes.json: {n} in {columns.get(n, {}).get('unit')}, not {unit}")


def probe_at(name, t):
    k = int(np.argmin(np.abs(probes["t"] - t)))
    check(abs(probes["t"][k] - t) < 1e-9, f"no probe row at t = {t}")
    return probes[name][k]


worst = 0.0
for t, _, a, _, _ in cables:
    index, stress = a["cable"][1], a["stress"][1]
    for cable, probe in ((0, "left_stress"), (1, "right_stress")):
        at_plate = stress[np.where(index == cable)[0][-1]]  # the cable's last point is its plate end
        ref = probe_at(probe, t)
        worst = max(worst, abs(at_plate - ref) / ref)
check(worst < 1e-6, f"cable stress at the plate end differs from the probe by {worst:.2e} (relative)")

# The plate's top-right node: the reference position with the largest y, then the largest x.
for t, _, a, x, _ in plate:
    u = a["displacement"][1]
    x0 = x - u[:, 0]
    with h5py.File(os.path.join(out, "fields", "plate_000000.h5"), "r") as h5:
        y0 = h5["y"][:] - h5["displacement"][:, 1]
    top = np.where(np.isclose(y0, y0.max(), atol=1e-9))[0]
    node = top[np.argmax(x0[top])]
    check(abs(u[node, 0] - probe_at("tip_x", t)) <= 1e-9 + 1e-6 * abs(u[node, 0]),
          f"plate t={t}: top-right ux {u[node, 0]} against the probe tip_x {probe_at('tip_x', t)}")
    vm = a["von_mises"][1]
    check(vm.max() <= probe_at("max_vm", t) * (1 + 1e-9), f"plate t={t}: an element mean above the point max")

# The animation from the same files: one frame per field file, MP4 where ffmpeg is installed, else GIF.
done = subprocess.run([sys.executable, os.path.join(root, "tools", "plot"), out, "--movie", "--fps", "4"],
                      capture_output=True, text=True)
check(done.returncode == 0, f"tools/plot --movie: {done.stderr.strip()}")
movie = os.path.join(out, "plots", "movie.mp4" if shutil.which("ffmpeg") else "movie.gif")
if os.path.isfile(movie) and movie.endswith(".gif"):
    from PIL import Image

    with Image.open(movie) as im:
        check(im.n_frames == 3, f"{movie}: {im.n_frames} frames for 3 field files")
elif os.path.isfile(movie):
    probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-show_entries", "stream=nb_read_frames",
                            "-of", "csv=p=0", movie], capture_output=True, text=True)
    check(probe.stdout.strip() == "3", f"{movie}: {probe.stdout.strip()} frames for 3 field files")
else:
    check(False, f"tools/plot --movie wrote no {movie}")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"fields: {len(fluid)} fluid, {len(plate)} plate, {len(cables)} cable frames and the tank read back; "
      f"cable stress against the probes within {worst:.1e}")
