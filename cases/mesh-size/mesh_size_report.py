#!/usr/bin/python3
"""Steady-state wear of several wear-tester runs side by side (the mesh-size study).

Usage: /usr/bin/python3 cases/mesh-size/mesh_size_report.py <run> [<run> ...]

Reads each run's summary.csv (parts/sample/ of a `wearsim run` or `wearsim dem` folder) and prints a Markdown table:
the mean over the revolutions after steady state of the wear-face wear, its per-column
wear, the mean wear increment per convex element and the normal force, each with its
standard error over those revolutions (std / sqrt(n)), and every run's ratio to the first.
Steady state is the run's own judgement, or revolution 2 when it never judged itself steady
(the reference runs were steady from revolution 2 to 4). A difference between two runs is
within their scatter when it is below about twice the combined standard errors.
"""
import math
import os
import sys

# The steady-state rule and the summary reader of the reference report, so both reports
# agree on which revolutions count.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../docs/results"))
from dem_reference_report import mean_se, read, steady_from  # noqa: E402

FALLBACK_STEADY = 2
MM3 = 1e9


def after_steady(rows):
    s, _ = steady_from(rows, FALLBACK_STEADY)
    return s, [r for r in rows if int(r["revolution"]) > s]


def main():
    runs = sys.argv[1:]
    if not runs:
        sys.exit(__doc__)
    quantities = [("wear per revolution [mm^3]", "wear_volume_m3", MM3)]
    quantities += [(f"column {c} [mm^3]", f"column{c}_wear_m3", MM3) for c in range(1, 6)]
    quantities += [
        ("element increment dv [mm^3]", "mean_element_increment_m3", MM3),
        ("normal force [N]", "normal_force_mean_N", 1.0),
        ("sides and bottom [mm^3]", "wear_volume_other_m3", MM3),
    ]
    stats, header = [], []
    for run in runs:
        rows = read(run)
        s, tail = after_steady(rows)
        if not tail:
            sys.exit(f"mesh_size_report: '{run}' has no revolution after steady state ({s})")
        header.append(f"revolutions {s + 1}-{int(rows[-1]['revolution'])}")
        stats.append({key: mean_se([r[key] * scale for r in tail])
                      for _, key, scale in quantities})
    names = [os.path.basename(os.path.normpath(r)) for r in runs]
    print("| | " + " | ".join(names) + " | " +
          " | ".join(f"{n} / {names[0]}" for n in names[1:]) + " |")
    print("|---" * (1 + 2 * len(runs) - 1) + "|")
    print("| after steady state | " + " | ".join(header) + " |" + " |" * (len(runs) - 1))
    for label, key, _ in quantities:
        base = stats[0][key][0]
        if all(st[key][0] == 0 for st in stats):
            continue  # a plain sample has no elements
        cells = [f"{m:.3g}" + ("" if math.isnan(se) else f" ± {se:.2g}")
                 for m, se in (st[key] for st in stats)]
        ratios = [f"{st[key][0] / base:.3f}" if base else "" for st in stats[1:]]
        print(f"| {label} | " + " | ".join(cells + ratios) + " |")


if __name__ == "__main__":
    main()
