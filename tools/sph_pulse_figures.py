#!/usr/bin/python3
"""Figures of a water-only pulse run (inputs/validation/tank_pulse.yaml): how it ended, the highest water at each
wall, the fall acceleration of the wall films and the noise of the right-wall pressure 5 mm above the floor.

    tools/sph_pulse_figures.py [--window T0 T1] out/tank_pulse_delta out/tank_pulse_standard

Definitions (docs/sph.md, "Shaken tank"):
  * highest water at a wall: the elevation probe 3 mm wide at the wall (highest particle centre + dx/2);
  * film fall acceleration: a = -2 c2 of a least-squares parabola c0 + c1 t + c2 t^2 through that elevation over
    +-0.1 s around each run-up peak higher than 0.15 m (the top of a film one or two particles thick, which
    falls freely if nothing holds it);
  * pressure noise: RMS over T0 <= t <= T1 (default 0.05 s to 1.0 s, before the left-wall impact of 1.06 s
    that ends the runs) of p(t) minus its centred moving average over 0.02 s (11 samples
    at the 2 ms probe interval; the sloshing and the pulse are below 2 Hz, the moving average passes them, the
    particle and acoustic noise above ~50 Hz is left);
  * particle pressure noise (needs h5py): at each field output with T0 < t <= T1, the RMS residual of the particle
    pressures in the 3 x 3 cm box at the right wall's foot (x >= 0.27 m, y <= 0.03 m, about 400 particles) about
    their least-squares quadratic in (x, y); the mean over those outputs. The probe above is a first-order kernel
    (MLS) interpolation and smooths most of the particle-to-particle scatter that delta-SPH removes."""
import csv
import json
import os
import sys


def moving_average(v, half):
    out = []
    for i in range(len(v)):
        lo, hi = max(0, i - half), min(len(v), i + half + 1)
        out.append(sum(v[lo:hi]) / (hi - lo))
    return out


def parabola_acceleration(t, y):
    # least squares y = c0 + c1 s + c2 s^2, s = t - mean(t); returns -2 c2
    n = len(t)
    tm = sum(t) / n
    s = [x - tm for x in t]
    S = [sum(v ** k for v in s) for k in range(5)]
    b = [sum(y[i] * s[i] ** k for i in range(n)) for k in range(3)]
    A = [[S[0], S[1], S[2]], [S[1], S[2], S[3]], [S[2], S[3], S[4]]]
    # Cramer's rule on the 3x3 normal equations
    def det(M):
        return (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0])
                + M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]))
    D = det(A)
    A2 = [row[:] for row in A]
    for r in range(3):
        A2[r][2] = b[r]
    return -2.0 * det(A2) / D


def particle_noise(run, t0, t1):
    try:
        import glob
        import h5py
        import numpy as np
    except ImportError:
        return None
    times = []
    for line in open(os.path.join(run, "fields", "fluid.xdmf")):
        if "<Time Value=" in line:
            times.append(float(line.split('"')[1]))
    files = sorted(glob.glob(os.path.join(run, "fields", "fluid_0*.h5")))
    out = []
    for t, f in zip(times, files):
        if not (t0 < t <= t1 + 1e-9):
            continue
        with h5py.File(f, "r") as h:
            x, y, p = h["x"][:], h["y"][:], h["p"][:]
        s = (x >= 0.27) & (y <= 0.03)
        u, v = x[s] - 0.30, y[s]
        A = np.c_[np.ones(s.sum()), u, v, u * u, u * v, v * v]
        c, *_ = np.linalg.lstsq(A, p[s], rcond=None)
        out.append(float(np.sqrt(np.mean((p[s] - A @ c) ** 2))))
    return (sum(out) / len(out), len(out)) if out else None


def report(run, t0, t1):
    rows = list(csv.DictReader(open(os.path.join(run, "probes.csv"))))
    t = [float(r["t"]) for r in rows]
    summary = json.load(open(os.path.join(run, "summary.json")))
    events = summary.get("health_events", [])
    fatal = [e for e in events if e.get("fatal")]
    print(f"== {run}")
    print(f"   ended at t = {t[-1]:.3f} s, exit status {summary.get('exit_status')}, "
          f"{summary.get('steps')} steps" + (f"; fatal: {fatal[0].get('message')}" if fatal else ""))
    for wall in ("elevation_left", "elevation_right"):
        y = [float(r[wall]) for r in rows]
        k = max(range(len(y)), key=lambda i: y[i])
        print(f"   {wall}: max {y[k]:.3f} m at t = {t[k]:.3f} s")
        dt = t[1] - t[0]
        half = int(round(0.1 / dt))
        i = 1
        while i < len(y) - 1:
            lo, hi = max(0, i - 10), min(len(y), i + 11)
            if y[i] > 0.15 and y[i] == max(y[lo:hi]) and i - half >= 0 and i + half < len(y):
                a = parabola_acceleration(t[i - half:i + half + 1], y[i - half:i + half + 1])
                print(f"     run-up peak {y[i]:.3f} m at t = {t[i]:.3f} s: top falls at {a:.2f} m/s^2 "
                      f"({a / 9.81:.2f} g) over +-0.1 s")
                i += half
            i += 1
    p = [float(r["p_right_5mm"]) for r in rows]
    smooth = moving_average(p, 5)
    sel = [i for i in range(len(t)) if t0 <= t[i] <= t1]
    rms = (sum((p[i] - smooth[i]) ** 2 for i in sel) / len(sel)) ** 0.5
    k = max(range(len(p)), key=lambda i: p[i])
    print(f"   p_right_5mm: max {p[k]:.0f} Pa at t = {t[k]:.3f} s, min {min(p):.0f} Pa; "
          f"noise (RMS of p minus its 0.02 s moving average, {t0} s <= t <= {t1} s) {rms:.1f} Pa"
          + ("" if t[-1] >= t1 else f" (run ended at {t[-1]:.3f} s)"))
    pn = particle_noise(run, t0, t1)
    if pn:
        print(f"   particle pressure noise at the right wall's foot: {pn[0]:.1f} Pa (mean of {pn[1]} field outputs)")


if __name__ == "__main__":
    args = sys.argv[1:]
    t0, t1 = 0.05, 1.0
    if args[:1] == ["--window"]:
        t0, t1 = float(args[1]), float(args[2])
        args = args[3:]
    if not args:
        sys.exit(__doc__)
    for d in args:
        report(d, t0, t1)
