#!/usr/bin/python3
"""The speed check against LIGGGHTS on a scene (run.sh): per core count and snapshot setting,
each code's whole-run wall time per step (median over the rounds) and, round by round, how
many times faster ours ran than LIGGGHTS in the same round; the particles left in the bin at
1.0 s beside them (the same scene drains alike). Prints a Markdown table.

usage: report.py [output/bin-vs-liggghts/times.csv]
"""
import csv
import statistics
import sys


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "output/bin-vs-liggghts/times.csv"
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"report: {path} holds no run")
    runs = {}
    for r in rows:
        key = (int(r["cores"]), int(r["snapshots"]), r["code"])
        runs.setdefault(key, {})[int(r["round"])] = r
    engines = sorted({r["engine"] for r in rows if r["code"] == "ours"})
    print(f"Engine {', '.join(engines)} against LIGGGHTS 3.8; whole runs of "
          f"{rows[0]['steps']} steps (1.0 s), seconds per run and microseconds per step.\n")
    print("| cores | snapshots | ours [s] | ours [us/step] | LIGGGHTS [s] | LIGGGHTS [us/step] "
          "| LIGGGHTS / ours, per round | particles left (ours, LIGGGHTS) |")
    print("|---|---|---|---|---|---|---|---|")
    worst = None
    for cores in (1, 2):
        for snap in (0, 1):
            ours = runs.get((cores, snap, "ours"), {})
            lig = runs.get((cores, snap, "liggghts"), {})
            both = sorted(set(ours) & set(lig))
            if not both:
                continue
            t_o = statistics.median(float(ours[k]["seconds"]) for k in both)
            t_l = statistics.median(float(lig[k]["seconds"]) for k in both)
            steps = int(ours[both[0]]["steps"])
            ratios = [float(lig[k]["seconds"]) / float(ours[k]["seconds"]) for k in both]
            worst = min(ratios + ([worst] if worst is not None else []))
            left = (", ".join(ours[k]["particles_left"] for k in both) + "; " +
                    ", ".join(lig[k]["particles_left"] for k in both))
            print(f"| {cores} | {'yes' if snap else 'no'} | {t_o:.1f} | {1e6 * t_o / steps:.0f} "
                  f"| {t_l:.1f} | {1e6 * t_l / steps:.0f} | "
                  f"{', '.join(f'{x:.2f}' for x in ratios)} | {left} |")
    print(f"\nSmallest ratio in any round: {worst:.2f}")


if __name__ == "__main__":
    main()
