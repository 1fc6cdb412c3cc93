#!/usr/bin/python3
"""Strong scaling past this machine, by model: the predicted parallel efficiency of a water-only scene on many
ranks from what a 1-rank and a 2-rank run of it measured, and a stated network.

usage: tools/scaling_model.py RUN_1 RUN_2 [--ranks 2,8,64,256,1024] [--latency 1.5e-6] [--bandwidth 12.5e9]
                              [--collectives 3] [--ghost-weight 0.5] [--imbalance 1.03] [--markdown]

RUN_1, RUN_2: run folders (their summary.json) of the same scene on 1 and 2 ranks, e.g. from
`jobscripts/scaling --strong inputs/bench/long_tank.yaml --ranks 1,2`.

The model of one step on P ranks (docs/scaling.md states it with its assumptions):
  T_P = imbalance * (t_1 / P) * node_factor * (1 + ghost_weight * g / (N / P))         compute
      + neighbours(P) * (m * latency + b / bandwidth)                                  halo and migration
      + collectives * 2 * log2(P) * latency                                            the step's reductions
with t_1 the 1-rank time per step, N the particles, m and b the messages and bytes a rank sends one neighbour a
step (from the 2-rank run, where each rank has one neighbour), g the ghosts from one neighbour (b over the 88
bytes a ghost carries a step: 6 state values, its id, two 2-vectors), node_factor the 2-rank run's compute per
particle over the 1-rank run's (two ranks sharing a node's memory bandwidth), neighbours(P) = 2 for the strips a
long tank is cut into (1 at P = 2). Efficiency E = t_1 / (P T_P).
"""
import argparse
import json
import math
import os
import sys

GHOST_BYTES = 6 * 8 + 8 + 2 * 8 + 2 * 8  # x, y, vx, vy, rho, m; gid; grad rho; the second 2-vector update


def steps_this_run(s):
    """The steps its loop wall time and timers count: a restarted run's since its restart."""
    return s.get("steps_this_run", s["steps"])


def load(run):
    path = os.path.join(run, "summary.json")
    if not os.path.isfile(path):
        sys.exit(f"tools/scaling_model.py: no summary.json in '{run}'")
    with open(path) as f:
        return json.load(f)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("run1")
    ap.add_argument("run2")
    ap.add_argument("--ranks", default="2,8,64,256,1024")
    ap.add_argument("--latency", type=float, default=1.5e-6)      # s, one message (InfiniBand class)
    ap.add_argument("--bandwidth", type=float, default=12.5e9)   # B/s, 100 Gb/s
    ap.add_argument("--collectives", type=int, default=3)  # a step's all-reductions: sph_collectives' 2 + the stop check
    ap.add_argument("--ghost-weight", type=float, default=0.5)   # a ghost's cost against an owned particle's
    ap.add_argument("--imbalance", type=float, default=1.03)     # METIS's default 3 % tolerance
    ap.add_argument("--markdown", action="store_true")
    a = ap.parse_args()
    s1, s2 = load(a.run1), load(a.run2)
    if s1.get("ranks") != 1 or s2.get("ranks") != 2:
        sys.exit("tools/scaling_model.py: RUN_1 must be a 1-rank run and RUN_2 a 2-rank run of the same scene")
    n = s1["initial_particles"]
    t1 = s1["loop_wall_time"] / steps_this_run(s1)
    d2 = s2["ranks_detail"]
    m = max(d2["messages_sent_per_step"])
    b = max(d2["bytes_sent_per_step"])
    g = b / GHOST_BYTES
    c1 = s1["ranks_detail"]["compute_seconds"][0] / steps_this_run(s1)
    c2 = max(d2["compute_seconds"]) / steps_this_run(s2)
    node = c2 / (c1 / 2)
    rows = []
    for p in [int(x) for x in a.ranks.split(",")]:
        neighbours = 1 if p == 2 else 2
        compute = a.imbalance * (t1 / p) * node * (1 + a.ghost_weight * g / (n / p))
        halo = neighbours * (m * a.latency + b / a.bandwidth)
        reductions = a.collectives * 2 * math.log2(p) * a.latency
        tp = compute + halo + reductions
        rows.append((p, n / p, 1e3 * compute, 1e3 * halo, 1e3 * reductions, 1e3 * tp, t1 / (p * tp)))
    head = (f"N = {n} particles, t_1 = {1e3 * t1:.1f} ms a step; from the 2-rank run: {m:.1f} messages and "
            f"{b / 1e3:.1f} kB to a neighbour a step ({g:.0f} ghosts), node factor {node:.3f}; latency "
            f"{1e6 * a.latency:g} us, bandwidth {a.bandwidth / 1e9:g} GB/s, {a.collectives} reductions a step, "
            f"ghost weight {a.ghost_weight}, imbalance {a.imbalance}")
    print(head if not a.markdown else head + "\n")
    print("| ranks | particles per rank | compute [ms] | halo [ms] | reductions [ms] | step [ms] | efficiency |")
    print("|---|---|---|---|---|---|---|")
    for p, per, c, h, r, t, e in rows:
        print(f"| {p} | {per:,.0f} | {c:.3f} | {h:.4f} | {r:.4f} | {t:.3f} | {100 * e:.0f} % |")


if __name__ == "__main__":
    main()
