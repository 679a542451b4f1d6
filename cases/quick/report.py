"""Report of the default case (cases/quick/run.sh): plain vs convex in the reference study's
set-up at s = 7, the reduction with its 95 % interval as `wearsim compare` printed it, set
against the full study at the same s and beside the study's answer at s = 3.

Both study figures are computed here from the committed run summaries of the reference study
(cases/reference-study/results, docs/results/run_summary.py), with the study report's own
functions, so they are the figures of docs/results/reference-study.md:
- the full study at s = 7 (plain-s7, convex-s7: 3 dem-only and 2 staged revolutions, 1 mm
  mesh, two threads): the reduction over the 56 h (2 revolutions) after steady state;
- the study's answer (s = 3, seeds 1 to 3): the reduction at 56 h, mean +- 95 % interval over
  the seeds (Student t), and seed 1's at 184 h.

Writes <root>/report.md. With --update-readme it also writes the README's block between the
markers `<!-- quick-report:begin -->` and `<!-- quick-report:end -->` and copies the comparison
plot to docs/images/quick_compare.png, so the README's figures and picture are those of one
run of the default command, named by its engine version.

Refuses runs made by different engine versions (parameters.prm, "# Engine version:").

usage: report.py [--update-readme] [--from K] [--seconds S] <root>
       (<root> holds plain/, convex/ and compare.txt)
"""
import argparse
import datetime
import os
import re
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, "../.."))
sys.path.insert(0, os.path.join(REPO, "docs/results"))
from dem_reference_report import read as read_summary  # noqa: E402
from dem_reference_report import tables_of as study_tables  # noqa: E402
import reference_study_report as study  # noqa: E402

STUDY = os.path.join(REPO, "cases/reference-study/results")
AGREEMENT_PP = 10.0  # percentage points: how close the default case is held to the full study
BEGIN, END = "<!-- quick-report:begin -->", "<!-- quick-report:end -->"


def fail(message):
    sys.exit(f"report: {message}")


def engine_version(run):
    with open(os.path.join(run, "parameters.prm")) as f:
        for line in f:
            if line.startswith("# Engine version:"):
                return line.split(":", 1)[1].strip()
    fail(f"{run}/parameters.prm names no engine version (a run from before engine versions "
         "were recorded); run the default case again")


def per_revolution(run, first):
    """The run's revolutions from `first` on: (revolution, wear [mm^3], bottom speed [m/s])."""
    rows = [r for r in read_summary(run) if r["revolution"] >= first]
    if not rows:
        fail(f"{run}: no revolution from {first} on")
    return [(int(r["revolution"]), r["wear_volume_m3"] * 1e9, r["bottom_speed_mean_m_s"])
            for r in rows]


def reduction_line(compare_txt):
    """(A, a, B, b, reduction, half-width) of the 'wear [mm^3]' line of wearsim compare."""
    with open(compare_txt) as f:
        for line in f:
            if line.startswith("wear [mm^3]"):
                num = r"([-+]?[0-9.]+(?:e[-+]?[0-9]+)?)"
                m = re.search(rf"{num} \+- {num}\s+{num} \+- {num}\s+{num} \+- {num} %", line)
                if m:
                    return [float(x) for x in m.groups()]
    fail(f"{compare_txt} holds no 'wear [mm^3]' line with intervals")


def study_run(name):
    path = os.path.join(STUDY, name)
    if not os.path.isdir(path):
        fail(f"the study's summary '{path}' is missing (cases/reference-study/README.md: run "
             f"{name} with the study's engine)")
    return study.Run(path)


def reduction_at_56h(plain, convex):
    """Percent less wear of convex than plain over the 56 h after steady state, or None."""
    p, c = study.at(*plain.cumulative(), study.T56), study.at(*convex.cumulative(), study.T56)
    return None if p is None or c is None else 100.0 * (1.0 - c / p)


def full_study_at_s7():
    plain, convex = study_run("plain-s7"), study_run("convex-s7")
    red = reduction_at_56h(plain, convex)
    if red is None:
        fail("the full study at s = 7 has not reached 56 h after steady state")
    return red, plain.engine


def study_answer():
    """The study's s = 3 answer: the 56 h reduction over seeds 1 to 3 (mean, 95 % half-width,
    n) and seed 1's reduction at 184 h."""
    seeds = [r for r in (reduction_at_56h(study_run("plain" + t), study_run("convex" + t))
                         for t in ("", "-seed2", "-seed3")) if r is not None]
    mean, half = study.interval(seeds)
    plain, convex = study_run("plain"), study_run("convex")
    p, c = study.at(*plain.cumulative(), study.T184), study.at(*convex.cumulative(), study.T184)
    return mean, half, len(seeds), 100.0 * (1.0 - c / p), plain.engine


def block(version, seconds, first, plain, convex, compare):
    a, ha, b, hb, red, hred = compare
    full, full_engine = full_study_at_s7()
    s3, s3_half, n3, s3_184, s3_engine = study_answer()
    off = red - full
    within = abs(off) <= AGREEMENT_PP
    when = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    timing = f", {seconds // 60} min {seconds % 60:02d} s for the runs and the report" \
        if seconds is not None else ""
    w = [f"Engine version **{version}**, {when}, one run per sample, one thread each{timing} "
         "(`bash scripts/run_default_case.sh`).", "",
         "| revolution | plain [mm^3] | bottom speed [m/s] | convex [mm^3] | bottom speed [m/s] |",
         "|---|---|---|---|---|"]
    for (k, wp, vp), (_, wc, vc) in zip(plain, convex):
        w.append(f"| {k} | {wp:.2f} | {vp:.3f} | {wc:.2f} | {vc:.3f} |")
    w.append(f"| mean +- 95 % interval | {a:.3g} +- {ha:.2g} | | {b:.3g} +- {hb:.2g} | |")
    w.append("")
    w.append(f"The reference study's set-up at s = 7 (the holder, the consolidator, the "
             f"150-degree tester, the calibrated alpha; revolutions {first} to {plain[-1][0]}, "
             f"interval by batch means, `wearsim compare`): the convex sample wears "
             f"**{red:.1f} +- {hred:.1f} % less** than the plain one. The full study at s = 7 "
             f"(1 mm mesh, 56 h after steady state, engine {full_engine}) gives {full:.1f} %: "
             f"{off:+.1f} percentage points, "
             + ("within" if within else "**outside**")
             + f" the {AGREEMENT_PP:.0f} points the default case is held to.")
    w.append("")
    w.append(f"**The study's answer** (s = 3, the particle size the study calibrated at, "
             f"engine {s3_engine}, `docs/results/reference-study.md`): the convex sample wears "
             f"**{s3:.1f} +- {s3_half:.1f} % less** over the laboratory's 56 h (95 % interval over "
             f"{n3} insertion seeds), {s3_184:.1f} % over 184 h (seed 1). The reduction grows as "
             "the particles shrink towards the gravel's size (s = 7, 4, 3, 2 in the study's size "
             "trend), which is why the default case is held to the full study at its own s.")
    return "\n".join(w) + "\n", within, off


def update_readme(text, root):
    readme = os.path.join(REPO, "README.md")
    with open(readme) as f:
        old = f.read()
    if old.count(BEGIN) != 1 or old.count(END) != 1:
        fail(f"{readme} needs exactly one {BEGIN} ... {END} block")
    head, rest = old.split(BEGIN)
    _, tail = rest.split(END)
    with open(readme + ".tmp", "w") as f:
        f.write(head + BEGIN + "\n" + text + END + tail)
    os.replace(readme + ".tmp", readme)
    shutil.copyfile(os.path.join(root, "compare.png"),
                    os.path.join(REPO, "docs/images/quick_compare.png"))
    print("report: README.md block and docs/images/quick_compare.png updated")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("root")
    ap.add_argument("--update-readme", action="store_true")
    ap.add_argument("--from", dest="first", type=int, default=2,
                    help="first revolution averaged, as given to wearsim compare (default 2)")
    ap.add_argument("--seconds", type=int, default=None, help="wall time of the runs")
    args = ap.parse_args()

    runs = {k: os.path.join(args.root, k) for k in ("plain", "convex")}
    for d in runs.values():
        if not os.path.isfile(os.path.join(study_tables(d), "summary.csv")):
            fail(f"run folder {d} is missing or holds no summary.csv")
    versions = {engine_version(d) for d in runs.values()}
    if len(versions) != 1:
        fail(f"the runs come from different engine versions: {sorted(versions)}")
    plain, convex = (per_revolution(runs[k], args.first) for k in ("plain", "convex"))
    compare = reduction_line(os.path.join(args.root, "compare.txt"))
    text, within, off = block(versions.pop(), args.seconds, args.first, plain, convex, compare)
    with open(os.path.join(args.root, "report.md.tmp"), "w") as f:
        f.write("# The default case: plain vs convex in the study's set-up at s = 7\n\n" + text +
                "\nPlot: compare.png. Each run: plain/, convex/ (parts/sample/: summary.csv, stages.csv, "
                "history.xdmf, plots/).\n")
    os.replace(os.path.join(args.root, "report.md.tmp"), os.path.join(args.root, "report.md"))
    print(text)
    if args.update_readme:
        update_readme(text, args.root)
    if not within:
        print(f"report: the reduction lies {off:+.1f} points from the full study's at s = 7",
              file=sys.stderr)


if __name__ == "__main__":
    main()
