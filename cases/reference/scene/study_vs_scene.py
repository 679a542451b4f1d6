#!/usr/bin/python3
"""A pair of the reference study's cases run again on the current engine against the study's
own runs.

Reads the study's stored summaries (cases/reference-study/results/<kind>-<variant>/
summary.csv, engine in their parameters.prm: the built-in tester for the study's engine) and
the runs of the same cases on the engine under test (`wearsim run` of a case that INCLUDEs
cases/reference-study/<kind>-<variant>.prm and sets its Output/Directory to <root>/<kind>:
<root>/<kind>/parts/sample/summary.csv). For each path and sample kind: the wear-law volume
per revolution over revolutions FROM.. as mean +- 95 % interval (Student t over the
revolutions, each revolution taken as one sample of the steady flow: one seed per path), and
per column. The scene agrees when its mean lies inside the built-in run's interval and the
difference's interval (Welch, the two paths' revolutions) holds zero.

usage: study_vs_scene.py [--from K] [--variant s4] <root>
       (variant: the study's case suffix, s4 or s7; root: the new runs' folder, e.g. output/s4-scene)
"""
import argparse
import csv
import math
import os
import statistics
import sys

T95 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447, 7: 2.365, 8: 2.306}
STUDY = os.path.join(os.path.dirname(__file__), "..", "..", "reference-study", "results")


def engine(run):
    with open(os.path.join(run, "parameters.prm")) as f:
        for line in f:
            if line.startswith("# Engine version:"):
                return line.split(":", 1)[1].strip()
    return "?"


def revolutions(summary, first):
    if not os.path.isfile(summary):
        sys.exit(f"study_vs_scene: '{summary}' does not exist (did the run finish a stage?)")
    with open(summary) as f:
        rows = [r for r in csv.DictReader(f) if int(r["revolution"]) >= first]
    if len(rows) < 2:
        sys.exit(f"study_vs_scene: {summary} has fewer than 2 revolutions from {first} on")
    return rows


def interval(values):
    m = statistics.mean(values)
    return m, T95.get(len(values) - 1, 1.96) * statistics.stdev(values) / math.sqrt(len(values))


def welch(a, b):
    va, vb = statistics.variance(a) / len(a), statistics.variance(b) / len(b)
    dof = (va + vb) ** 2 / (va**2 / (len(a) - 1) + vb**2 / (len(b) - 1))
    t = T95.get(max(1, int(dof)), 1.96)
    return statistics.mean(b) - statistics.mean(a), t * math.sqrt(va + vb)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--from", dest="first", type=int, default=2)
    p.add_argument("--variant", default="s4", help="the study's case suffix (s4, s7)")
    p.add_argument("root")
    a = p.parse_args()
    disagree = False
    for kind in ("plain", "convex"):
        study = os.path.join(STUDY, f"{kind}-{a.variant}")
        scene = os.path.join(a.root, kind)
        rs = revolutions(os.path.join(study, "summary.csv"), a.first)
        rc = revolutions(os.path.join(scene, "parts", "sample", "summary.csv"), a.first)
        print(f"## {kind}-{a.variant}, revolutions {a.first}..: built-in tester (engine "
              f"{engine(study)}, {len(rs)} revolutions) against the scene (engine "
              f"{engine(scene)}, {len(rc)} revolutions) [mm^3 per revolution]\n")
        print("| figure | built-in tester | scene | scene - tester |")
        print("|---|---|---|---|")
        columns = ["wear_volume_m3"] + [f"column{j}_wear_m3" for j in range(1, 6)]
        for c in columns:
            xs = [float(r[c]) * 1e9 for r in rs]
            xc = [float(r[c]) * 1e9 for r in rc]
            ms, hs = interval(xs)
            mc, hc = interval(xc)
            d, hd = welch(xs, xc)
            name = "wear" if c == "wear_volume_m3" else c.replace("_wear_m3", "")
            holds = abs(d) <= hd
            print(f"| {name} | {ms:.3f} +- {hs:.3f} | {mc:.3f} +- {hc:.3f} | "
                  f"{d:+.3f} +- {hd:.3f}{'' if holds else ' (does not hold 0)'} |")
            if c == "wear_volume_m3" and abs(mc - ms) > hs:
                disagree = True
        print()
    sys.exit(1 if disagree else 0)


if __name__ == "__main__":
    main()
