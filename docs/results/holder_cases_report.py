#!/usr/bin/python3
"""The wear-out and stress cases in the holder, reported from their runs' summaries.

Usage: /usr/bin/python3 docs/results/holder_cases_report.py [--root DIR] [--out DIR]
           [--engine VERSION] [--check]

--root    a folder holding the summaries stress-plain, stress-convex, wear-out-convex and
          wear-out-plain (default: each beside its case, cases/<case>/results/<run>)
--out     where holder-cases.md and its plots go (default docs/results)
--engine  the engine version every run must name (default: each run its own study's, the
          ENGINE file beside its case: cases/reference-study/ENGINE for the stress pair, so
          that they sit beside the reference study's results, cases/wear-out/ENGINE for the
          wear-out pair)
--check   only read and check the summaries; print what would be reported, write nothing

A summary folder is what docs/results/run_summary.py writes from a run folder
(cases/reference-study/run.sh does after every call); its stages.csv, parameters.prm,
elements.csv, part_life.csv and ending.txt are read, nothing else. A run missing is listed as
not run; a run of another engine version than its study's, or one that names none, is refused,
as is a root with none of the runs. A run still in progress is reported as far as it got (its
stages done of those planned), and how it ended is the summary's ending.txt, from the log
run.sh writes beside its run folder.

A staged stage stands for (revolutions) x (amplification) x 28 h of the laboratory test
(docs/wear-tester.md); `dem-only` stages wear nothing and stand for no hours. The stage's
DEM wear (`dem_wear_volume_m3`, Archard alone, one revolution) and its applied volume
(`applied_volume_m3`: amplified and, with the stress-informed law on, scaled by
1 + c (sigma_vM / sigma_ref)^m per face) are told apart, so that the law's effect on the
convex/plain comparison shows as the difference of the two ratios. The wear-out pair's life
(elements standing, element volume left, the hours at which half of it is gone) and its
convex/plain ratio at equal hours are computed in wear_out_life.py.
"""
import os
import sys

import matplotlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reference_study_report import (Run, fail, fmt, has_revolution, parse_args,  # noqa: E402
                                    prm_settings, write_atomic)
from wear_out_life import (Life, cumulative_ratio, element_label_wear, hours_at_fraction, interpolate,  # noqa: E402
                           rate_ratio, staged)

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PROG = os.path.basename(sys.argv[0])
REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
# Each run: its case file and the ENGINE file of its study (the one beside the case file).
NAMES = {"stress-plain": "cases/stress/plain.prm", "stress-convex": "cases/stress/convex.prm",
         "wear-out-convex": "cases/wear-out/convex.prm", "wear-out-plain": "cases/wear-out/plain.prm",
         "wear-out-convex-fine": "cases/wear-out/convex-fine.prm",
         "wear-out-convex-a10": "cases/wear-out/convex-a10.prm",
         "wear-out-convex-stages": "cases/wear-out/convex-stages.prm",
         "wear-out-convex-curved": "cases/wear-out/curved/convex-curved.prm",
         "wear-out-convex-curved-fine": "cases/wear-out/curved/convex-curved-fine.prm",
         "wear-out-convex-front": "cases/wear-out/front/convex-front.prm",
         "wear-out-convex-front-a10": "cases/wear-out/front/convex-front-a10.prm",
         "wear-out-convex-front-curved": "cases/wear-out/front/convex-front-curved.prm",
         "wear-out-convex-front-curved-fine": "cases/wear-out/front/convex-front-curved-fine.prm"}
# The ENGINE file beside each case file, else the reference study's (as run.sh chooses).
STUDY_ENGINE = {n: (os.path.join(os.path.dirname(prm), "ENGINE")
                    if os.path.isfile(os.path.join(REPO, os.path.dirname(prm), "ENGINE"))
                    else "cases/reference-study/ENGINE") for n, prm in NAMES.items()}
# The convergence of the pattern's life: the wear-out's convex run (mesh size h, amplification
# A) beside the same at h/2 and at A/2; and h beside h/2 with the first mesh refined at the
# curved element surfaces; and A beside A/2, h beside h/2 (curvature-refined) with the implicit step
# that puts its zero set onto the exact front. Each: (run, what it is, the run it is compared with).
CONVERGENCE = (("wear-out-convex-stages", "h, A", None),
               ("wear-out-convex-fine", "h/2, A", "wear-out-convex-stages"),
               ("wear-out-convex-a10", "h, A/2", "wear-out-convex-stages"),
               ("wear-out-convex-curved", "h, A, curvature-refined first mesh", None),
               ("wear-out-convex-curved-fine", "h/2, A, curvature-refined first mesh", "wear-out-convex-curved"),
               ("wear-out-convex-front", "h, A, implicit step onto the exact front", None),
               ("wear-out-convex-front-a10", "h, A/2, implicit step onto the exact front", "wear-out-convex-front"),
               ("wear-out-convex-front-curved", "h, A, curvature-refined, onto the exact front", None),
               ("wear-out-convex-front-curved-fine", "h/2, A, curvature-refined, onto the exact front",
                "wear-out-convex-front-curved"))
# Each run's colour and line in the plots.
STYLES = {"stress-plain": ("tab:blue", "o-"), "stress-convex": ("tab:orange", "o-"),
          "wear-out-convex": ("tab:green", "s-"), "wear-out-plain": ("tab:purple", "s-"),
          "wear-out-convex-fine": ("tab:olive", "^:"), "wear-out-convex-a10": ("tab:cyan", "v:"),
          "wear-out-convex-stages": ("tab:gray", "s:"),
          "wear-out-convex-curved": ("tab:red", "d-."), "wear-out-convex-curved-fine": ("tab:pink", "x-."),
          "wear-out-convex-front": ("tab:brown", "P--"), "wear-out-convex-front-a10": ("tab:blue", "*--"),
          "wear-out-convex-front-curved": ("tab:purple", "d--"),
          "wear-out-convex-front-curved-fine": ("k", "x--")}
# Each run's summary beside its case file: cases/<case>/results/<run>.
SUMMARIES = {n: os.path.join(REPO, os.path.dirname(prm), "results", n) for n, prm in NAMES.items()}


def study_engines(engine):
    """{run: the engine version it must name}: `engine` for all, or each its study's ENGINE file."""
    if engine is not None:
        return {n: engine for n in NAMES}
    out = {}
    for n, path in STUDY_ENGINE.items():
        with open(os.path.join(REPO, path)) as f:
            out[n] = f.read().strip()
    return out


def load(root, engines):
    """The runs found ({name: Run}, in root or, root None, beside their case files) and those
    not found; stops when none is found or one names another engine than its study's."""
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
    odd = {n: r.engine for n, r in runs.items() if r.engine != engines[n]}
    if odd:
        fail("runs of another engine version than their study's ("
             + ", ".join(f"{n}: {e}, not {engines[n]}" for n, e in odd.items())
             + "); re-run them with the study's engine (cases/reference-study/run.sh)")
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


def save_figure(fig, out, name):
    tmp = os.path.join(out, "." + name + ".tmp")
    fig.savefig(tmp, dpi=120, format="png")
    plt.close(fig)
    os.replace(tmp, os.path.join(out, name))


def plot(runs, out):
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.0))
    for name, run in runs.items():
        rows = staged(run)
        if not rows:
            continue
        colour, style = STYLES[name]
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
    save_figure(fig, out, "holder_cases.png")


def plot_wear_out(runs, out):
    """wear_out.png: the DEM wear of a revolution of both samples, their ratio at equal hours, and
    the convex elements' volume left and elements standing, against the hours (with the
    convergence runs' volume left)."""
    C, P = runs.get("wear-out-convex"), runs.get("wear-out-plain")
    fig, (a1, a2, a3) = plt.subplots(1, 3, figsize=(15, 4.0))
    for run, colour, label in ((C, "tab:green", "convex"), (P, "tab:purple", "plain")):
        if run is None:
            continue
        rows = staged(run)
        a1.plot([r["start_hours"] for r in rows], [r["dem_wear_volume_m3"] * 1e9 for r in rows], "o-",
                color=colour, ms=3, label=label)
    a1.set_xlabel("laboratory hours before the stage [h]")
    a1.set_ylabel("DEM wear of one revolution [mm$^3$]")
    a1.legend(fontsize=8)
    if C is not None and P is not None:
        ratios = rate_ratio(C, P)
        a2.plot([r[1] for r in ratios], [r[4] for r in ratios], "o-", color="tab:red", ms=3,
                label="wear of a revolution")
        cum = cumulative_ratio(C, P)
        a2.plot([c[0] for c in cum], [c[3] for c in cum], "s--", color="tab:gray", ms=3,
                label="cumulative applied wear")
        a2.legend(fontsize=8)
    a2.set_xlabel("laboratory hours [h]")
    a2.set_ylabel("convex / plain at equal hours")
    life = Life(C) if C is not None else None
    if life:
        f = life.element_fraction()
        a3.plot([h for h, _ in f], [100 * x for _, x in f], "o-", color="tab:green", ms=3, label="h, A")
        for name, what, _ in CONVERGENCE[1:]:
            other = Life(runs[name]) if name in runs else None
            if other:
                g = other.element_fraction()
                colour, style = STYLES[name]
                a3.plot([h for h, _ in g], [100 * x for _, x in g], style, color=colour, ms=3, label=what)
        a3.axhline(50, color="0.7", lw=0.8)
        a3.legend(fontsize=8, loc="lower left")
        a3.set_ylabel("element volume left [%]", color="tab:green")
        b3 = a3.twinx()
        b3.step([life.hours[k] for k in life.stages], [life.n_standing(k) for k in life.stages], where="post",
                 color="tab:brown")
        b3.set_ylabel(f"elements standing (of {life.n_elements()})", color="tab:brown")
        b3.set_ylim(0, life.n_elements() + 1)
        a3.set_ylim(0, 105)
    a3.set_xlabel("laboratory hours after the stage [h]")
    fig.tight_layout()
    save_figure(fig, out, "wear_out.png")


def ending(run):
    """How the run ended: finished, or as run.sh's last call left it (Run.last_call_ending),
    a SIGTERM's checkpoint being where run.sh continues it, or worn out (its end criterion met)."""
    last = run.last_call_ending()
    if last is not None and last.startswith("worn out at"):
        return last
    if run.planned_stages("staged") == len(staged(run)):
        return "finished"
    if not run.has_log():
        return "in progress or stopped (no log beside the run folder)"
    if last is None:
        return "in progress, or killed without a message"
    return last + (", continued from its checkpoint by run.sh" if last.startswith("stopped by SIGTERM") else "")


def run_table(runs, missing):
    w = ["| run | case file | engine | schedule | staged stages done | hours they stand for | wall time [h] | how it ended |",
         "|---|---|---|---|---|---|---|---|"]
    for name, r in runs.items():
        rows = staged(r)
        plan = r.planned_stages("staged")
        done = f"{len(rows)} of {plan}" if plan else str(len(rows))
        hours = rows[-1]["cumulative_hours"] if rows else 0.0
        w.append(f"| {name} | `{r.case}` | {r.engine} | {r.planned} | {done} | {hours:.0f} | {r.wall_hours():.1f} | {ending(r)} |")
    w.append("")
    if missing:
        w.append("**Not run** with its study's engine: " + ", ".join(missing) + ".\n")
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
    C, P = runs.get("wear-out-convex"), runs.get("wear-out-plain")
    w = ["## Wear-out of the convex sample, beside the plain one (`cases/wear-out`)\n"]
    if not C:
        w.append("Not run yet.\n")
        return w
    rows = staged(C)
    cols = [("stage", lambda r: f"{int(r['stage'])}"),
            ("amplification", lambda r: f"{r['amplification']:.2f}"),
            ("hours", lambda r: f"{r['cumulative_hours']:.0f}"),
            ("applied [mm^3]", lambda r: fmt(mm3(r, "applied_volume_m3"), 1)),
            ("cumulative [mm^3]", lambda r: fmt(mm3(r, "cumulative_applied_m3"), 1)),
            ("deepest recession [mm]", lambda r: fmt(r["max_depth_m"] * 1e3, 3)),
            ("remeshes (first attempt)",
             lambda r: f"{int(r['remeshes'])} ({int(r.get('first_attempt_remeshes', r['remeshes']))})"),
            ("min scaled Jacobian", lambda r: fmt(r["min_scaled_jacobian"], 3)),
            ("von Mises [MPa]", lambda r: mpa(r, "max_von_mises_ball_Pa")),
            ("worn-through faces", lambda r: f"{int(r['worn_through_faces'])}")]
    w.append("The convex run's staged stages (hours: after the stage):\n")
    w += stage_table(rows, cols)
    w.append("")
    if rows:
        last = rows[-1]
        remeshes = sum(int(r["remeshes"]) for r in rows)
        first = sum(int(r.get("first_attempt_remeshes", r["remeshes"])) for r in rows)
        w.append(f"After {len(rows)} staged stages ({last['cumulative_hours']:.0f} h of the laboratory test) "
                 f"the sample has lost {last['cumulative_applied_m3'] * 1e9:.1f} mm^3; the deepest recession of "
                 f"the last stage was {last['max_depth_m'] * 1e3:.3f} mm; "
                 + (f"{first} of its {remeshes} remeshes met the quality floor at the first attempt "
                    f"({100.0 * first / remeshes:.0f} %). " if remeshes else "no stage remeshed. ")
                 + f"The run: {ending(C)}.\n")
    w += life_section(C, P)
    w += ratio_section(C, P)
    w += heights_section(C)
    w += convergence_section(runs)
    return w


def convergence_section(runs):
    """The hours at which half the element volume is gone, at h and A, h/2 and A/2, and at h and
    h/2 with the first mesh refined at the curved element surfaces; each against its pair's
    first run, beside the elements' volume on the first mesh (what the mesh size changes most),
    by the run's own measure (the foot its labels span) and on the unworn footprints."""
    w = ["**Convergence of the pattern's life**: the hours at which half the convex elements' volume is "
         "gone (linear between stages), with the sample mesh halved (`convex-fine.prm`) and the "
         "amplification halved (`convex-a10.prm`) against `convex-stages.prm` (`convex.prm`'s first "
         "stages again, every surface kept), and at h and h/2 with the first mesh refined at the curved "
         "element surfaces (`curved/convex-curved.prm`, `curved/convex-curved-fine.prm`), and at A and A/2 "
         "with the implicit step that puts the new surface onto the exact front (`front/convex-front.prm`, "
         "`front/convex-front-a10.prm`, the schedules of `convex-stages.prm` and `convex-a10.prm`) and at h and "
         "h/2 curvature-refined by the same engine (`front/convex-front-curved.prm`, "
         "`front/convex-front-curved-fine.prm`); each differs "
         "from the run named by the percentage given. Two measures of the element volume: the run's own "
         "(`part_life.csv`), above the foot each element's labels span, which moves with the boundary "
         "between its label and the base's as each stage's surface takes its labels from the last; and "
         "on the unworn footprints (`element_life.csv`, `wearsim life <run>` on the surfaces the run "
         "kept), above the worn surface's heights along each element's outline on the first mesh, "
         "which do not move. Beside them, the wear the stages removed from the element labels by the "
         "first measure's hour (`part_wear.csv`). The elements' volume on the first mesh is the meshed "
         "one (the 23 half-ellipsoids hold 23 x 2/3 pi a b h = 4,624 mm^3 on the reference pattern).\n",
         "| run | mesh size, amplification | sample mesh [mm] | amplification | staged stages | "
         "elements' volume on the first mesh [mm^3] | half gone, labels' foot [h] | against | "
         "wear removed from the element labels by then [mm^3] | half gone, unworn footprints [h] | against |",
         "|---|---|---|---|---|---|---|---|---|---|---|"]
    half, kept, measured_by = {}, {}, set()
    for name, what, against in CONVERGENCE:
        run = runs.get(name)
        if run is None:
            w.append(f"| {name} | {what} | | | | | not run | | | | |")
            continue
        life, foot = Life(run), Life(run, "element_life.csv")
        measured_by |= foot.measured_by
        half[name] = hours_at_fraction(life.element_fraction(), 0.5) if life else None
        kept[name] = hours_at_fraction(foot.element_fraction(), 0.5) if foot else None

        def left(lf):
            if not lf:
                return "not measured"
            v = lf.element_volume(lf.stages[-1]) / lf.element_volume(lf.stages[0])
            return f"not yet ({100 * v:.1f} % left after {lf.hours[lf.stages[-1]]:.0f} h)"

        def diff(figures):
            base = figures.get(against)
            return (f"{100 * (figures[name] / base - 1):+.1f} % against {against}"
                    if figures[name] is not None and base else "")

        start = f"{life.element_volume(life.stages[0]) * 1e9:,.0f}" if life else ""
        labels = element_label_wear(run)
        points = [(life.hours[k], labels.get(k, 0.0)) for k in life.stages] if life else []
        by_then = (f"{1e9 * interpolate(half[name], [h for h, _ in points], [v for _, v in points]):,.0f}"
                   if half[name] is not None and labels else "")
        w.append(f"| {name} | {what} | {float(run.params.get('Mesh size', 'nan')) * 1e3:g} | "
                 f"{run.params.get('Amplification', '?')} | {len(staged(run))} | {start} | "
                 f"{f'{half[name]:.0f}' if half[name] is not None else left(life)} | {diff(half)} | {by_then} | "
                 f"{f'{kept[name]:.0f}' if kept[name] is not None else left(foot)} | {diff(kept)} |")
    w.append("")
    if measured_by:
        w.append("The unworn footprints measured by `wearsim life` of engine "
                 + ", ".join(sorted(measured_by)) + ".\n")
    return w


def life_section(C, P):
    """The convex elements' life per stage (part_life.csv), and the plain sample's thinnest point."""
    life = Life(C)
    if not life:
        return ["The convex run records no part life (an engine older than `part_life.csv`).\n"]
    v0, n0 = life.element_volume(life.stages[0]), life.n_elements()
    w = [f"**The pattern's life** (`parts/sample/part_life.csv`): an element stands while its top is more than "
         f"{life.vanish * 1e3:.2f} mm above its foot (the implicit recession's vanish height, also the end "
         f"criterion `elements gone`); its volume is what lies above its foot, {v0 * 1e9:.0f} mm^3 for the "
         f"{n0} unworn elements. The thinnest point is the part's lowest wear-face point above its clamped "
         "bottom.\n",
         "| stage | hours | elements standing | element volume left [mm^3] | left [%] | tallest / lowest element [mm] "
         "| convex thinnest [mm] | plain thinnest at these hours [mm] |",
         "|---|---|---|---|---|---|---|---|"]
    plain = Life(P) if P is not None else None
    for k in life.stages:
        h = life.hours[k]
        if h == 0 and k != life.stages[0] and life.hours.get(k - 1) == 0:
            continue  # dem-only stages: nothing worn yet, the first row stands for them
        heights = [e[0] * 1e3 for e in life.elements[k].values()]
        thin = "-"
        if plain:
            xs = [plain.hours[j] for j in plain.stages]
            t = interpolate(h, xs, [plain.part[j][0] for j in plain.stages])
            thin = f"{t * 1e3:.2f}" if t is not None else "-"
        ev = life.element_volume(k)
        extremes = f"{max(heights):.2f} / {min(heights):.2f}" if heights else "none left"
        w.append(f"| {k} | {h:.0f} | {life.n_standing(k)} | {ev * 1e9:.0f} | {100 * ev / v0:.1f} | "
                 f"{extremes} | {life.part[k][0] * 1e3:.2f} | {thin} |")
    w.append("")
    half = hours_at_fraction(life.element_fraction(), 0.5)
    w.append("**Half the element volume gone** at "
             + (f"{half:.0f} h (linear between the two stages around it).\n" if half is not None else
                f"(not yet: {100 * life.element_volume(life.stages[-1]) / v0:.1f} % left after "
                f"{life.hours[life.stages[-1]]:.0f} h).\n"))
    return w


def ratio_section(C, P):
    """The convex/plain ratio at equal hours, of the wear of a revolution and cumulative."""
    w = ["**Convex / plain at equal hours** (the plain run interpolated in hours at the convex run's, "
         "nothing extrapolated; `wear_out.png`):\n", "![wear-out life and ratio](wear_out.png)\n"]
    if P is None:
        w.append("Not reported: the plain run is not run yet.\n")
        return w
    ratios = rate_ratio(C, P)
    if not ratios:
        w.append("Not reported yet: the plain run covers none of the convex run's staged stages.\n")
        return w
    w += ["| convex stage | hours before it | DEM wear of a revolution, convex [mm^3] | plain [mm^3] | convex / plain |",
          "|---|---|---|---|---|"]
    w += [f"| {k} | {h:.0f} | {c * 1e9:.2f} | {p * 1e9:.2f} | {r:.3f} |" for k, h, c, p, r in ratios]
    w.append("")
    cum = cumulative_ratio(C, P)
    if cum:
        h, c, p, r = cum[-1]
        w.append(f"Over the first {h:.0f} h the convex sample lost {c * 1e9:.0f} mm^3 and the plain one "
                 f"{p * 1e9:.0f} mm^3: **convex / plain {r:.3f}** of the wear applied to the geometry "
                 f"(the wear of a revolution: {ratios[0][4]:.3f} on the unworn samples, {ratios[-1][4]:.3f} "
                 f"at {ratios[-1][1]:.0f} h).\n")
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


def engines_line(runs):
    """Which engine made which runs: the stress pair the reference study's, the wear-out pair its own."""
    by = {}
    for n, r in runs.items():
        by.setdefault(r.engine, []).append(n)
    return ("**Engine versions** " + "; ".join(f"{e}: {', '.join(ns)}" for e, ns in by.items())
            + " (each run its study's, the ENGINE file beside its case: the stress pair the reference "
            "study's, `cases/reference-study/ENGINE`, so that it sits beside the study's results; the "
            "wear-out study its own, `cases/wear-out/ENGINE`, which has the implicit recession and the "
            "part's life; the curvature-refined convergence pair `cases/wear-out/curved/ENGINE`, whose "
            "flat-region flips never make an edge that exists already).")


def report(runs, missing):
    w = ["# The wear-out and stress cases in the holder\n",
         "Generated by `/usr/bin/python3 docs/results/holder_cases_report.py` from the run summaries; "
         "do not edit by hand.\n",
         engines_line(runs) + " The cases: the study's samples in their holder in the "
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
    runs, missing = load(args["--root"], study_engines(args["--engine"]))
    engines = ", ".join(sorted({r.engine for r in runs.values()}))
    if check_only:
        print(f"{PROG}: {len(runs)} runs ({', '.join(f'{n}: {len(staged(r))} staged' for n, r in runs.items())}), "
              f"engine {engines}; not run: {', '.join(missing) or 'none'}")
        return
    out = args["--out"]
    os.makedirs(out, exist_ok=True)
    plot(runs, out)
    plot_wear_out(runs, out)
    write_atomic(os.path.join(out, "holder-cases.md"), report(runs, missing))
    print(f"{PROG}: {os.path.join(out, 'holder-cases.md')} from {len(runs)} runs, engine {engines}")


if __name__ == "__main__":
    main(sys.argv[1:])
