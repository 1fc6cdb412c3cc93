#!/usr/bin/python3
"""The far-wall pressure of dam-break runs (inputs/validation/dambreak_pressure.yaml) against Buchner (2002): one
panel per run, the probe as sampled (grey) and its 20 ms centred running mean (the study's smoothing, io/metrics.hpp),
in the data's units p / (rho g H) against t sqrt(g / H), H = 0.6 m.

usage:
  tools/dambreak_pressure_figure.py OUT.png LABEL=RUN [LABEL=RUN ...]

RUN is a run folder (its probes.csv), or STUDY_DIR#N: the N-th point (from 1) of a study's folder (its runs.json),
e.g. out/studies/dambreak_pressure#1 for the first point of `tools/study run inputs/studies/dambreak_pressure.yaml`.
LABEL holds no '='. The figure of docs/sph.md:

  tools/dambreak_pressure_figure.py docs/figures/dambreak_pressure.png "H/50, the scene=out/studies/dambreak_pressure#1" \
    "H/100=out/studies/dambreak_pressure#3" "delta 0.2=out/studies/dambreak_pressure#6" \
    "Wendland C2, h 2 dx=out/studies/dambreak_pressure#11" \
    "delta 0.2 and Wendland C2, h 2 dx=out/studies/dambreak_pressure#13" \
    "the same at H/100=out/studies/dambreak_pressure#14"
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "inputs", "validation", "data", "dambreak_buchner_2002_pressure_2d.csv")
H, G, RHO = 0.6, 9.81, 1000.0  # the scene's column height, gravity and density
SMOOTH = 0.02  # s, the study's running mean


def read_data():
    with open(DATA) as f:
        rows = [line.strip().split(",") for line in f if line.strip() and not line.startswith("#")]
    return np.array([[float(a), float(b)] for a, b in rows[1:]])


def read_run(folder):
    with open(os.path.join(folder, "probes.csv")) as f:
        rows = list(csv.DictReader(f))
    t = np.array([float(r["t"]) for r in rows])
    p = np.array([float(r["p_wall"]) for r in rows])
    return t, p


def running_mean(t, v, width):
    """The centred mean over t_k +- width / 2 (as io::running_mean)."""
    lo = np.searchsorted(t, t - 0.5 * width, side="left")
    hi = np.searchsorted(t, t + 0.5 * width, side="right")
    c = np.concatenate([[0.0], np.cumsum(v)])
    return (c[hi] - c[lo]) / (hi - lo)


def main(argv):
    if len(argv) < 2 or argv[0] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if argv and argv[0] in ("-h", "--help") else 2
    out, runs = argv[0], []
    for arg in argv[1:]:
        label, _, folder = arg.partition("=")
        if "#" in folder:
            study, _, n = folder.rpartition("#")
            try:
                with open(os.path.join(study, "runs.json")) as f:
                    folder = json.load(f)[int(n) - 1]["folder"]
            except (OSError, ValueError, IndexError) as e:
                print(f"dambreak_pressure_figure: '{arg}': no point {n} in {study}/runs.json ({e})", file=sys.stderr)
                return 2
        if not folder or not os.path.isfile(os.path.join(folder, "probes.csv")):
            print(f"dambreak_pressure_figure: '{arg}' is not LABEL=RUN with RUN/probes.csv", file=sys.stderr)
            return 2
        runs.append((label, folder))
    data = read_data()
    scale_t, scale_p = np.sqrt(G / H), 1.0 / (RHO * G * H)
    fig, axes = plt.subplots(len(runs), 1, figsize=(8.0, 1.9 * len(runs)), sharex=True, squeeze=False)
    for ax, (label, folder) in zip(axes[:, 0], runs):
        t, p = read_run(folder)
        ax.plot(t * scale_t, p * scale_p, color="0.7", lw=0.4, label="probe (1 ms)")
        ax.plot(t * scale_t, running_mean(t, p, SMOOTH) * scale_p, color="C0", lw=1.0, label="20 ms mean")
        ax.plot(data[:, 0], data[:, 1], "k.", ms=3, label="Buchner (2002)")
        ax.set_ylim(-0.5, 2.0)
        ax.set_xlim(2.0, 7.5)
        ax.grid(alpha=0.3)
        ax.text(0.01, 0.92, label, transform=ax.transAxes, fontsize=8, va="top")
        ax.set_ylabel("p / rho g H", fontsize=8)
    axes[0, 0].legend(fontsize=7, loc="upper right", ncol=3)
    axes[-1, 0].set_xlabel("t sqrt(g / H)")
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    print(f"dambreak_pressure_figure: {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
