#!/usr/bin/python3
"""The wear tester as a scene against the built-in tester (scene_vs_tester.sh).

For each sample kind (plain, convex) and seed, the mean DEM wear-law volume per revolution
over revolutions FROM.. of stages.csv (one stage per revolution on both paths; a scene's in
parts/sample/, its wearing wall's folder), then per path
the mean over the seeds +- the 95 % interval (Student t, n - 1 degrees of freedom). The scene
agrees when its mean lies inside the built-in tester's interval (the ensemble spread).
Writes <root>/report.md and prints it; exits 1 when a kind disagrees, 2 on missing runs.

Then the reductions of `wearsim compare` (compare-*.txt beside the runs), if present.

usage: compare_scene.py [--from K] [--seconds S] [--cases DIR] <root> <seed> [<seed> ...]
"""
import argparse
import csv
import datetime
import math
import os
import statistics
import sys

# Student t, two-sided 95 %, by degrees of freedom
T95 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447, 7: 2.365, 8: 2.306,
       9: 2.262, 10: 2.228}


def engine_version(run):
    with open(os.path.join(run, "parameters.prm")) as f:
        for line in f:
            if line.startswith("# Engine version:"):
                return line.split(":", 1)[1].strip()
    sys.exit(f"compare_scene: {run}/parameters.prm names no engine version")


def wear_per_revolution(run, first):
    path = os.path.join(run, "stages.csv")
    if not os.path.isfile(path):  # a scene's: its wearing wall's
        path = os.path.join(run, "parts", "sample", "stages.csv")
    if not os.path.isfile(path):
        print(f"compare_scene: '{path}' does not exist (did the run finish?)", file=sys.stderr)
        sys.exit(2)
    with open(path) as f:
        rows = [r for r in csv.DictReader(f) if int(r["stage"]) >= first]
    if not rows:
        print(f"compare_scene: {path} has no revolution from {first} on", file=sys.stderr)
        sys.exit(2)
    return statistics.mean(float(r["dem_wear_volume_m3"]) for r in rows) * 1e9


def interval(values):
    m = statistics.mean(values)
    if len(values) < 2:
        return m, float("nan")
    return m, T95.get(len(values) - 1, 1.96) * statistics.stdev(values) / math.sqrt(len(values))


def main():
    a = argparse.ArgumentParser()
    a.add_argument("--from", dest="first", type=int, default=3)
    a.add_argument("--seconds", type=int, default=0)
    a.add_argument("--cases", default="cases/sector-30")
    a.add_argument("root")
    a.add_argument("seeds", nargs="+")
    o = a.parse_args()
    versions = {engine_version(os.path.join(o.root, f"{p}-{k}-{s}"))
                for p in ("tester", "scene") for k in ("plain", "convex") for s in o.seeds}
    if len(versions) != 1:
        sys.exit(f"compare_scene: the runs come from different engine versions {sorted(versions)}")
    lines = [f"Engine version **{versions.pop()}**, "
             f"{datetime.datetime.utcnow():%Y-%m-%d %H:%M} UTC, seeds {', '.join(o.seeds)}, one "
             "thread per run" + (f", {o.seconds // 60} min {o.seconds % 60} s for the runs"
                                 if o.seconds else "") + ".", "",
             f"Wear-law volume per revolution [mm^3], revolutions {o.first} to the last, "
             f"{o.cases} (built-in tester) and the same case written as a scene by `wearsim tester-scene` (scene):",
             "", "| kind | seed | tester | scene |", "|---|---|---|---|"]
    ok = True
    verdicts = []
    for kind in ("plain", "convex"):
        t = [wear_per_revolution(os.path.join(o.root, f"tester-{kind}-{s}"), o.first)
             for s in o.seeds]
        sc = [wear_per_revolution(os.path.join(o.root, f"scene-{kind}-{s}"), o.first)
              for s in o.seeds]
        for s, x, y in zip(o.seeds, t, sc):
            lines.append(f"| {kind} | {s} | {x:.3f} | {y:.3f} |")
        (tm, th), (sm, sh) = interval(t), interval(sc)
        lines.append(f"| {kind} | mean +- 95 % | {tm:.3f} +- {th:.3f} | {sm:.3f} +- {sh:.3f} |")
        inside = abs(sm - tm) <= th
        ok = ok and inside
        verdicts.append(f"{kind}: the scene's mean {sm:.3f} lies {'inside' if inside else 'OUTSIDE'} "
                        f"the tester's {tm:.3f} +- {th:.3f} mm^3 per revolution "
                        f"({100 * (sm - tm) / tm:+.1f} %).")
    lines += [""] + verdicts
    for name, what in (("tester", "built-in tester, convex against plain"),
                       ("scene", "the tester as a scene, convex against plain"),
                       ("plain", "plain sample, the scene against the tester"),
                       ("convex", "convex sample, the scene against the tester")):
        path = os.path.join(o.root, f"compare-{name}.txt")
        if os.path.isfile(path):
            with open(path) as f:
                text = [l.rstrip() for l in f]
            lines += ["", f"`wearsim compare --part sample --from {o.first}`, {what}:", ""]
            lines += [f"    {l}" for l in text]
    text = "\n".join(lines) + "\n"
    with open(os.path.join(o.root, "report.md"), "w") as f:
        f.write(text)
    print(text, end="")
    print(f"written to {os.path.join(o.root, 'report.md')}")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
