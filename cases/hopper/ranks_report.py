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
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "cases", "hopper"))
from discharge import engine, mean_interval, rate  # noqa: E402

T_FROM, T_TO = 0.7, 1.2  # [s]
BEGIN, END = "<!-- ranks table: begin -->", "<!-- ranks table: end -->"


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    out = args[0] if args else os.path.join(ROOT, "output", "hopper-ranks")
    runs, engines = {}, set()
    for name in sorted(os.listdir(out)):
        m = re.fullmatch(r"r(\d+)-s(\d+)", name)
        series = os.path.join(out, name, "scene_series.csv")
        if not m or not os.path.exists(series):
            continue
        w = rate(series, T_FROM, T_TO)
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
