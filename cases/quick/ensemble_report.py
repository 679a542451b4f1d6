"""Ensemble table of the quick case: wear per revolution of plain and convex runs that
differ only in the insertion seed, with the bed's slip speed and normal force beside them.

The wear of a sample the bed slides over follows Archard: volume ~ alpha F_n v t. Where the
seed changes the wear, the table shows whether it changed the flow (the bottom layer's speed
v) or the wear per unit of flow (wear / (F_n v), in mm^3 per revolution per N m/s).

usage: ensemble_report.py <run dir> ...   (directories named <kind>-<seed>, as
       cases/quick/ensemble.sh writes them; each holds summary.csv)
"""
import os
import statistics
import sys

# The summary reader and the mean with its standard error of the other study reports.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../docs/results"))
from dem_reference_report import mean_se, read as read_summary  # noqa: E402


def read(run):
    rows = read_summary(run)
    mean = lambda key: statistics.mean(r[key] for r in rows)
    wear = mean("wear_volume_m3") * 1e9  # [mm^3] per revolution
    speed = mean("bottom_speed_mean_m_s")  # [m/s]
    force = mean("normal_force_mean_N")  # [N]
    return {"wear": wear, "speed": speed, "force": force, "per_flow": wear / (force * speed)}


def main(runs):
    if not runs:
        sys.exit(__doc__)
    table = {}
    for run in runs:
        name = os.path.basename(os.path.normpath(run))
        kind, _, seed = name.rpartition("-")
        if kind not in ("plain", "convex"):
            sys.exit(f"ensemble_report: {run}: expected a directory named plain-<seed> or convex-<seed>")
        table.setdefault(seed, {})[kind] = read(run)
    print("seed    | plain: wear [mm^3/rev]  v_bottom [m/s]  F_n [N]  wear/(F_n v) | "
          "convex: wear  v_bottom  F_n  wear/(F_n v) | reduction")
    for seed, k in table.items():
        cells = []
        for kind in ("plain", "convex"):
            r = k.get(kind)
            cells.append("-" if r is None else
                         f"{r['wear']:6.2f} {r['speed']:6.3f} {r['force']:5.1f} {r['per_flow']:6.3f}")
        red = (f"{100 * (1 - k['convex']['wear'] / k['plain']['wear']):5.0f} %"
               if len(k) == 2 else "-")
        print(f"{seed:7} | {cells[0]:>36} | {cells[1]:>28} | {red}")
    for key, label in (("wear", "wear per revolution [mm^3]"), ("speed", "bottom speed [m/s]"),
                       ("per_flow", "wear / (F_n v)")):
        parts = []
        for kind in ("plain", "convex"):
            vals = [k[kind][key] for k in table.values() if kind in k]
            if vals:
                m, se = mean_se(vals)
                parts.append(f"{kind} {m:.3g} +- {se:.2g} (min {min(vals):.3g}, max {max(vals):.3g})")
        print(f"{label}, mean +- standard error over seeds: " + "; ".join(parts))
    both = [k for k in table.values() if len(k) == 2]
    if both:
        p = statistics.mean(k["plain"]["wear"] for k in both)
        c = statistics.mean(k["convex"]["wear"] for k in both)
        reds = [1 - k["convex"]["wear"] / k["plain"]["wear"] for k in both]
        print(f"reduction of the ensemble means: {100 * (1 - c / p):.0f} % "
              f"(single seeds {100 * min(reds):.0f} to {100 * max(reds):.0f} %, {len(both)} seeds)")


if __name__ == "__main__":
    main(sys.argv[1:])
