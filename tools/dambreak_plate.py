#!/usr/bin/python3
"""The dam break onto an elastic plate (inputs/validation/dambreak_plate.yaml; docs/coupling.md, section 15):
the tip's history at several resolutions against the published bands, the water's load on the plate by part,
and the plate's energy balance; prints the convergence table (successive differences of the tip history).

usage: tools/dambreak_plate.py DIR [DIR ...] [--png OUT_PREFIX]
  DIR: finished runs of the scene (e.g. with --set fluid.spacing=...), coarse to fine; the first is used for the
       load and energy charts.
"""
import csv
import json
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HALFETI = os.path.join(os.environ.get("HALFETI_BUILD") or os.path.join(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))), "build"), "src", "app", "halfeti")  # HALFETI_BUILD: another build folder
L = 0.146  # the benchmark's length scale [m]
# Published tip histories as issue #14 summarises them (PFEM, SPH, partitioned FE, MPS-DEM): first peak and the
# tip at 0.45 s.
PEAK = (0.045, 0.048, 0.22, 0.26)
LATE = (0.017, 0.020, 0.45)


def read(run):
    with open(os.path.join(run, "probes.csv"), newline="") as f:
        rows = list(csv.reader(f))
    return {n: np.array([float(r[j]) for r in rows[1:]]) for j, n in enumerate(rows[0])}


def spacing(run):
    with open(os.path.join(run, "scene.resolved.yaml")) as f:
        for line in f:
            if line.strip().startswith("spacing:"):
                return float(line.split(":")[1])
    return float("nan")


def main(argv):
    png = None
    if "--png" in argv:
        k = argv.index("--png")
        png = argv[k + 1]
        del argv[k:k + 2]
    runs = argv
    if not runs:
        print(__doc__)
        return 2
    data = [read(r) for r in runs]
    dxs = [spacing(r) for r in runs]
    print("| dx | particles | first peak [mm] at [s] | tip at 0.45 s [mm] | RMS difference to the next coarser, 0-0.6 s [mm] | wall [s] |")
    print("|---|---|---|---|---|---|")
    prev = None
    for run, d, dx in zip(runs, data, dxs):
        t, tip = d["t"], d["tip_x"]
        k = int(np.argmax(tip))
        late = np.interp(0.45, t, tip)
        s = json.load(open(os.path.join(run, "summary.json")))
        diff = ""
        if prev is not None:
            # RMS of this run's tip minus the coarser run's, at the coarser run's samples over 0-0.6 s (or as far
            # as both reach): the metrics' one home, halfeti compare.
            end = min(t[-1], read(prev)["t"][-1], 0.6)
            out = subprocess.run([HALFETI, "compare", run, "--probe", "tip_x", "--metric", "rms", "--reference",
                                  os.path.join(prev, "probes.csv"), "--columns", "t,tip_x", "--window", f"0,{end!r}"],
                                 capture_output=True, text=True, check=True).stdout
            diff = "%.2f" % (1e3 * json.loads(out)["value"])
        prev = run
        print("| L/%.0f | %d | %.1f at %.3f | %.1f | %s | %.0f |" % (L / dx, s["particles"], 1e3 * tip[k], t[k], 1e3 * late,
                                                                   diff, s["wall_time"]))
    if png is None:
        return 0
    fig, ax = plt.subplots(figsize=(7, 4))
    for d, dx in zip(data, dxs):
        ax.plot(d["t"], 1e3 * d["tip_x"], label="L/%.0f" % (L / dx))
    ax.fill_between([PEAK[2], PEAK[3]], 1e3 * PEAK[0], 1e3 * PEAK[1], color="grey", alpha=0.4, label="published")
    ax.fill_between([LATE[2] - 0.01, LATE[2] + 0.01], 1e3 * LATE[0], 1e3 * LATE[1], color="grey", alpha=0.4)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("tip x displacement [mm]")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png + "_tip.png", dpi=110)
    d = data[0]
    t = d["t"]
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(12, 4))
    win = 10  # 10 ms running mean of the loads (probes every 1 ms)

    def smooth(v):
        return np.convolve(v, np.ones(win) / win, mode="same")
    for name, label in [("wall_left_push_x", "ghosts, left face, push"), ("wall_left_suction_x", "ghosts, left face, suction"),
                        ("wall_right_push_x", "ghosts, right face, push"), ("wall_right_suction_x", "ghosts, right face, suction"),
                        ("contact_x", "contact")]:
        if name in d:
            a1.plot(t, smooth(d[name]), label=label)
    a1.set_xlabel("t [s]")
    a1.set_ylabel("water's x force on the plate [N/m] (10 ms mean)")
    a1.legend(fontsize=8)
    a1.grid(alpha=0.3)
    # (runs from before the structure_potential_energy probe: without gravity's share)
    e = d["strain_energy"] + d["structure_kinetic_energy"] + d.get("structure_potential_energy", 0.0 * t)
    work = d["work_wall"] + d["work_added_mass"] + d["work_contact"]
    a2.plot(t, e - e[0], label="plate: strain + kinetic + gravity")
    a2.plot(t, work, "--", label="water's work on the plate")
    for name in ("work_wall", "work_added_mass", "work_contact"):
        a2.plot(t, d[name], lw=0.8, label=name)
    a2.set_xlabel("t [s]")
    a2.set_ylabel("J/m")
    a2.legend(fontsize=8)
    a2.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png + "_loads.png", dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
