#!/usr/bin/env python3
"""The hopper over ranks (cases/hopper/README.md, "Over ranks") from the runs of ranks.sh.

    /usr/bin/python3 cases/hopper/ranks_report.py [output/hopper-ranks] [--update-readme]

Per run, the discharge rate W [kg/s] is the least-squares slope of the outlet's mass
(scene_series.csv, outlet_below_mass_kg) against time over 0.7 <= t <= 1.2 s: from 0.25 s
after the plug starts to drop to the run's end. Every rank count of one seed starts from the
same inserted bed (every rank inserts it from the seed and keeps its slab), so the rank
counts are compared seed by seed: (W_n - W_1) / W_1 and its mean over the seeds with the 95 %
interval of Student's t (n - 1 degrees of freedom). A rank count gives the one process's W
within the spread of seeds when that interval contains 0; beside it, each rank count's mean W
and the seeds' spread (95 % interval of the mean). Wall time per run from the log's clock
is not kept: the runs of 4 ranks share 2 cores.
With --update-readme the table replaces the block between the README's markers.
"""
import csv
import math
import os
import re
import sys

T_FROM, T_TO = 0.7, 1.2 + 1e-3  # [s] the rows land within a time step of the interval
T95 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447, 7: 2.365, 8: 2.306,
       9: 2.262, 10: 2.228}
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BEGIN, END = "<!-- ranks table: begin -->", "<!-- ranks table: end -->"


def rate(series):
    """[kg/s] slope of the outlet's mass over T_FROM <= t <= T_TO; None if the run is short."""
    t, m = [], []
    with open(series) as f:
        for row in csv.DictReader(f):
            time = float(row["time_s"])
            if T_FROM - 1e-3 <= time <= T_TO:
                t.append(time)
                m.append(float(row["outlet_below_mass_kg"]))
    if not t or t[-1] < 1.2 - 1e-3:
        return None
    tm, mm = sum(t) / len(t), sum(m) / len(m)
    return sum((a - tm) * (b - mm) for a, b in zip(t, m)) / sum((a - tm) ** 2 for a in t)


def engine(folder):
    with open(os.path.join(folder, "parameters.prm")) as f:
        for line in f:
            if line.startswith("# Engine version:"):
                return line.split(":", 1)[1].strip()
    return "unknown"


def mean_interval(x):
    n = len(x)
    m = sum(x) / n
    if n < 2:
        return m, float("nan")
    s = math.sqrt(sum((v - m) ** 2 for v in x) / (n - 1))
    return m, T95.get(n - 1, 1.96) * s / math.sqrt(n)


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    out = args[0] if args else os.path.join(ROOT, "output", "hopper-ranks")
    runs, engines = {}, set()
    for name in sorted(os.listdir(out)):
        m = re.fullmatch(r"r(\d+)-s(\d+)", name)
        series = os.path.join(out, name, "scene_series.csv")
        if not m or not os.path.exists(series):
            continue
        w = rate(series)
        if w is not None:
            runs[(int(m.group(1)), int(m.group(2)))] = w
            engines.add(engine(os.path.join(out, name)))
    seeds = sorted({s for (_, s) in runs})
    lines = ["Engine version %s; W from 0.7 to 1.2 s; seeds %s." %
             (", ".join(sorted(engines)), ", ".join(map(str, seeds))), "",
             "| ranks x threads | W per seed [kg/s] | mean W +- 95 % [kg/s] | "
             "(W_n - W_1) / W_1, mean +- 95 % |", "|---|---|---|---|"]
    for ranks in sorted({r for (r, _) in runs}):
        w = [runs[(ranks, s)] for s in seeds if (ranks, s) in runs]
        mw, hw = mean_interval(w)
        paired = [(runs[(ranks, s)] - runs[(1, s)]) / runs[(1, s)]
                  for s in seeds if (ranks, s) in runs and (1, s) in runs]
        diff = "" if ranks == 1 or not paired else "%+.1f %% +- %.1f %%" % tuple(
            100 * v for v in mean_interval(paired))
        lines.append("| %d x %d | %s | %.3f +- %.3f | %s |" %
                     (ranks, 2 if ranks == 1 else 1, ", ".join("%.3f" % v for v in w), mw, hw,
                      diff))
    table = "\n".join(lines)
    print(table)
    if "--update-readme" in sys.argv:
        path = os.path.join(ROOT, "cases", "hopper", "README.md")
        text = open(path).read()
        a, b = text.index(BEGIN) + len(BEGIN), text.index(END)
        open(path, "w").write(text[:a] + "\n" + table + "\n" + text[b:])


if __name__ == "__main__":
    main()
