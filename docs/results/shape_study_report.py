#!/usr/bin/python3
"""The shape study's report: the convex pattern's advantage with clumps beside spheres,
generated from the runs' summaries.

Usage: /usr/bin/python3 docs/results/shape_study_report.py [--runs DIR] [--spheres DIR]
           [--out DIR] [--check]

--runs     the clumps' run summaries (default cases/shape-study/results): calibration-plain
           (`wearsim dem` and `wearsim calibrate`), plain and convex (the pair, 56 h and 184 h),
           plain-seed2/3 and convex-seed2/3 (seeds at 56 h), one folder each
--spheres  the spheres' run summaries (default cases/reference-study/results, checked as the
           reference study's report checks them): plain-s4 and convex-s4 (the same cases with
           spheres), plain and convex with their seeds (s = 3: 184 h and the seeds' interval)
--out      where shape-study.md and shape_study.png go (default docs/results)
--check    only read and check the summaries; print what would be reported, write nothing

The clumps' runs must name one engine version (cases/shape-study/ENGINE) and one Archard
coefficient, the one their calibration calibrated (its summary's calibration.prm, which
plain.prm and convex.prm include), and
must have run clumps; the spheres' runs are the reference study's, of its engine. The pair is
required; every other run missing is listed as not run. Wear is read from the first staged
revolution on (the schedule's 3 dem-only revolutions bring the bed to steady flow), 28 h a
revolution: 56 h are 2 revolutions, 184 h 6.57.
"""
import math
import os
import sys

import matplotlib
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reference_study_report import (BOTTOM_LAYER, T56, T184, T_95, at, calibrated_alpha, fail, fmt,  # noqa: E402
                                    interval, load_runs, mark_hours, parse_args, runs_table, seed_table,
                                    write_atomic)

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PROG = os.path.basename(sys.argv[0])
RUNS = "cases/shape-study/results"
SPHERES = "cases/reference-study/results"
CLUMP_RUNS = ["plain", "convex", "plain-seed2", "plain-seed3", "convex-seed2", "convex-seed3"]
CALIBRATED = "cases/shape-study/results/calibration-plain/calibration.prm"
PAIR_COMMAND = "cases/reference-study/run.sh cases/shape-study/plain.prm cases/shape-study/convex.prm"


def shape(run):
    return run.params.get("Particle shape", "sphere")


def load(root, spheres_root):
    """The clumps' runs ({name: Run}), those not run, their calibration (or None) and the spheres'
    runs; stops on what the report must not read (see the module's text)."""
    clumps, missing, cal = load_runs(root, os.path.join(root, "calibration-plain"), CLUMP_RUNS,
                                     f"include {CALIBRATED} in cases/shape-study/plain.prm and convex.prm",
                                     PAIR_COMMAND)
    for n, r in list(clumps.items()) + ([("calibration-plain", cal)] if cal else []):
        if shape(r) == "sphere":
            fail(f"'{r.path}' ran spheres (DEM/Particle shape), not the study's clumps")
    spheres, _, sphere_cal = load_runs(spheres_root, None)
    for n in ("plain-s4", "convex-s4"):
        if n not in spheres:
            fail(f"the spheres' run '{os.path.join(spheres_root, n)}' is missing (the reference study's s = 4 pair)")
    for r in spheres.values():
        if shape(r) != "sphere":
            fail(f"'{r.path}' ran '{shape(r)}', not spheres")
    return clumps, missing, cal, spheres, sphere_cal


def ratio_at(runs, plain, convex, t):
    """(plain, convex, convex / plain) wear at t revolutions after steady; None where not reached."""
    if plain not in runs or convex not in runs:
        return None, None, None
    p, c = at(*runs[plain].cumulative(), t), at(*runs[convex].cumulative(), t)
    return p, c, (c / p if p and c is not None else None)


def column_figures(run, upto):
    """Per column (1 meets the flow first) over the first `upto` revolutions after steady, per
    revolution: wear, of it the elements' and the base strip's [mm^3], and the mean normal
    force [N] (the mean of the revolutions' means)."""
    idx, _ = run.after_steady()
    idx = idx[:upto]
    wear = np.sum(run.column_wear[idx, :], axis=0) * 1e9 / len(idx)
    elements = np.zeros(5)
    if run.element_wear is not None:
        for j, lab in enumerate(run.element_labels):
            elements[int(str(lab)[0]) - 1] += np.sum(run.element_wear[idx, j]) * 1e9 / len(idx)
    force = np.array([np.mean([run.rows[i][f"column{k}_force_mean_N"] for i in idx]) for k in range(1, 6)])
    return {"wear [mm^3]": wear, "of it the elements [mm^3]": elements,
            "of it the base strip [mm^3]": wear - elements, "normal force [N]": force}


def flow_means(run):
    """The means over the revolutions from the first staged one of the revolutions' figures."""
    idx, _ = run.after_steady()
    keys = ("normal_force_mean_N", "bottom_speed_mean_m_s", "bottom_spin_mean_rad_s", "bottom_count",
            "speed_over_sample_mean_m_s", "bed_height_mean_m")
    out = {k: float(np.mean([run.rows[i][k] for i in idx])) for k in keys}
    out["window"] = f"{int(run.rows[idx[0]]['revolution'])}-{int(run.rows[idx[-1]]['revolution'])}"
    return out


def runs_section(clumps, missing, cal):
    w = runs_table(clumps, cal, "calibration-plain")
    if missing or not cal:
        w.append("**Not run** with this engine: " + ", ".join(missing + ([] if cal else ["calibration-plain"])) + ".\n")
    return w


def calibration_section(cal, spheres, sphere_cal):
    w = ["## Calibration with clumps\n"]
    if not cal:
        return w + ["Not run: the clumps' Archard coefficient is not calibrated yet.\n"]
    steady = cal.steady_judgement()
    vols = [r["wear_volume_m3"] * 1e9 for r in cal.rows if r["revolution"] > steady] if steady else []
    alpha = calibrated_alpha(cal.path)
    sphere_alpha = spheres["plain"].params.get("Archard coefficient", "nan")
    at_s = "s = " + cal.params.get("Scaling factor", "?")
    sphere_s = "s = " + sphere_cal.params.get("Scaling factor", "?") if sphere_cal else "another run"
    w.append(f"The plain sample in its holder at {at_s} with `{shape(cal)}` clumps (`{cal.case}`, "
             f"`wearsim dem`, starting alpha {cal.params.get('Archard coefficient', '?')} 1/Pa): steady from "
             f"revolution {steady or 'none'}; wear of the wear face in the revolutions after it "
             f"{', '.join(f'{v:.2f}' for v in vols) or 'none'} mm^3"
             + (f" (mean {np.mean(vols):.2f})" if vols else "") + ". The laboratory's 145.16 mm^3 over 2 "
             f"revolutions (56 h) calibrates alpha = **{alpha or 'n/a'} 1/Pa** for the clumps, used by every "
             f"clumps' run below; the spheres' runs use {sphere_alpha} 1/Pa (calibrated on the same plain "
             f"sample with spheres at {sphere_s})"
             + (f": clumps / spheres {float(alpha) / float(sphere_alpha):.3f}.\n" if alpha else ".\n"))
    return w


def advantage_section(clumps, spheres):
    w = ["## Convex / plain: clumps beside spheres\n",
         "| | clumps: plain [mm^3] | clumps: convex [mm^3] | clumps: convex / plain "
         "| spheres s = 4: convex / plain | spheres s = 3: convex / plain |",
         "|---|---|---|---|---|---|"]
    for t, lab in ((T56, "56 h (2 revolutions)"), (T184, "184 h (6.57 revolutions)")):
        p, c, ratio = ratio_at(clumps, "plain", "convex", t)
        s4, s3 = ratio_at(spheres, "plain-s4", "convex-s4", t)[2], ratio_at(spheres, "plain", "convex", t)[2]
        cells = [fmt(p), fmt(c), fmt(ratio, 3) if ratio else "not reached",
                 fmt(s4, 3) if s4 else "not run", fmt(s3, 3) if s3 else "not run"]
        w.append(f"| {lab} | " + " | ".join(cells) + " |")
    w.append("\nClumps, cumulative wear of the wear face from the first staged revolution:\n")
    w.append("| revolutions | hours | plain [mm^3] | convex [mm^3] | convex / plain |")
    w.append("|---|---|---|---|---|")
    (n_p, cum_p), (n_c, cum_c) = clumps["plain"].cumulative(), clumps["convex"].cumulative()
    for k in range(max(len(n_p), len(n_c))):
        p = cum_p[k] if k < len(cum_p) else None
        c = cum_c[k] if k < len(cum_c) else None
        w.append(f"| {k + 1} | {28 * (k + 1)} | {fmt(p)} | {fmt(c)} | {fmt(c / p, 3) if p and c is not None else ''} |")
    w.append("\n![cumulative wear and columns](shape_study.png)\n")
    return w


def seeds_section(clumps, spheres):
    w = ["## Spread over insertion seeds (56 h)\n",
         "| grains | sample | seed 1 | seed 2 | seed 3 | mean +- 95 % |", "|---|---|---|---|---|---|"]
    lines, per_grains = [], []
    for grains, runs in (("clumps, s = 4", clumps), ("spheres, s = 3", spheres)):
        rows, ratios = seed_table(runs)
        w += [f"| {grains} | {k} | " + " | ".join(cells) + " |" for k, cells in rows]
        per_grains.append(ratios)
        if ratios:
            m, h = interval(ratios)
            lines.append(f"- {grains}: convex / plain per seed {', '.join(f'{x:.3f}' for x in ratios)}; "
                         f"mean **{m:.3f} +- {fmt(h, 3)}** (95 %, Student t, {len(ratios)} seed"
                         f"{'s' if len(ratios) > 1 else ''}).")
    lines += difference_lines(*per_grains, ratio_at(spheres, "plain-s4", "convex-s4", T56)[2])
    return w + [""] + lines + [""]


def difference_lines(clumps, spheres, spheres_s4):
    """What the seeds tell of shape: the clumps' mean ratio minus the spheres' at s = 3, with a 95 %
    interval from Welch's standard error and the conservative min(n) - 1 degrees of freedom (no
    equal variances assumed), and where the spheres' one run at s = 4 lies against the clumps'
    interval."""
    if len(clumps) < 2:
        return []
    mc, hc = interval(clumps)
    out = []
    if len(spheres) >= 2:
        ms = float(np.mean(spheres))
        se = math.sqrt(np.var(clumps, ddof=1) / len(clumps) + np.var(spheres, ddof=1) / len(spheres))
        dof = min(len(clumps), len(spheres)) - 1
        d, h = mc - ms, T_95[dof] * se
        verdict = "differ" if abs(d) > h else "cannot be told apart"
        out.append(f"- clumps (s = 4) minus spheres (s = 3): **{d:+.3f} +- {h:.3f}** (95 %, Welch's standard "
                   f"error, {dof} degree{'s' if dof > 1 else ''} of freedom, the smaller seed count less one): "
                   f"at 95 % the two {verdict}.")
    if spheres_s4:
        where = "outside" if abs(spheres_s4 - mc) > hc else "inside"
        out.append(f"- spheres at s = 4 (one seed): {spheres_s4:.3f}, {where} the clumps' interval "
                   f"{mc - hc:.3f} to {mc + hc:.3f} at the same scale.")
    return out


def columns_section(clumps, spheres):
    pairs = (("clumps", clumps["plain"], clumps["convex"]), ("spheres", spheres["plain-s4"], spheres["convex-s4"]))
    w = ["## Where the wear goes, per column\n"]
    w.append("Per revolution, over the revolutions from the first staged one both runs of a pair have ("
             + "; ".join(f"{g}: {min(len(P.after_steady()[1]), len(C.after_steady()[1]))}" for g, P, C in pairs)
             + "), at s = 4. A column is its elements and the strip of base top between the midlines to its "
             "neighbours (the first and last strips reaching the sample's edges); the plain sample reports the "
             "same strips. Column 1 meets the flow first.\n")
    w.append("| sample | grains | per revolution | 1 | 2 | 3 | 4 | 5 | 5 / 1 |")
    w.append("|---|---|---|---|---|---|---|---|---|")
    shares = {}
    for sample in ("plain", "convex"):
        for g, P, C in pairs:
            r = P if sample == "plain" else C
            upto = int(min(len(P.after_steady()[1]), len(C.after_steady()[1])))
            figs = column_figures(r, upto)
            shares[(sample, g)] = figs["wear [mm^3]"] / np.sum(figs["wear [mm^3]"])
            for q, v in figs.items():
                if sample == "plain" and q.startswith("of it"):
                    continue
                w.append(f"| {sample} | {g} | {q} | " + " | ".join(f"{x:.2f}" for x in v)
                         + f" | {v[4] / v[0] if v[0] else float('nan'):.2f} |")
    w.append("\nShare of the sample's wear per column:\n")
    w.append("| sample | grains | 1 | 2 | 3 | 4 | 5 |")
    w.append("|---|---|---|---|---|---|---|")
    for (sample, g), v in shares.items():
        w.append(f"| {sample} | {g} | " + " | ".join(f"{100 * x:.1f} %" for x in v) + " |")
    w.append("")
    return w


def flow_section(clumps, spheres):
    w = ["## The bed's flow over the sample\n",
         "| sample | grains | revolutions | mean normal force [N] | bottom-layer speed [m/s] "
         "| bottom-layer spin [rad/s] | bottom-layer grains | speed over the sample [m/s] | bed height [mm] |",
         "|---|---|---|---|---|---|---|---|---|"]
    for sample in ("plain", "convex"):
        for g, r in (("clumps", clumps[sample]), ("spheres", spheres[f"{sample}-s4"])):
            f = flow_means(r)
            w.append(f"| {sample} | {g} | {f['window']} | {f['normal_force_mean_N']:.2f} | "
                     f"{f['bottom_speed_mean_m_s']:.3f} | {f['bottom_spin_mean_rad_s']:.2f} | {f['bottom_count']:.1f} | "
                     f"{f['speed_over_sample_mean_m_s']:.3f} | {1e3 * f['bed_height_mean_m']:.1f} |")
    return w + ["", BOTTOM_LAYER, ""]


def plot(clumps, spheres, out):
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11.5, 4.2))
    for g, ls, P, C in (("clumps", "-", clumps["plain"], clumps["convex"]),
                        ("spheres s = 4", "--", spheres["plain-s4"], spheres["convex-s4"])):
        for name, r, colour in (("plain", P, "tab:blue"), ("convex", C, "tab:orange")):
            n, cum = r.cumulative()
            a1.plot(np.concatenate([[0], n]), np.concatenate([[0], cum]), ls, marker="o", ms=3, color=colour,
                    label=f"{name}, {g}")
    mark_hours(a1)
    a1.set_xlabel("revolutions from the first staged one (28 h each)")
    a1.legend(fontsize=8)
    bars = [("plain", "clumps", clumps["plain"], clumps["convex"], "tab:blue", None),
            ("plain", "spheres", spheres["plain-s4"], spheres["convex-s4"], "tab:blue", "//"),
            ("convex", "clumps", clumps["plain"], clumps["convex"], "tab:orange", None),
            ("convex", "spheres", spheres["plain-s4"], spheres["convex-s4"], "tab:orange", "//")]
    for k, (sample, g, P, C, colour, hatch) in enumerate(bars):
        upto = int(min(len(P.after_steady()[1]), len(C.after_steady()[1])))
        wear = column_figures(P if sample == "plain" else C, upto)["wear [mm^3]"]
        a2.bar(np.arange(1, 6) + (k - 1.5) * 0.2, 100 * wear / np.sum(wear), width=0.2, color=colour,
               hatch=hatch, edgecolor="k", lw=0.3, label=f"{sample}, {g}")
    a2.set_xlabel("column (1 meets the flow first)")
    a2.set_ylabel("share of the sample's wear [%]")
    a2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "shape_study.png"), dpi=120)
    plt.close(fig)


def report(clumps, missing, cal, spheres, sphere_cal):
    P = clumps["plain"]
    w = ["# The shape study: clumps against spheres in the holder at s = 4\n",
         "Generated by `/usr/bin/python3 docs/results/shape_study_report.py` from the runs' summaries; "
         "do not edit by hand.\n",
         f"**Grains** `{shape(P)}` (`docs/dem.md`, the shape library). **Engines** {P.engine} for the clumps "
         f"(`cases/shape-study/ENGINE`, every clumps' run below), {spheres['plain'].engine} for the spheres (the "
         "reference study's, `docs/results/reference-study.md`). **Case files** `cases/shape-study/*.prm`, the "
         f"clumps' coefficient from `{CALIBRATED}`.\n"]
    w += runs_section(clumps, missing, cal)
    w += calibration_section(cal, spheres, sphere_cal)
    w += advantage_section(clumps, spheres)
    w += seeds_section(clumps, spheres)
    w += columns_section(clumps, spheres)
    w += flow_section(clumps, spheres)
    return "\n".join(w)


def main(argv):
    args, check_only = parse_args(argv, {"--runs": RUNS, "--spheres": SPHERES, "--out": "docs/results"},
                                  __doc__.splitlines()[3].strip())
    clumps, missing, cal, spheres, sphere_cal = load(args["--runs"], args["--spheres"])
    if check_only:
        print(f"{PROG}: {len(clumps)} clumps' runs ({', '.join(clumps)}), engine {clumps['plain'].engine}, "
              f"calibration {'present' if cal else 'not run'}; not run: {', '.join(missing) or 'none'}; "
              f"spheres' engine {spheres['plain'].engine}")
        return
    for n in ("plain", "convex"):
        if clumps[n].first_staged_rev is None:
            fail(f"'{clumps[n].path}' has no staged revolution yet")
    out = args["--out"]
    os.makedirs(out, exist_ok=True)
    plot(clumps, spheres, out)
    write_atomic(os.path.join(out, "shape-study.md"), report(clumps, missing, cal, spheres, sphere_cal))
    print(f"{PROG}: {os.path.join(out, 'shape-study.md')} from {len(clumps)} clumps' runs, engine {clumps['plain'].engine}")


if __name__ == "__main__":
    main(sys.argv[1:])
