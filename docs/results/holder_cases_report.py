#!/usr/bin/python3
"""The wear-out and stress cases in the holder (issue 32, item 6), reported from their runs' summaries.

Usage: /usr/bin/python3 docs/results/holder_cases_report.py [--root DIR] [--out DIR]
           [--engine VERSION] [--check]

--root    a folder holding the three summaries stress-plain, stress-convex and
          wear-out-convex (default: each beside its case, cases/stress/results/stress-plain,
          cases/stress/results/stress-convex and, for the wear-out run of the reference
          study's engine, cases/wear-out/results/wear-out-convex-b13327c60d5d)
--out     where holder-cases.md and its plots go (default docs/results)
--engine  the engine version every run must name (default cases/reference-study/ENGINE, the
          reference study's engine, so that these results sit beside the study's)
--check   only read and check the summaries; print what would be reported, write nothing

A summary folder is what docs/results/run_summary.py writes from a run folder
(cases/reference-study/run.sh does after every call); its stages.csv, parameters.prm,
elements.csv and ending.txt are read, nothing else. A run missing is listed as not run; a run
of another engine version, or one that names none, is refused, as is a root with none of the
three runs. A run still in progress is reported as far as it got (its stages done of those
planned), and how it ended is the summary's ending.txt, from the log run.sh writes beside its
run folder.

A staged stage stands for (revolutions) x (amplification) x 28 h of the laboratory test
(docs/wear-tester.md); `dem-only` stages wear nothing and stand for no hours. The stage's
DEM wear (`dem_wear_volume_m3`, Archard alone, one revolution) and its applied volume
(`applied_volume_m3`: amplified and, with the stress-informed law on, scaled by
1 + c (sigma_vM / sigma_ref)^m per face) are told apart, so that the law's effect on the
convex/plain comparison shows as the difference of the two ratios.
"""
import os
import sys

import matplotlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reference_study_report import (HOURS_PER_REV, Run, fail, fmt, has_revolution, parse_args,  # noqa: E402
                                    prm_settings, write_atomic)

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PROG = os.path.basename(sys.argv[0])
NAMES = {"stress-plain": "cases/stress/plain.prm", "stress-convex": "cases/stress/convex.prm",
         "wear-out-convex": "cases/wear-out/convex.prm"}
# Each run's summary beside its case file: cases/<case>/results/<run>.
SUMMARIES = {n: os.path.join(os.path.dirname(prm), "results", n) for n, prm in NAMES.items()}
# The wear-out run this report shows is the one the reference study's engine made; the
# wear-out study's own runs (cases/wear-out/ENGINE) write their summaries beside it.
SUMMARIES["wear-out-convex"] += "-b13327c60d5d"


def staged(run):
    """The run's staged stages, each with the laboratory hours the stages up to it stand for."""
    rows, hours = [], 0.0
    for r in run.stages:
        if r["scheme_name"] != "staged":
            continue
        hours += (r["last_revolution"] - r["first_revolution"] + 1) * r["amplification"] * HOURS_PER_REV
        rows.append(dict(r, cumulative_hours=hours))
    return rows


def load(root, engine):
    """The runs found ({name: Run}, in root or, root None, beside their case files) and those
    not found; stops when none is found or one names another engine."""
    runs, missing = {}, []
    for name in NAMES:
        path = os.path.join(root, name) if root else SUMMARIES[name]
        if has_revolution(path) and os.path.isfile(os.path.join(path, "stages.csv")):
            runs[name] = Run(path)
        else:
            missing.append(name + (" (started, no revolution done yet)" if os.path.isdir(path) else ""))
    if not runs:
        fail(f"none of the runs {', '.join(NAMES)} is in '{root or ', '.join(SUMMARIES.values())}' "
             f"(bash cases/reference-study/run.sh {' '.join(NAMES.values())})")
    odd = {n: r.engine for n, r in runs.items() if r.engine != engine}
    if odd:
        fail("runs of another engine version than " + engine + " ("
             + ", ".join(f"{n}: {e}" for n, e in odd.items()) + "); re-run them with the study's engine "
             "(cases/reference-study/run.sh)")
    return runs, missing


def stage_table(rows, columns):
    """Markdown rows of (heading, function of a stage row) columns."""
    out = ["| " + " | ".join(h for h, _ in columns) + " |", "|" + "---|" * len(columns)]
    for r in rows:
        out.append("| " + " | ".join(f(r) for _, f in columns) + " |")
    return out


def mm3(r, key):
    return r[key] * 1e9


def mpa(r, key):
    return fmt(r[key] / 1e6, 3) if r[key] > 0 else "-"


def plot(runs, out):
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.0))
    styles = {"stress-plain": ("tab:blue", "o-"), "stress-convex": ("tab:orange", "o-"),
              "wear-out-convex": ("tab:green", "s-")}
    for name, run in runs.items():
        rows = staged(run)
        if not rows:
            continue
        colour, style = styles[name]
        h = [0.0] + [r["cumulative_hours"] for r in rows]
        v = [0.0] + [r["cumulative_applied_m3"] * 1e9 for r in rows]
        a1.plot(h, v, style, color=colour, ms=3, label=name)
        a2.plot([r["cumulative_hours"] for r in rows], [r["max_von_mises_ball_Pa"] / 1e6 for r in rows], style,
                color=colour, ms=3, label=name)
    a1.set_xlabel("laboratory hours the staged stages stand for [h]")
    a1.set_ylabel("cumulative applied wear [mm$^3$]")
    a1.legend(fontsize=8)
    a2.set_xlabel("laboratory hours [h]")
    a2.set_ylabel("largest ball-averaged von Mises stress [MPa]")
    a2.legend(fontsize=8)
    fig.tight_layout()
    tmp = os.path.join(out, ".holder_cases.png.tmp")
    fig.savefig(tmp, dpi=120, format="png")
    plt.close(fig)
    os.replace(tmp, os.path.join(out, "holder_cases.png"))


def ending(run):
    """How the run ended: finished, or as run.sh's last call left it (Run.last_call_ending),
    a SIGTERM's checkpoint being where run.sh continues it."""
    if run.planned_stages("staged") == len(staged(run)):
        return "finished"
    if not run.has_log():
        return "in progress or stopped (no log beside the run folder)"
    last = run.last_call_ending()
    if last is None:
        return "in progress, or killed without a message"
    return last + (", continued from its checkpoint by run.sh" if last.startswith("stopped by SIGTERM") else "")


def run_table(runs, missing):
    w = ["| run | case file | schedule | staged stages done | hours they stand for | wall time [h] | how it ended |",
         "|---|---|---|---|---|---|---|"]
    for name, r in runs.items():
        rows = staged(r)
        plan = r.planned_stages("staged")
        done = f"{len(rows)} of {plan}" if plan else str(len(rows))
        hours = rows[-1]["cumulative_hours"] if rows else 0.0
        w.append(f"| {name} | `{r.case}` | {r.planned} | {done} | {hours:.0f} | {r.wall_hours():.1f} | {ending(r)} |")
    w.append("")
    if missing:
        w.append("**Not run** with this engine: " + ", ".join(missing) + ".\n")
    return w


def stress_section(runs):
    P, C = runs.get("stress-plain"), runs.get("stress-convex")
    w = ["## Stress-informed wear, plain and convex (`cases/stress`)\n"]
    if not P or not C:
        w.append("Not reported: " + ("both runs are" if not P and not C else "one of the pair is")
                 + " not run yet.\n")
        return w
    s = prm_settings(os.path.join(P.path, "parameters.prm"))
    on = s.get("Enabled") == "true"  # the first `Enabled` of the resolved file is this law's
    w.append(("The law: s = 1 + " + f"{s.get('Sensitivity', '?')} (sigma_vM / {s.get('Reference stress', '?')} Pa)"
              f"^{s.get('Exponent', '?')}" if on else "The stress-informed law is **off** in these runs")
             + f"; amplification {s.get('Amplification', '?')} a stage.\n")
    sp, sc = staged(P), staged(C)
    n = min(len(sp), len(sc))
    rows = [(a, b) for a, b in zip(sp[:n], sc[:n])]
    w.append("Per staged stage (stages both runs have done): DEM wear is the stage's Archard wear "
             "of the sample (one revolution, before amplification and the law); applied is what "
             "the stage removed from the geometry.\n")
    cols = [("stage", lambda p: f"{int(p[0]['stage'])}"),
            ("hours", lambda p: f"{p[0]['cumulative_hours']:.0f}"),
            ("DEM wear plain [mm^3]", lambda p: fmt(mm3(p[0], "dem_wear_volume_m3"))),
            ("DEM wear convex [mm^3]", lambda p: fmt(mm3(p[1], "dem_wear_volume_m3"))),
            ("applied plain [mm^3]", lambda p: fmt(mm3(p[0], "applied_volume_m3"), 1)),
            ("applied convex [mm^3]", lambda p: fmt(mm3(p[1], "applied_volume_m3"), 1)),
            ("stress factor plain / convex", lambda p: f"{p[0]['mean_stress_factor']:.3f} / {p[1]['mean_stress_factor']:.3f}"),
            ("von Mises plain / convex [MPa]", lambda p: f"{mpa(p[0], 'max_von_mises_ball_Pa')} / {mpa(p[1], 'max_von_mises_ball_Pa')}"),
            ("safety factor plain / convex", lambda p: f"{fmt(p[0]['safety_factor'], 0)} / {fmt(p[1]['safety_factor'], 0)}")]
    w += stage_table(rows, cols)
    w.append("")
    if n:
        # applied per unit amplification: the law's factor alone, whatever the amplification
        dem = [sum(r["dem_wear_volume_m3"] for r in x[:n]) for x in (sp, sc)]
        app = [sum(r["applied_volume_m3"] / r["amplification"] for r in x[:n]) for x in (sp, sc)]
        r_dem = dem[1] / dem[0] if dem[0] > 0 else float("nan")
        r_app = app[1] / app[0] if app[0] > 0 else float("nan")
        w.append(f"Over the {n} staged stages both have done ({sp[n - 1]['cumulative_hours']:.0f} h): "
                 f"convex/plain of the DEM (Archard) wear **{r_dem:.3f}**, of the applied wear per unit "
                 f"amplification **{r_app:.3f}** ({app[0] * 1e9:.1f} and {app[1] * 1e9:.1f} mm^3). "
                 + (f"The law {'narrows' if r_app > r_dem else 'widens'} the convex sample's advantage by "
                    f"{abs(r_app - r_dem) * 100:.1f} percentage points.\n" if abs(r_app - r_dem) >= 5e-4 else
                    "The two agree to 0.05 percentage points.\n"))
    return w


def wear_out_section(runs):
    W = runs.get("wear-out-convex")
    w = ["## Wear-out of the convex sample (`cases/wear-out`)\n"]
    if not W:
        w.append("Not run yet.\n")
        return w
    rows = staged(W)
    cols = [("stage", lambda r: f"{int(r['stage'])}"),
            ("amplification", lambda r: f"{r['amplification']:.2f}"),
            ("hours", lambda r: f"{r['cumulative_hours']:.0f}"),
            ("applied [mm^3]", lambda r: fmt(mm3(r, "applied_volume_m3"), 1)),
            ("cumulative [mm^3]", lambda r: fmt(mm3(r, "cumulative_applied_m3"), 1)),
            ("deepest recession [mm]", lambda r: fmt(r["max_depth_m"] * 1e3, 3)),
            ("remeshes", lambda r: f"{int(r['remeshes'])}"),
            ("min scaled Jacobian", lambda r: fmt(r["min_scaled_jacobian"], 3)),
            ("von Mises [MPa]", lambda r: mpa(r, "max_von_mises_ball_Pa")),
            ("worn-through faces", lambda r: f"{int(r['worn_through_faces'])}")]
    w += stage_table(rows, cols)
    w.append("")
    if rows:
        last = rows[-1]
        w.append(f"After {len(rows)} staged stages ({last['cumulative_hours']:.0f} h of the laboratory test) "
                 f"the sample has lost {last['cumulative_applied_m3'] * 1e9:.1f} mm^3; the deepest recession of "
                 f"the last stage was {last['max_depth_m'] * 1e3:.3f} mm. The run: {ending(W)}.\n")
    w += heights_section(W)
    return w


def element_heights(run, stage):
    """Each element's (label ij >= 11, C<ij>, i its column along the flow) highest point above the
    unworn base top [mm] on the stage's surface; the base top is where the elements stand on the
    unworn surface (their lowest point there)."""
    extents = run.element_extents()
    unworn, worn = extents.get(0, {}), extents.get(stage, {})
    base_top = min((bottom for _, bottom in unworn.values()), default=float("nan"))
    return ({k: (top - base_top) * 1e3 for k, (top, _) in unworn.items()},
            {k: (top - base_top) * 1e3 for k, (top, _) in worn.items() if k in unworn})


def heights_section(run):
    """A grid of the elements' heights on the last kept surface (columns along the flow, rows across it)."""
    stage = run.last_surface()
    if stage is None:
        return []
    unworn, worn = element_heights(run, stage)
    if not worn:
        return []
    cols = sorted({k // 10 for k in worn})
    rows = sorted({k % 10 for k in worn})
    lo, hi = min(unworn.values()), max(unworn.values())
    w = [f"Element heights after stage {stage}: each element's highest point above the unworn base top [mm] "
         f"(unworn {lo:.2f}{f' to {hi:.2f}' if hi - lo >= 0.005 else ''}; below zero the element is gone and "
         "the base around it has receded). Column 1 meets the flow first; row 1 is at the inner radius.\n",
         "| row | " + " | ".join(f"column {c}" for c in cols) + " |", "|" + "---|" * (len(cols) + 1)]
    for r in rows:
        w.append(f"| {r} | " + " | ".join(f"C{c}{r} {worn[10 * c + r]:.2f}" if 10 * c + r in worn else ""
                                         for c in cols) + " |")
    w.append("")
    return w


def report(runs, missing, engine):
    w = ["# The wear-out and stress cases in the holder\n",
         "Generated by `/usr/bin/python3 docs/results/holder_cases_report.py` from the run folders; "
         "do not edit by hand.\n",
         f"**Engine version** {engine} (every run below; the reference study's, "
         "`cases/reference-study/ENGINE`). The cases: the study's samples in their holder in the "
         "150-degree tester at s = 4 with a 3 mm sample mesh (`cases/stress/README.md`, "
         "`cases/wear-out/README.md`).\n"]
    w += run_table(runs, missing)
    w.append("A staged stage stands for its revolutions x its amplification x 28 h of the laboratory test.\n")
    w.append("![applied wear and stress](holder_cases.png)\n")
    w += stress_section(runs)
    w += wear_out_section(runs)
    return "\n".join(w)


def main(argv):
    args, check_only = parse_args(argv, {"--root": None, "--out": "docs/results", "--engine": None},
                                  __doc__.splitlines()[2])
    engine = args["--engine"]
    if engine is None:
        with open("cases/reference-study/ENGINE") as f:
            engine = f.read().strip()
    runs, missing = load(args["--root"], engine)
    if check_only:
        print(f"{PROG}: {len(runs)} runs ({', '.join(f'{n}: {len(staged(r))} staged' for n, r in runs.items())}), "
              f"engine {engine}; not run: {', '.join(missing) or 'none'}")
        return
    out = args["--out"]
    os.makedirs(out, exist_ok=True)
    plot(runs, out)
    write_atomic(os.path.join(out, "holder-cases.md"), report(runs, missing, engine))
    print(f"{PROG}: {os.path.join(out, 'holder-cases.md')} from {len(runs)} runs, engine {engine}")


if __name__ == "__main__":
    main(sys.argv[1:])
