#!/usr/bin/python3
"""The reference study's report (issue 32), generated from its runs' summaries.

Usage: /usr/bin/python3 docs/results/reference_study_report.py [--runs DIR] [--out DIR]
           [--calibration DIR] [--check]

--runs         the study's run summaries (default cases/reference-study/results): plain,
               convex (the study), plain-seed2/3 and convex-seed2/3 (seeds), plain-s7/s4/s2
               and convex-s7/s4/s2 (particle size), plain-reference and convex-reference (the
               node-moving method), one folder each
--out          where reference-study.md and its plots go (default docs/results)
--calibration  the calibration's summary (default cases/calibration/results/calibration-plain);
               the coefficient its calibration.prm holds must be the one every run used
--check        only read the summaries and check them (the study pair present, one engine
               version); print what would be reported from, write nothing

A summary folder is what docs/results/run_summary.py writes from a run folder (run.sh does
after every call, into cases/reference-study/results/<case>; the calibration's is written by
hand, cases/calibration/README.md); the report reads nothing else, so that it regenerates
from the repository alone. The study pair is required; every other run missing is listed as
not run, and a run short of 56 h after steady state says in the size trend how far it got.
All runs present must name the same engine version (the second line of their parameters.prm),
or the report is refused.

"After steady state" counts from the first staged revolution (the schedule's dem-only
revolutions bring the bed to steady flow on the unworn sample; the run's own steady judgement
is printed beside). 56 h of the laboratory test are 2 revolutions, 184 h 6.57 (28 h per
revolution, docs/wear-tester.md).
"""
import math
import os
import sys

import matplotlib
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_summary  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PROG = os.path.basename(sys.argv[0])
HOURS_PER_REV = 28.0
T56, T184 = 56.0 / HOURS_PER_REV, 184.0 / HOURS_PER_REV
RUNS = "cases/reference-study/results"
CALIBRATION = "cases/calibration/results/calibration-plain"
T_95 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571}  # Student t, two-sided 95 %
# What the bottom layer's figures are (docs/theory.md section 7, coupling's tester evaluation).
BOTTOM_LAYER = (
    "**The bottom layer**, at each of the revolution's evaluation samples (`Samples per revolution`): "
    "the grains whose centre lies over the sample's footprint and whose lowest point lies less than "
    "one mean diameter (the PSD's, at the run's scaling factor) above the wear surface under it; a "
    "clump counts as one grain (its centre of mass over the footprint, its gap the least over its "
    "members). Its **speed** is |v| of the grain's centre of mass (not of its members' points, which "
    "carry omega x arm); its **spin** is |omega| of the grain, in the space frame, which is the "
    "tester's and the sample's (the sample stands still, the floor turns under the bed). A "
    "revolution's mean pools every bottom grain of every sample (a grain in n samples counts n "
    "times); the table's figure is the mean of the revolutions' means from the first staged one.")


def fail(message):
    sys.exit(f"{PROG}: {message}")


def prm_settings(path):
    """The `set name = value` lines of a parameter file, the first of each name (subsections
    are not told apart: the names the report reads are unique in the resolved parameters)."""
    out = {}
    with open(path) as f:
        for line in f:
            s = line.split("#", 1)[0].strip()
            if s.startswith("set ") and "=" in s:
                k, v = s[4:].split("=", 1)
                out.setdefault(k.strip(), v.strip())
    return out


class Run:
    """One run's summary folder (docs/results/run_summary.py): its revolutions, stages, engine
    version and what the plots need of its surfaces."""

    def __init__(self, path):
        """Reads the summary folder `path`; stops when it names no engine version or has no
        revolution."""
        self.path = path
        self.name = os.path.basename(os.path.normpath(path))
        with open(os.path.join(path, "parameters.prm")) as f:
            lines = [f.readline() for _ in range(2)]
        if not lines[1].startswith("# Engine version:"):
            fail(f"'{path}/parameters.prm' names no engine version (a run older than the study)")
        self.engine = lines[1].split(":", 1)[1].strip()
        self.case = lines[0].split(" of ", 1)[-1].strip()
        self.rows = self._csv("summary.csv")
        # a `wearsim dem` run (the calibration) has revolutions and no stages
        has_stages = os.path.isfile(os.path.join(path, "stages.csv"))
        self.stages = self._csv("stages.csv") if has_stages else []
        if not self.rows:
            fail(f"'{path}/summary.csv' has no revolution yet")
        self.params = prm_settings(os.path.join(path, "parameters.prm"))
        self.element_labels, self.element_wear, self.column_wear = run_summary.read_revolutions(path)
        schemes = [r["scheme_name"] for r in self.stages]
        self.first_staged_rev = next(
            (int(r["first_revolution"]) for r in self.stages if r["scheme_name"] == "staged"), None)
        self.n_staged = schemes.count("staged")
        self.planned = self.params.get("Schedule", "?")

    def _csv(self, name):
        """The rows of one of the summary's CSV files (numbers as floats); stops when it is missing."""
        path = os.path.join(self.path, name)
        if not os.path.isfile(path):
            fail(f"'{path}' does not exist (is '{self.path}' a run summary, docs/results/run_summary.py?)")
        return run_summary.read_csv(path)

    def column(self, name):
        return np.array([r[name] for r in self.rows], dtype=float)

    def after_steady(self):
        """Revolutions from the first staged one: (index array into rows, revolutions 1..n)."""
        if self.first_staged_rev is None:
            return np.array([], dtype=int), np.array([])
        idx = np.array([i for i, r in enumerate(self.rows) if r["revolution"] >= self.first_staged_rev])
        return idx, np.arange(1, len(idx) + 1, dtype=float)

    def cumulative(self):
        """Cumulative wear-face volume [mm^3] after steady state, revolutions 1..n."""
        idx, n = self.after_steady()
        return n, np.cumsum(self.column("wear_volume_m3")[idx]) * 1e9

    def steady_judgement(self):
        s = int(self.rows[-1].get("steady_revolution", 0) or 0)
        return s

    def face_map(self):
        """(centroids [face, (x, y)] [m], labels) of the stage-0 wear face, or None."""
        return run_summary.read_map(self.path)

    def profiles(self):
        """[(line name, x [m], {stage: (y, z, wear depth)})]: the wear face cut along the flow
        on the stage-0 and the last surface."""
        return run_summary.read_profiles(self.path)

    def element_extents(self):
        """{stage: {label: (highest z, lowest z) [m]}} on the stage-0 and the last surface."""
        return run_summary.read_elements(self.path)

    def wall_hours(self):
        """Wall-clock time the run took so far [h]: its revolutions (summary.csv) and the FEM side
        of its stages (stages.csv), on whatever else shared the machine then."""
        fem = ("wear_s", "fem_solve_s", "mesh_motion_s", "remesh_s", "output_s")
        seconds = sum(r.get("wall_seconds", 0.0) for r in self.rows)
        seconds += sum(r.get(k, 0.0) for r in self.stages for k in fem)
        return seconds / 3600.0

    def planned_stages(self, scheme):
        """The number of stages of one scheme the schedule asks for (`3 dem-only, 20 staged`:
        20 staged), or None when it names none."""
        for part in str(self.planned).split(","):
            words = part.split()
            if len(words) == 2 and words[1] == scheme and words[0].isdigit():
                return int(words[0])
        return None

    def has_log(self):
        """Whether the run had the log run.sh writes beside its folder (ending.txt, from it)."""
        return os.path.isfile(os.path.join(self.path, "ending.txt"))

    def last_call_ending(self):
        """How the last call of run.sh on this run ended (ending.txt: "stopped by SIGTERM in stage
        k of n" or "stopped by an error in stage k: <what>"), or None when the log was missing or
        told neither (finished, still running, or killed without a word)."""
        if not self.has_log():
            return None
        with open(os.path.join(self.path, "ending.txt")) as f:
            return f.read().strip() or None

    def last_surface(self):
        """The stage of the run's last surface, or None when it had none past stage 0."""
        stage = run_summary.read_run_txt(self.path).get("last surface", "none")
        return int(stage) if stage.isdigit() else None


def fits(x, y):
    """Least squares through the origin: y = a x and y = b x^2 + c x, with R^2."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    out = {"a": float("nan"), "r2_lin": float("nan"), "b": float("nan"), "c": float("nan"), "r2_quad": float("nan")}
    if len(x) < 1:
        return out
    ss = float(np.sum((y - y.mean()) ** 2)) if len(y) > 1 else 0.0
    a = float(np.dot(x, y) / np.dot(x, x))
    out["a"] = a
    out["r2_lin"] = 1 - float(np.sum((y - a * x) ** 2)) / ss if ss > 0 else float("nan")
    if len(x) >= 2:
        A = np.column_stack([x * x, x])
        (b, c), *_ = np.linalg.lstsq(A, y, rcond=None)
        out["b"], out["c"] = float(b), float(c)
        out["r2_quad"] = 1 - float(np.sum((y - b * x * x - c * x) ** 2)) / ss if ss > 0 else float("nan")
    return out


def at(n, cum, t):
    """Cumulative wear at t revolutions after steady (linear between whole revolutions), or None
    when the run has not got that far."""
    if len(n) == 0 or t > n[-1] + 1e-9:
        return None
    return float(np.interp(t, np.concatenate([[0.0], n]), np.concatenate([[0.0], cum])))


def amplifications(run, n):
    """The amplifications of the first n staged stages, as text."""
    a = [r["amplification"] for r in run.stages if r["scheme_name"] == "staged"][:n]
    return ", ".join(f"{x:g}" if x == 1 else f"{x:.3f}" for x in a) or "no staged stage"


def interval(values):
    """Mean and 95 % half-width (Student t) of a list."""
    v = np.asarray(values, float)
    if len(v) < 2:
        return float(v.mean()), float("nan")
    return float(v.mean()), T_95.get(len(v) - 1, 2.0) * float(v.std(ddof=1)) / math.sqrt(len(v))


def fmt(x, digits=2):
    return "n/a" if x is None or (isinstance(x, float) and math.isnan(x)) else f"{x:.{digits}f}"


def has_revolution(path):
    """Whether the summary folder's summary.csv holds a revolution (a header and a row)."""
    return run_summary.count_revolutions(path) > 0


STUDY_RUNS = ["plain", "convex", "plain-seed2", "plain-seed3", "convex-seed2", "convex-seed3", "plain-s7",
              "convex-s7", "plain-s4", "convex-s4", "plain-s2", "convex-s2", "plain-reference", "convex-reference"]


def load_runs(root, calibration, names=STUDY_RUNS,
              remedy="copy it to cases/reference-study/calibration.prm", run_script="cases/reference-study/run.sh"):
    """The study's runs found in root ({name: Run}, `names` in that order), those not found
    (with "started, no revolution done yet" when the folder is there) and the calibration
    (None when absent); stops on a missing plain or convex run, mixed engines or mixed Archard
    coefficients, or a calibration whose coefficient the runs do not use (`remedy` says how the
    case files take it)."""
    runs, missing = {}, []
    for n in names:
        p = os.path.join(root, n)
        if has_revolution(p):
            runs[n] = Run(p)
        else:  # not started, or started and no revolution done yet
            missing.append(n + (" (started, no revolution done yet)" if os.path.isdir(p) else ""))
    for n in ("plain", "convex"):
        if n not in runs:
            fail(f"the study run '{os.path.join(root, n)}' is missing ({run_script})")
    calibration = calibration or CALIBRATION
    cal = Run(calibration) if os.path.isfile(os.path.join(calibration, "summary.csv")) else None
    engines = {r.engine for r in runs.values()} | ({cal.engine} if cal else set())
    if len(engines) != 1:
        listing = ", ".join(f"{n}: {r.engine}" for n, r in runs.items())
        fail(f"the runs come from different engine versions ({listing}"
             f"{', calibration: ' + cal.engine if cal else ''}); re-run them with one")
    alphas = {n: r.params.get("Archard coefficient") for n, r in runs.items()}
    if len(set(alphas.values())) != 1:
        fail("the runs use different Archard coefficients ("
             + ", ".join(f"{n}: {a}" for n, a in alphas.items()) + "); every case includes one calibration.prm")
    written = calibrated_alpha(cal.path) if cal else None
    if written is not None and float(written) != float(alphas["plain"] or "nan"):
        fail(f"the calibration '{cal.path}' calibrated alpha = {written} 1/Pa (its calibration.prm), but the "
             f"study's runs use {alphas['plain']}; {remedy} and re-run")
    return runs, missing, cal


def seed_values(runs, t=T56):
    """The seeds' runs of each sample ({"plain": [seed 1, 2, 3: Run or None], "convex": ...}), their
    wear at t revolutions after steady state (None where not run or not reached) and the
    convex / plain ratio of each seed both samples reached."""
    seed_runs = {k: [runs.get(k + s) for s in ("", "-seed2", "-seed3")] for k in ("plain", "convex")}
    vals = {k: [at(*r.cumulative(), t) if r else None for r in rs] for k, rs in seed_runs.items()}
    ratios = [c / p for p, c in zip(vals["plain"], vals["convex"]) if p and c]
    return seed_runs, vals, ratios


def seed_table(runs, t=T56):
    """The seeds' table at t revolutions after steady state: per sample (name, [seed 1, 2, 3 as
    text, "mean +- 95 % (n = k)"]), and the convex / plain ratio of each seed both reached."""
    seed_runs, vals, ratios = seed_values(runs, t)
    rows = []
    for k in ("plain", "convex"):
        got = [v for v in vals[k] if v is not None]
        m, h = interval(got) if got else (float("nan"), float("nan"))
        cells = ["not run" if r is None else ("not reached" if v is None else fmt(v))
                 for r, v in zip(seed_runs[k], vals[k])]
        rows.append((k, cells + [f"{fmt(m)} +- {fmt(h)} (n = {len(got)})"]))
    return rows, ratios


def calibrated_alpha(path):
    """The Archard coefficient `wearsim calibrate` wrote into <path>/calibration.prm, or None."""
    f = os.path.join(path, "calibration.prm")
    if not os.path.isfile(f):
        return None
    alpha = prm_settings(f).get("Archard coefficient")
    if alpha is None:
        fail(f"'{f}' sets no Archard coefficient")
    return alpha


def element_rows(run, upto):
    """Per element cumulative wear [mm^3] over the first `upto` revolutions after steady, and the
    base (wear face minus elements)."""
    idx, _ = run.after_steady()
    idx = idx[:upto]
    total = float(np.sum(run.column("wear_volume_m3")[idx])) * 1e9
    if run.element_wear is None or not run.element_labels:
        return {}, total, total
    per = np.sum(run.element_wear[idx, :], axis=0) * 1e9
    elements = {f"C{lab}": float(v) for lab, v in zip(run.element_labels, per)}
    return elements, total - float(per.sum()), total


def mark_hours(ax):
    """The laboratory's 56 h and 184 h marked on an axis of revolutions after steady state, whose
    ordinate is the cumulative wear."""
    for t, lab in ((T56, "56 h"), (T184, "184 h")):
        ax.axvline(t, color="grey", lw=0.6, ls=":")
        ax.text(t, ax.get_ylim()[1] * 0.97, lab, ha="right", va="top", fontsize=8, rotation=90)
    ax.set_ylabel("cumulative wear of the wear face [mm$^3$]")


def plot_wear(runs, out):
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for name, colour in (("plain", "tab:blue"), ("convex", "tab:orange")):
        n, cum = runs[name].cumulative()
        if len(n) == 0:
            continue
        f = fits(n, cum)
        ax.plot(n, cum, "o", color=colour, label=f"{name}")
        xx = np.linspace(0, n[-1], 50)
        ax.plot(xx, f["a"] * xx, "-", color=colour, lw=0.8, label=f"{name}: linear fit")
        if not math.isnan(f["b"]):
            ax.plot(xx, f["b"] * xx * xx + f["c"] * xx, "--", color=colour, lw=0.8, label=f"{name}: quadratic fit")
    mark_hours(ax)
    ax.set_xlabel("revolutions after steady state (28 h each)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "reference_study_wear.png"), dpi=120)
    plt.close(fig)


def plot_columns_elements(runs, upto, out):
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.0), gridspec_kw={"width_ratios": [1, 2.4]})
    for k, (name, colour) in enumerate((("plain", "tab:blue"), ("convex", "tab:orange"))):
        r = runs[name]
        idx, _ = r.after_steady()
        cols = np.sum(r.column_wear[idx[:upto], :], axis=0) * 1e9
        a1.bar(np.arange(1, 6) + (k - 0.5) * 0.38, cols, width=0.38, color=colour, label=name)
    a1.set_xlabel("column (1 meets the flow first)")
    a1.set_ylabel(f"wear over {upto} revolutions [mm$^3$]")
    a1.legend(fontsize=8)
    elements, base, _ = element_rows(runs["convex"], upto)
    names = list(elements)
    a2.bar(range(len(names)), [elements[n] for n in names], color="tab:orange")
    a2.set_xticks(range(len(names)))
    a2.set_xticklabels(names, rotation=90, fontsize=8)
    a2.set_ylabel(f"convex: wear over {upto} revolutions [mm$^3$]")
    a2.set_title(f"elements (base: {base:.1f} mm$^3$)", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "reference_study_elements.png"), dpi=120)
    plt.close(fig)


def plot_map(run, upto, out):
    """Per-element wear on the footprint: each element's faces coloured by its wear."""
    c, lab = run.face_map()
    elements, _, _ = element_rows(run, upto)
    fig, ax = plt.subplots(figsize=(5.2, 5.6))
    vmax = max(elements.values()) if elements else 1
    cmap = plt.get_cmap("viridis")
    base = lab == 3
    ax.scatter(c[base, 0] * 1e3, c[base, 1] * 1e3, s=0.3, color="0.85")
    for name, v in elements.items():
        m = lab == int(name[1:])
        if not np.any(m):
            continue
        ax.scatter(c[m, 0] * 1e3, c[m, 1] * 1e3, s=1.5, color=cmap(v / vmax))
        ax.text(c[m, 0].mean() * 1e3 + 4, c[m, 1].mean() * 1e3, f"{name}\n{v:.1f}", fontsize=6, va="center")
    sm = plt.cm.ScalarMappable(cmap=cmap, norm=plt.Normalize(0, vmax))
    fig.colorbar(sm, ax=ax, label=f"element wear over {upto} revolutions [mm$^3$]")
    ax.set_xlabel("radial position [mm] (inner radius left)")
    ax.set_ylabel("along the flow [mm] (the flow comes from below)")
    ax.set_aspect("equal")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "reference_study_map.png"), dpi=130)
    plt.close(fig)


def plot_profiles(run, out):
    """Worn profiles along the flow through the middle elements (C13, C33, C53) and the
    inner ones (C11, ...): first and last surface, and the depth between them (the cuts are
    the run summary's, run_summary.section)."""
    n, lines = run.last_surface(), run.profiles()
    if n is None or not lines:
        return False
    fig, axes = plt.subplots(len(lines), 1, figsize=(8, 2.6 * len(lines)), squeeze=False)
    for ax, (name, x0, cuts) in zip(axes[:, 0], lines):
        y0, z0, _ = cuts[0]
        y1, z1, d1 = cuts[n]
        ax.plot(y0 * 1e3, z0 * 1e3, color="0.5", lw=0.8, label="unworn")
        ax.plot(y1 * 1e3, z1 * 1e3, color="tab:red", lw=0.8, label=f"after stage {n}")
        ax.set_ylabel("z [mm]")
        ax.set_title(f"through {name} (x = {x0 * 1e3:.1f} mm)", fontsize=9)
        ax2 = ax.twinx()
        ax2.plot(y1 * 1e3, d1 * 1e6, color="tab:blue", lw=0.6)
        ax2.set_ylabel("worn depth (normal) [um]", color="tab:blue")
        ax.legend(fontsize=7, loc="upper left")
    axes[-1, 0].set_xlabel("along the flow [mm]")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "reference_study_profiles.png"), dpi=120)
    plt.close(fig)
    return True


def plot_flow(runs, out):
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.6))
    for name, colour in (("plain", "tab:blue"), ("convex", "tab:orange")):
        r = runs[name]
        rev = r.column("revolution")
        for ax, col, lab in zip(axes, ("normal_force_mean_N", "bottom_speed_mean_m_s", "bottom_spin_mean_rad_s"),
                                ("mean normal force on the wear face [N]", "bottom-layer speed [m/s]",
                                 "bottom-layer spin [rad/s]")):
            ax.plot(rev, r.column(col), "o-", color=colour, ms=3, label=name)
            ax.set_ylabel(lab)
            ax.set_xlabel("revolution")
            if r.first_staged_rev:
                ax.axvline(r.first_staged_rev - 0.5, color=colour, lw=0.5, ls=":")
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "reference_study_flow.png"), dpi=120)
    plt.close(fig)


def node_moving_section(runs):
    """The `reference` scheme's runs against the staged ones of the same sample: how far each
    went, how it ended (distorted, all 20 revolutions, or how run.sh's last call stopped it:
    the scheme keeps no checkpoint, so a stopped run is reported as far as it went) and the
    wear from the staged runs' first staged revolution, against the staged wear over as many."""
    w = ["## The node-moving method on the same cases\n"]
    P, C = runs["plain"], runs["convex"]
    w.append("The `reference` scheme moves the sample's surface nodes inside the DEM from the first "
             "revolution and stops at the first distorted face; its wear is counted from revolution "
             f"{P.first_staged_rev or 4}, as the staged run's. It keeps no checkpoint: a run stopped "
             "before it distorted or finished is reported as far as it went.\n")
    w.append("| sample | revolutions run | how it ended | mean wear a revolution, revolutions run [mm^3] "
             "| staged run, same revolutions [mm^3] | cumulative wear from that revolution [mm^3] "
             "| staged, same revolutions [mm^3] |")
    w.append("|---|---|---|---|---|---|---|")
    for name, staged in (("plain", P), ("convex", C)):
        key = f"{name}-reference"
        if key not in runs:
            w.append(f"| {name} | not run | | | | | |")
            continue
        r = runs[key]
        start = staged.first_staged_rev or 4
        done = int(r.rows[-1]["revolution"])
        planned = r.planned_stages("reference")
        distorted = next((d for d in (str(x.get("distortion", "")).strip() for x in r.stages) if d), "")
        if distorted:
            ended = f"distorted in revolution {done}: {distorted}"
        elif planned and len(r.stages) >= planned:
            ended = f"all {planned} revolutions, undistorted"
        else:
            ended = r.last_call_ending() or "in progress, or killed without a message"
        mean = np.mean([x["wear_volume_m3"] for x in r.rows]) * 1e9
        same_revs = [x["wear_volume_m3"] for x in staged.rows if x["revolution"] <= done]
        mean_staged = fmt(np.mean(same_revs) * 1e9) if len(same_revs) == len(r.rows) else "n/a"
        compared = [x["wear_volume_m3"] for x in r.rows if x["revolution"] >= start]
        n_ref = len(compared)
        if n_ref:
            ref = sum(compared) * 1e9
            _, cum = staged.cumulative()
            cum_cells = (f"{ref:.2f} ({n_ref} revolution{'s' if n_ref > 1 else ''}) | "
                         + (fmt(cum[n_ref - 1]) if n_ref <= len(cum) else "n/a"))
        else:
            cum_cells = f"none: it ended before revolution {start} |"
        w.append(f"| {name} | {done} | {ended} | {mean:.2f} | {mean_staged} | {cum_cells} |")
    w.append("")
    return w


def size_trend_section(runs, missing):
    """The 56 h convex/plain ratio at s = 4, 3 and 2. A run that has not reached 56 h after
    steady state (s = 2 is a long case, run over several sessions) says how far it got:
    revolutions done of its schedule's, or started with none done, or not run."""
    w = ["## Trend with particle size: convex / plain at 56 h\n"]
    w.append("| s | plain [mm^3] | convex [mm^3] | convex / plain | geometry moved at |")
    w.append("|---|---|---|---|---|")
    started = {m.split(" (")[0] for m in missing if m.endswith("(started, no revolution done yet)")}

    def how_far(name):
        if name not in runs:
            return "not reached: started, no revolution done" if name in started else "not run"
        r = runs[name]
        done = int(r.rows[-1]["revolution"])
        planned = sum(r.planned_stages(k) or 0 for k in ("dem-only", "staged"))
        return f"not reached: {done} of {planned} revolutions done" if planned else f"not reached: {done} revolutions done"

    sizes = (("7", ("plain-s7", "convex-s7")), ("4", ("plain-s4", "convex-s4")), ("3", ("plain", "convex")),
             ("2", ("plain-s2", "convex-s2")))
    at56 = {n: at(*runs[n].cumulative(), T56) for _, pair in sizes for n in pair if n in runs}
    for s, (pn, cn) in sizes:
        p, c = at56.get(pn), at56.get(cn)
        cells = [fmt(v) if v is not None else how_far(n) for n, v in ((pn, p), (cn, c))]
        ratio = fmt(c / p, 3) if p and c else ""
        notes = "; ".join(f"{n}: {amplifications(runs[n], 2)}" for n in (pn, cn) if n in runs and runs[n].n_staged)
        w.append(f"| {s} | {cells[0]} | {cells[1]} | {ratio} | {notes} |")
    short = [(n, ref) for n, ref in (("plain-s2", "plain"), ("convex-s2", "convex"))
             if n in runs and at56[n] is None]
    if short:
        w.append("\nSo far, wear of the wear face a revolution at s = 2 against s = 3 (the same revolutions; "
                 "before steady state it includes the bed's settling):\n")
        def wear_by_revolution(r):
            return {int(x["revolution"]): x["wear_volume_m3"] * 1e9 for x in r.rows}

        for n, ref in short:
            at3 = wear_by_revolution(runs[ref])
            pairs = [f"revolution {k}: {fmt(v)} ({fmt(at3.get(k))})" for k, v in wear_by_revolution(runs[n]).items()]
            w.append(f"- {n} (s = 3 in brackets): " + "; ".join(pairs) + " mm^3.")
    w.append("\nThe wear compared is the DEM's own in each revolution. The geometry it moves is that "
             "wear times the stage's amplification: 1, unless a stage would recede a vertex by more than "
             "`Coupling/Maximum depth fraction` edge lengths and the case lets it run at less "
             "(`Coupling/Adaptive amplification`, `stages.csv`).\n")
    return w


def runs_table(runs, cal, cal_name):
    """The table of the runs and their calibration (named cal_name): case, schedule, how far."""
    w = ["| run | case | schedule | revolutions done | staged stages done | wall time [h] |", "|---|---|---|---|---|---|"]
    for n, r in runs.items():
        w.append(f"| {n} | `{r.case}` | {r.planned} | {int(r.rows[-1]['revolution'])} | {r.n_staged} | "
                 f"{r.wall_hours():.1f} |")
    if cal:
        w.append(f"| {cal_name} | `{cal.case}` | `wearsim dem` to steady + 2 | {int(cal.rows[-1]['revolution'])} | - | "
                 f"{cal.wall_hours():.1f} |")
    return w + [""]


def report(runs, missing, cal, out):
    P, C = runs["plain"], runs["convex"]
    w = []
    w.append("# The reference study: plain and convex samples in the holder at s = 3\n")
    w.append("Generated by `/usr/bin/python3 docs/results/reference_study_report.py` from the run "
             "folders; do not edit by hand.\n")
    w.append(f"**Engine version** {P.engine} (every run below). **Case files** "
             "`cases/reference-study/*.prm`, the calibrated coefficient from "
             "`cases/reference-study/calibration.prm`.\n")
    w += runs_table(runs, cal, "calibration")
    w.append("Wall time: the revolutions' and the stages' own clocks (`summary.csv`, `stages.csv`), "
             "with whatever else ran on the machine then (`cases/reference-study/README.md`, Status).\n")
    if missing or not cal:
        w.append("**Not run** with this engine: " + ", ".join(missing + ([] if cal else ["calibration"])) + ".\n")

    # Calibration
    if cal:
        alpha = P.params.get("Archard coefficient", "?")
        steady = cal.steady_judgement()
        vols = [r["wear_volume_m3"] * 1e9 for r in cal.rows if r["revolution"] > steady] if steady else []
        w.append("## Calibration\n")
        w.append(f"Plain sample in the holder, s = 3, `wearsim dem` (`{cal.case}`): steady from revolution "
                 f"{steady}; wear of the wear face in the revolutions after it "
                 f"{', '.join(f'{v:.2f}' for v in vols)} mm^3 (mean {np.mean(vols) if vols else float('nan'):.2f}"
                 f" at the starting alpha {cal.params.get('Archard coefficient', '?')} 1/Pa). The laboratory's "
                 f"145.16 mm^3 over 2 revolutions (56 h) calibrates alpha = **{alpha} 1/Pa**, used by every "
                 "run below.\n")

    # Cumulative wear and fits
    w.append("## Cumulative wear after steady state\n")
    w.append("![cumulative wear](reference_study_wear.png)\n")
    n_p, cum_p = P.cumulative()
    n_c, cum_c = C.cumulative()
    for name, r in (("plain", P), ("convex", C)):
        s = r.steady_judgement()
        w.append(f"- {name}: first staged revolution {r.first_staged_rev} "
                 f"(the run judged its flow steady {'from revolution ' + str(s) if s else 'at no revolution'}).")
    w.append("")
    w.append("| revolutions after steady | hours | plain [mm^3] | convex [mm^3] | convex / plain |")
    w.append("|---|---|---|---|---|")
    for k in range(max(len(n_p), len(n_c))):
        p = cum_p[k] if k < len(cum_p) else None
        c = cum_c[k] if k < len(cum_c) else None
        ratio = c / p if p and c is not None else None
        w.append(f"| {k + 1} | {28 * (k + 1)} | {fmt(p)} | {fmt(c)} | {fmt(ratio, 3)} |")
    w.append("")
    w.append("Fits through the origin, V in mm^3, n in revolutions after steady state:\n")
    w.append("| sample | linear V = a n: a | R^2 | quadratic V = b n^2 + c n: b | c | R^2 |")
    w.append("|---|---|---|---|---|---|")
    for name, (n, cum) in (("plain", (n_p, cum_p)), ("convex", (n_c, cum_c))):
        f = fits(n, cum)
        w.append(f"| {name} | {fmt(f['a'], 3)} | {fmt(f['r2_lin'], 5)} | {fmt(f['b'], 4)} | {fmt(f['c'], 3)} | {fmt(f['r2_quad'], 5)} |")
    w.append("")
    w.append("| | plain [mm^3] | convex [mm^3] | convex / plain | reduction |")
    w.append("|---|---|---|---|---|")
    for t, lab in ((T56, "56 h (2 revolutions)"), (T184, "184 h (6.57 revolutions)")):
        p, c = at(n_p, cum_p, t), at(n_c, cum_c, t)
        if p is None or c is None:
            w.append(f"| {lab} | {fmt(p)} | {fmt(c)} | not reached | |")
        else:
            w.append(f"| {lab} | {p:.2f} | {c:.2f} | {c / p:.3f} | {100 * (1 - c / p):.1f} % |")
    w.append("")

    # Columns and elements
    upto = int(min(len(n_p), len(n_c)))
    w.append(f"## Where the wear goes (over the {upto} revolutions after steady state both runs have)\n")
    w.append("![columns and elements](reference_study_elements.png)\n")
    w.append("| column | plain [mm^3] | convex [mm^3] |")
    w.append("|---|---|---|")
    idx_p, _ = P.after_steady()
    idx_c, _ = C.after_steady()
    cp = np.sum(P.column_wear[idx_p[:upto], :], axis=0) * 1e9
    cc = np.sum(C.column_wear[idx_c[:upto], :], axis=0) * 1e9
    for j in range(5):
        w.append(f"| {j + 1} | {cp[j]:.2f} | {cc[j]:.2f} |")
    w.append("")
    elements, base, total = element_rows(C, upto)
    if elements:
        share = sum(elements.values()) / total if total else float("nan")
        w.append(f"Convex sample: the 23 elements take **{100 * share:.1f} %** of its wear "
                 f"({sum(elements.values()):.2f} of {total:.2f} mm^3), the base {base:.2f} mm^3.\n")
        w.append("| element | wear [mm^3] | element | wear [mm^3] | element | wear [mm^3] |")
        w.append("|---|---|---|---|---|---|")
        names = list(elements)
        for k in range(0, len(names), 3):
            cells = []
            for n in names[k:k + 3]:
                cells += [n, f"{elements[n]:.2f}"]
            cells += [""] * (6 - len(cells))
            w.append("| " + " | ".join(cells) + " |")
        w.append("")
        trio = [elements.get(n) for n in ("C11", "C13", "C15")]
        if all(v is not None for v in trio):
            w.append(f"Leading column, inner to outer: C11 {trio[0]:.2f}, C13 {trio[1]:.2f}, C15 {trio[2]:.2f} mm^3 "
                     f"(C15 / C11 = {trio[2] / trio[0]:.2f}; the outer radius moves faster).\n")
        w.append("![per-element wear on the footprint](reference_study_map.png)\n")
    if plot_profiles(C, out):
        w.append("![worn profiles](reference_study_profiles.png)\n")

    # Flow
    w.append("## Loads and flow per revolution\n")
    w.append("![force, speed, spin](reference_study_flow.png)\n")
    w.append("| sample | window | mean normal force [N] | bottom-layer speed [m/s] | bottom-layer spin [rad/s] | C_v speed | C_v bed height | C_v wear rate |")
    w.append("|---|---|---|---|---|---|---|---|")
    for name, r in (("plain", P), ("convex", C)):
        idx, _ = r.after_steady()
        if len(idx) == 0:
            continue
        rows = [r.rows[i] for i in idx]
        mean = lambda k: float(np.mean([x[k] for x in rows]))  # noqa: E731
        s = r.steady_judgement()
        cv = r.rows[s - 1] if s else r.rows[idx[0] - 1]
        w.append(f"| {name} | revolutions {int(rows[0]['revolution'])}-{int(rows[-1]['revolution'])} | "
                 f"{mean('normal_force_mean_N'):.2f} | {mean('bottom_speed_mean_m_s'):.3f} | "
                 f"{mean('bottom_spin_mean_rad_s'):.2f} | {cv['cv_speed']:.3f} | {cv['cv_bed_height']:.3f} | "
                 f"{cv['cv_wear_rate']:.3f} |")
    w.append("\nC_v: of the steady window the run judged itself by (revolution of its steady judgement).\n")
    w.append(BOTTOM_LAYER + "\n")

    # Seeds
    w.append("## Spread over insertion seeds (2 revolutions after steady state, 56 h)\n")
    rows, ratios = seed_table(runs)
    w.append("| sample | seed 1 | seed 2 | seed 3 | mean +- 95 % |")
    w.append("|---|---|---|---|---|")
    w += [f"| {k} | " + " | ".join(cells) + " |" for k, cells in rows]
    if ratios:
        m, h = interval(ratios)
        w.append(f"\nconvex / plain per seed: {', '.join(f'{x:.3f}' for x in ratios)}; mean {m:.3f} +- {fmt(h, 3)} "
                 f"(95 %, {len(ratios)} seed{'s' if len(ratios) > 1 else ''}).\n")

    w += node_moving_section(runs)

    w += size_trend_section(runs, missing)
    return "\n".join(w)


def parse_args(argv, defaults, usage):
    """The `--name value` options named in defaults (over their defaults) and whether `--check`
    was given; anything else stops with the usage line."""
    args = dict(defaults)
    check_only = "--check" in argv
    argv = [a for a in argv if a != "--check"]
    k = 0
    while k < len(argv):
        if argv[k] in args and k + 1 < len(argv):
            args[argv[k]] = argv[k + 1]
            k += 2
        else:
            fail(f"unexpected argument '{argv[k]}'; {usage}")
    return args, check_only


def write_atomic(path, text):
    """Writes text to path through a temporary file beside it, so a reader never sees half."""
    tmp = os.path.join(os.path.dirname(path), "." + os.path.basename(path) + ".tmp")
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def main(argv):
    args, check_only = parse_args(argv, {"--runs": RUNS, "--out": "docs/results",
                                         "--calibration": None}, __doc__.splitlines()[2])
    runs, missing, cal = load_runs(args["--runs"], args["--calibration"])
    if check_only:
        print(f"{PROG}: {len(runs)} runs ({', '.join(runs)}), engine {runs['plain'].engine}, "
              f"calibration {'present' if cal else 'not run'}; not run: {', '.join(missing) or 'none'}")
        return
    out = args["--out"]
    os.makedirs(out, exist_ok=True)
    plot_wear(runs, out)
    n = int(min(len(runs["plain"].after_steady()[1]), len(runs["convex"].after_steady()[1])))
    if n > 0:
        plot_columns_elements(runs, n, out)
        plot_map(runs["convex"], n, out)
    plot_flow(runs, out)
    text = report(runs, missing, cal, out)
    write_atomic(os.path.join(out, "reference-study.md"), text)
    print(f"{PROG}: {os.path.join(out, 'reference-study.md')} from {len(runs)} runs, engine {runs['plain'].engine}")


if __name__ == "__main__":
    main(sys.argv[1:])
