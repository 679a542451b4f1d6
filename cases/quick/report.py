"""Report of the default case (cases/quick/ensemble.sh): plain vs convex over several
insertion seeds, the reduction with its 95 % interval as `wearsim compare` printed it, set
against the full-size tester's figure at the same particle size.

Writes <root>/report.md. With --update-readme it also writes the README's block between
the markers `<!-- quick-report:begin -->` and `<!-- quick-report:end -->` and copies the
comparison plot to docs/images/quick_compare.png, so the README's figures and picture are
always those of one run of the default command, named by its engine version.

Refuses runs made by different engine versions (parameters.prm, "# Engine version:").

usage: report.py [--update-readme] [--from K] [--seconds S] <root> <seed> [<seed> ...]
       (<root> holds plain-<seed>/, convex-<seed>/ and compare.txt)
"""
import argparse
import datetime
import os
import re
import shutil
import statistics
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, "../.."))
sys.path.insert(0, os.path.join(REPO, "docs/results"))
from dem_reference_report import read as read_summary  # noqa: E402

# The full 150-degree tester at s = 4 without the holder (cases/quick/full-tester, engine
# ef5c1696864e, revolutions 3 to 8 of wearsim compare: plain 62.42 +- 1.3, convex
# 34.98 +- 0.89 mm^3 per revolution); cases/quick/README.md, "The yardstick".
FULL_TESTER = {"reduction_percent": 44.0, "half_width": 1.6,
               "where": "cases/quick/full-tester, the full tester at s = 4 without holder, "
                        "engine ef5c1696864e"}
AGREEMENT_PP = 10.0  # percentage points: issue 36's "representative" bound
BEGIN, END = "<!-- quick-report:begin -->", "<!-- quick-report:end -->"


def engine_version(run):
    with open(os.path.join(run, "parameters.prm")) as f:
        for line in f:
            if line.startswith("# Engine version:"):
                return line.split(":", 1)[1].strip()
    sys.exit(f"report: {run}/parameters.prm names no engine version (a run from before "
             "engine versions were recorded); run the default case again")


def per_run(run, first):
    rows = [r for r in read_summary(run) if r["revolution"] >= first]
    if not rows:
        sys.exit(f"report: {run}: no revolution from {first} on")
    mean = lambda key: statistics.mean(r[key] for r in rows)
    return {"wear": mean("wear_volume_m3") * 1e9, "speed": mean("bottom_speed_mean_m_s"),
            "force": mean("normal_force_mean_N")}


def reduction_line(compare_txt):
    """(A, a, B, b, reduction, half-width) of the 'wear [mm^3]' line of wearsim compare."""
    with open(compare_txt) as f:
        for line in f:
            if line.startswith("wear [mm^3]"):
                num = r"([-+]?[0-9.]+(?:e[-+]?[0-9]+)?)"
                m = re.search(rf"{num} \+- {num}\s+{num} \+- {num}\s+{num} \+- {num} %", line)
                if m:
                    return [float(x) for x in m.groups()]
    sys.exit(f"report: {compare_txt} holds no 'wear [mm^3]' line with intervals")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("root")
    ap.add_argument("seeds", nargs="+")
    ap.add_argument("--update-readme", action="store_true")
    ap.add_argument("--from", dest="first", type=int, default=3,
                    help="first revolution averaged, as given to wearsim compare (default 3)")
    ap.add_argument("--seconds", type=int, default=None, help="wall time of the runs")
    args = ap.parse_args()

    runs = {(k, s): os.path.join(args.root, f"{k}-{s}") for s in args.seeds
            for k in ("plain", "convex")}
    for d in runs.values():
        if not os.path.isfile(os.path.join(d, "summary.csv")):
            sys.exit(f"report: run folder {d} is missing or holds no summary.csv")
    versions = {engine_version(d) for d in runs.values()}
    if len(versions) != 1:
        sys.exit(f"report: the runs come from different engine versions: {sorted(versions)}")
    version = versions.pop()
    a, ha, b, hb, red, hred = reduction_line(os.path.join(args.root, "compare.txt"))
    ref = FULL_TESTER["reduction_percent"]
    off = red - ref
    within = abs(off) <= AGREEMENT_PP

    lines = []
    when = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    timing = f", {args.seconds // 60} min {args.seconds % 60:02d} s for the runs and the report" \
        if args.seconds is not None else ""
    lines.append(f"Engine version **{version}**, {when}, {len(args.seeds)} seeds per sample "
                 f"({', '.join(args.seeds)}), one thread per run{timing} "
                 "(`bash scripts/run_default_case.sh`).")
    lines.append("")
    lines.append("| seed | plain [mm^3/rev] | bottom speed [m/s] | convex [mm^3/rev] | "
                 "bottom speed [m/s] | reduction |")
    lines.append("|---|---|---|---|---|---|")
    for s in args.seeds:
        p, c = per_run(runs[("plain", s)], args.first), per_run(runs[("convex", s)], args.first)
        lines.append(f"| {s} | {p['wear']:.2f} | {p['speed']:.3f} | {c['wear']:.2f} | "
                     f"{c['speed']:.3f} | {100 * (1 - c['wear'] / p['wear']):.0f} % |")
    lines.append(f"| mean +- 95 % interval | {a:.3g} +- {ha:.2g} | | {b:.3g} +- {hb:.2g} | | "
                 f"**{red:.1f} +- {hred:.1f} %** |")
    lines.append("")
    lines.append(f"Wear of the wear face per revolution, revolutions {args.first} to 6 (the staged "
                 "ones, wear amplified 20x). The convex sample wears "
                 f"**{red:.0f} +- {hred:.0f} % less** than the plain one (95 % interval across "
                 f"the seeds, `wearsim compare`); the full tester gives {ref:.1f} +- "
                 f"{FULL_TESTER['half_width']:.1f} % "
                 f"({FULL_TESTER['where']}): {off:+.1f} percentage points, "
                 + ("within" if within else "**outside**")
                 + f" the {AGREEMENT_PP:.0f} points the default case is held to.")
    text = "\n".join(lines) + "\n"

    with open(os.path.join(args.root, "report.md"), "w") as f:
        f.write("# The default case: plain vs convex over seeds\n\n" + text +
                "\nPlot: compare.png. Each run: <kind>-<seed>/ (summary.csv, stages.csv, "
                "history.xdmf, plots/).\n")
    print(text)
    if args.update_readme:
        readme = os.path.join(REPO, "README.md")
        with open(readme) as f:
            old = f.read()
        if old.count(BEGIN) != 1 or old.count(END) != 1:
            sys.exit(f"report: {readme} needs exactly one {BEGIN} ... {END} block")
        head, rest = old.split(BEGIN)
        _, tail = rest.split(END)
        with open(readme + ".tmp", "w") as f:
            f.write(head + BEGIN + "\n" + text + END + tail)
        os.replace(readme + ".tmp", readme)
        shutil.copyfile(os.path.join(args.root, "compare.png"),
                        os.path.join(REPO, "docs/images/quick_compare.png"))
        print("report: README.md block and docs/images/quick_compare.png updated")
    if not within:
        print(f"report: the reduction lies {off:+.1f} points from the full tester's", file=sys.stderr)


if __name__ == "__main__":
    main()
