#!/usr/bin/env python3
"""Compares two run folders' tables column by column, as text, leaving out the wall-clock
columns (which differ between any two runs): summary.csv and stages.csv (a tester case's are
its part's, parts/sample/) and scene_series.csv, those that either run has. Exits 1 on any
difference, a table one run lacks included.

    python3 scripts/compare_physical_columns.py RUN_A RUN_B

Used to show that a change leaves a run's results bit for bit as they were (the CSV files
print 10 significant digits; the DEM is chaotic, so a change of rounding anywhere in the
loop shows up in them within a revolution).
"""
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "coupling", "output"))
from run_tables import tables_of  # noqa: E402  (where a run's tables are)

WALL_CLOCK = {"wall_seconds", "particle_steps_per_s", "dem_s", "wear_s", "fem_solve_s",
              "mesh_motion_s", "remesh_s", "output_s"}


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        sys.exit(f"{path}: empty")
    return rows[0], rows[1:]


def compare(a, b):
    head_a, rows_a = read(a)
    head_b, rows_b = read(b)
    if head_a != head_b:
        print(f"{a} and {b}: different columns")
        return 1
    if len(rows_a) != len(rows_b):
        print(f"{a}: {len(rows_a)} rows, {b}: {len(rows_b)} rows")
        return 1
    keep = [k for k, name in enumerate(head_a) if name not in WALL_CLOCK]
    n_diff = 0
    for r, (ra, rb) in enumerate(zip(rows_a, rows_b), start=2):
        for k in keep:
            if ra[k] != rb[k]:
                n_diff += 1
                if n_diff <= 10:
                    print(f"{a} line {r} column {head_a[k]}: {ra[k]} != {rb[k]}")
    print(f"{b}: {len(rows_b)} rows x {len(keep)} physical columns, "
          f"{'identical' if n_diff == 0 else str(n_diff) + ' values differ'} "
          f"({len(head_a) - len(keep)} wall-clock columns left out)")
    return 1 if n_diff else 0


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    a, b = sys.argv[1:]
    pairs = [(os.path.join(tables_of(a), name), os.path.join(tables_of(b), name))
             for name in ("summary.csv", "stages.csv")]
    pairs.append((os.path.join(a, "scene_series.csv"), os.path.join(b, "scene_series.csv")))
    pairs = [(x, y) for x, y in pairs if os.path.isfile(x) or os.path.isfile(y)]
    if not pairs:
        sys.exit(f"{a} and {b} hold no summary.csv, stages.csv or scene_series.csv")
    status = 0
    for x, y in pairs:  # a table one run has and the other lacks is a difference
        status |= compare(x, y) if os.path.isfile(x) and os.path.isfile(y) else (
            print(f"{x if not os.path.isfile(x) else y}: missing") or 1)
    return status


if __name__ == "__main__":
    sys.exit(main())
