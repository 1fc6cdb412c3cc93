#!/usr/bin/python3
"""The water's lowest pressure beside the plate's faces in a run's field dumps (docs/coupling.md, section 16): for
every dump, the particles within one spacing of a plate node (the plate as it is then) and the lowest pressure among
them, against the lowest in the tank. Prints the five lowest dumps and the median of the dumps' lowest.

usage: tools/plate_suction.py RUN [--within METRES]
  RUN: a finished run with fields (output.field_interval > 0); --within: the distance from a plate node (default:
       the scene's fluid.spacing, from RUN/scene.resolved.yaml).
"""
import glob
import os
import re
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np
import yaml


def dump_times(run):
    """Each fluid dump's file name -> its time, from fields/fluid.xdmf."""
    times = {}
    for grid in ET.parse(os.path.join(run, "fields", "fluid.xdmf")).iter("Grid"):
        when = grid.find("Time")
        if when is None:
            continue
        for item in grid.iter("DataItem"):
            m = re.search(r"(fluid_\d+\.h5)", item.text or "")
            if m:
                times[m.group(1)] = float(when.get("Value"))
                break
    return times


def within_of(x, y, px, py, reach):
    """Which of the points (x, y) lie within `reach` of any of (px, py) (brute force, in blocks)."""
    near = np.zeros(len(x), dtype=bool)
    for k in range(0, len(x), 4096):
        dx = x[k:k + 4096, None] - px[None, :]
        dy = y[k:k + 4096, None] - py[None, :]
        near[k:k + 4096] = (dx * dx + dy * dy).min(axis=1) < reach * reach
    return near


def main(argv):
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__)
        return 0 if argv else 2
    run = argv[0]
    within = None
    if "--within" in argv:
        within = float(argv[argv.index("--within") + 1])
    if within is None:
        with open(os.path.join(run, "scene.resolved.yaml")) as f:
            within = float(yaml.safe_load(f)["fluid"]["spacing"])
    times = dump_times(run)
    rows = []
    for path in sorted(glob.glob(os.path.join(run, "fields", "fluid_*.h5"))):
        plate = path.replace("fluid_", "plate_")
        if not os.path.exists(plate):
            continue
        with h5py.File(path) as a, h5py.File(plate) as b:
            x, y, p = a["x"][:], a["y"][:], a["p"][:]
            near = within_of(x, y, b["x"][:], b["y"][:], within)
        if near.any():
            i = int(np.argmin(np.where(near, p, np.inf)))
            rows.append((float(p[i]), times.get(os.path.basename(path), float("nan")), x[i], y[i], float(p.min())))
    if not rows:
        print(f"tools/plate_suction.py: no fluid and plate dumps in {run}/fields", file=sys.stderr)
        return 2
    for r in sorted(rows)[:5]:
        print("%.0f Pa at t = %.3f s at (%.4f, %.4f) m; lowest in the tank %.0f Pa" % r)
    print("%d dumps; median of the lowest beside the faces %.0f Pa" % (len(rows), np.median([r[0] for r in rows])))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
