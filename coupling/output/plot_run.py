#!/usr/bin/env python3
"""Plots of a `wearsim run` results folder (PNG files written into <run>/plots/).

    /usr/bin/python3 coupling/output/plot_run.py <run> [--elements C13,C33]
    /usr/bin/python3 coupling/output/plot_run.py --compare <runA> <runB> [--output DIR]
    /usr/bin/python3 coupling/output/plot_run.py --compare [--from K] <A1> [<A2> ...] -- <B1> [...]

One run: wear vs revolutions with the fits y = a x and y = b x^2 + c x (R^2), wear per column
and per convex element, normal force, bottom-layer speeds, coefficients of variation, stress
per stage, and worn profiles (side and front views) of chosen convex elements per stage.
Compare: cumulative wear and wear per revolution of every run of both sides, the mean wear
per revolution after steady state with its 95 % interval (band; bars with error bars for the
wear face and each column), peak ball-averaged von Mises per stage (error bars across runs).
The intervals are those of `wearsim compare`: batch means over one run's revolutions, or
across runs. Stress per stage: the largest ball-averaged von Mises (converges under
refinement), the volume-weighted 99.9th and 99th percentiles, and the largest
quadrature-point value (mesh-dependent); runs written before these columns show only the
last (max_von_mises_Pa).
Needs python3-matplotlib, python3-numpy and python3-h5py (Debian packages).
"""
import argparse
import csv
import glob
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from run_tables import tables_of  # noqa: E402  (where a run's tables are: parts/sample/ of a tester run)


def read_csv(path):
    if not os.path.exists(path):
        sys.exit(f"plot_run: '{path}' does not exist (is this a wearsim run folder?)")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return rows


def column(rows, name, default=np.nan):
    out = []
    for r in rows:
        try:
            out.append(float(r.get(name, default)))
        except (TypeError, ValueError):
            out.append(default)
    return np.array(out)


def qp_von_mises(rows):
    """[Pa] largest quadrature-point von Mises per stage (max_von_mises_Pa in older runs)."""
    qp = column(rows, "max_von_mises_qp_Pa")
    return np.where(np.isnan(qp), column(rows, "max_von_mises_Pa"), qp)


def ball_von_mises(rows):
    """[Pa] largest ball-averaged von Mises per stage; the quadrature-point value for runs
    written before the ball average (the caller labels it)."""
    ball = column(rows, "max_von_mises_ball_Pa")
    return (ball, True) if not np.all(np.isnan(ball)) else (qp_von_mises(rows), False)


def positive(v):
    """v with the stages without a solve (0) as gaps, for a log axis."""
    return np.where(v > 0, v, np.nan)


def fits(x, y):
    """Least squares through the origin: y = a x and y = b x^2 + c x, with R^2."""
    if len(x) == 0:
        return None
    a = float(np.dot(x, y) / np.dot(x, x))
    m = np.vstack([x * x, x]).T
    (b, c), *_ = np.linalg.lstsq(m, y, rcond=None)
    ss = float(np.sum((y - y.mean()) ** 2)) or 1.0
    r2a = 1 - float(np.sum((y - a * x) ** 2)) / ss
    r2q = 1 - float(np.sum((y - b * x * x - c * x) ** 2)) / ss
    return a, r2a, b, c, r2q


def save(fig, path):
    for ax in fig.axes:
        if ax.get_xlabel() in ("revolution", "stage"):
            ax.xaxis.get_major_locator().set_params(integer=True)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print("wrote", path)


def plot_wear(rows, out):
    rev = column(rows, "revolution")
    cum = column(rows, "wear_volume_cumulative_m3") * 1e9
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(rev, cum, "o", label="DEM wear (wear law, not amplified)")
    f = fits(rev, cum)
    if f:
        a, r2a, b, c, r2q = f
        x = np.linspace(0, rev.max(), 100)
        ax.plot(x, a * x, "-", label=f"y = {a:.3g} x  (R$^2$ = {r2a:.4f})")
        ax.plot(x, b * x * x + c * x, "--", label=f"y = {b:.3g} x$^2$ + {c:.3g} x  (R$^2$ = {r2q:.4f})")
    ax.set_xlabel("revolution")
    ax.set_ylabel("cumulative wear volume [mm$^3$]")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    save(fig, os.path.join(out, "wear.png"))


def plot_bars(rows, out):
    last = rows[-1:]
    cols = sorted(k for k in rows[0] if k.startswith("column") and k.endswith("_wear_m3"))
    elems = [k for k in rows[0] if k.startswith("C") and k.endswith("_wear_m3")]
    fig, axes = plt.subplots(1, 2, figsize=(10, 4), gridspec_kw={"width_ratios": [1, 3]})
    total_col = [column(rows, k).sum() * 1e9 for k in cols]
    axes[0].bar([k.replace("_wear_m3", "") for k in cols], total_col, color="tab:blue")
    axes[0].set_ylabel("wear over all revolutions [mm$^3$]")
    axes[0].set_title("per column")
    if elems:
        total_el = [column(rows, k).sum() * 1e9 for k in elems]
        axes[1].bar([k.replace("_wear_m3", "") for k in elems], total_el, color="tab:orange")
        axes[1].set_title("per convex element")
        axes[1].tick_params(axis="x", rotation=90)
    else:
        axes[1].text(0.5, 0.5, "plain sample: no elements", ha="center", transform=axes[1].transAxes)
    del last
    save(fig, os.path.join(out, "wear_per_column_and_element.png"))


def plot_flow(rows, out):
    rev = column(rows, "revolution")
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
    axes[0].errorbar(rev, column(rows, "normal_force_mean_N"), column(rows, "normal_force_std_N"), fmt="o-")
    axes[0].set_ylabel("normal force on the wear face [N]")
    axes[1].errorbar(rev, column(rows, "bottom_speed_mean_m_s"), column(rows, "bottom_speed_std_m_s"),
                     fmt="o-", label="speed [m/s]")
    ax2 = axes[1].twinx()
    ax2.errorbar(rev, column(rows, "bottom_spin_mean_rad_s"), column(rows, "bottom_spin_std_rad_s"),
                 fmt="s--", color="tab:red", label="angular speed [rad/s]")
    axes[1].set_ylabel("bottom-layer speed [m/s]")
    ax2.set_ylabel("bottom-layer angular speed [rad/s]", color="tab:red")
    for name, label in [("cv_speed", "speed over the sample"), ("cv_bed_height", "bed height"),
                        ("cv_wear_rate", "wear rate")]:
        axes[2].plot(rev, column(rows, name), "o-", label=label)
    axes[2].set_ylabel("coefficient of variation [-]")
    axes[2].legend(fontsize=8)
    for ax in axes:
        ax.set_xlabel("revolution")
        ax.grid(alpha=0.3)
    save(fig, os.path.join(out, "flow.png"))


def plot_stages(stages, out):
    if not stages:
        return
    st = column(stages, "stage")
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8))
    axes[0].plot(st, column(stages, "applied_volume_m3") * 1e9, "o-", label="asked (wear x amplification)")
    axes[0].plot(st, column(stages, "geometry_volume_change_m3") * 1e9, "x--", label="removed by the mesh update")
    worn_through = column(stages, "worn_through_volume_m3", 0.0) * 1e9
    if np.nansum(worn_through) > 0:
        axes[0].plot(st, worn_through, "s:", label="asked of worn-through faces (not removed)")
    axes[0].set_ylabel("volume per stage [mm$^3$]")
    axes[0].legend(fontsize=8)
    radius = column(stages, "stress_averaging_radius_m")
    ball = "ball average" + (f" (R = {radius[0] * 1e3:.2g} mm)" if len(radius) and radius[0] > 0 else "")
    for name, label, style in [("max_von_mises_ball_Pa", "max of the " + ball, "o-"),
                               ("von_mises_p999_Pa", "99.9th percentile (by volume)", "s--"),
                               ("von_mises_p99_Pa", "99th percentile (by volume)", "^--")]:
        v = positive(column(stages, name) * 1e-6)
        if not np.all(np.isnan(v)):
            axes[1].plot(st, v, style, label=label)
    axes[1].plot(st, positive(qp_von_mises(stages) * 1e-6), "x:", color="gray",
                 label="max at a quadrature point (mesh-dependent)")
    axes[1].set_yscale("log")
    axes[1].set_ylabel("von Mises [MPa]")
    axes[1].legend(fontsize=7)
    for k, r in enumerate(stages):
        if float(r.get("remeshes", 0)) > 0:
            axes[1].axvline(st[k], color="gray", alpha=0.3)
    for ax in axes:
        ax.set_xlabel("stage")
        ax.grid(alpha=0.3)
    save(fig, os.path.join(out, "stages.png"))


def element_label(name):
    return 10 * int(name[1]) + int(name[2])


def section(pts, tri, axis, value):
    """Segments where the triangles cross the plane coordinate[axis] = value."""
    segs = []
    for t in tri:
        p = pts[t]
        d = p[:, axis] - value
        cut = []
        for i in range(3):
            j = (i + 1) % 3
            if (d[i] < 0) != (d[j] < 0):
                s = d[i] / (d[i] - d[j])
                cut.append(p[i] + s * (p[j] - p[i]))
        if len(cut) == 2:
            segs.append(cut)
    return segs


def plot_profiles(run, elements, out):
    """Mid-plane sections of convex elements per stage: side (y-z at the element's centre x)
    and front (x-z at its centre y), from the surface files of the stages."""
    try:
        import h5py
    except ImportError:
        print("plot_run: python3-h5py missing, no profiles")
        return
    from matplotlib.collections import LineCollection

    files = sorted(glob.glob(os.path.join(run, "surface", "stage_*.h5")))
    if len(files) > 6:  # first, last and about four in between
        keep = set(np.linspace(0, len(files) - 1, 6).round().astype(int))
        files = [f for k, f in enumerate(files) if k in keep]
    for name in elements:
        lab = element_label(name)
        fig, axes = plt.subplots(1, 2, figsize=(10, 3.6))
        centre = None
        colours = plt.cm.viridis(np.linspace(0, 0.9, max(1, len(files))))
        for k, path in enumerate(files):
            with h5py.File(path, "r") as h5:
                pts = h5["/points"][...]
                tri = h5["/triangles"][...]
                labels = h5["/cell/label"][...].ravel()
            mine = tri[labels == lab]
            if mine.size == 0:
                continue
            if centre is None:  # the unworn element's footprint centre
                centre = pts[np.unique(mine.ravel())].mean(axis=0)
            stage = int(os.path.basename(path)[6:10])
            for ax, axis, horiz, title in [(axes[0], 0, 1, "side view (section at its centre x)"),
                                           (axes[1], 1, 0, "front view (section at its centre y)")]:
                segs = section(pts, mine, axis, centre[axis])
                lines = [[(a[horiz] * 1e3, a[2] * 1e3), (b[horiz] * 1e3, b[2] * 1e3)] for a, b in segs]
                ax.add_collection(LineCollection(lines, colors=[colours[k]], label=f"stage {stage}"))
                ax.set_title(f"{name}: {title}", fontsize=10)
                ax.set_xlabel("y [mm]" if horiz == 1 else "x [mm]")
                ax.set_ylabel("z [mm]")
        if centre is None:
            plt.close(fig)
            continue
        for ax in axes:
            ax.autoscale()
            ax.set_aspect("equal", adjustable="datalim")
            ax.grid(alpha=0.3)
        axes[0].legend(fontsize=7)
        save(fig, os.path.join(out, f"profile_{name}.png"))


def plot_wear_out(run, stages, out, hours_per_revolution):
    """Removed volume and the height of every convex element (max z - min z of its surface)
    against equivalent test hours: revolutions x amplification x hours per revolution
    (the reference study's alpha: 2 revolutions = 56 h, so 28 h)."""
    try:
        import h5py
    except ImportError:
        return
    files = sorted(glob.glob(os.path.join(run, "surface", "stage_*.h5")))
    if not stages or len(files) < 2:
        return
    hours = {0: 0.0}
    total = 0.0
    for r in stages:
        if r.get("scheme_name") != "dem-only":
            n = float(r["last_revolution"]) - float(r["first_revolution"]) + 1
            total += n * float(r["amplification"]) * hours_per_revolution
        hours[int(float(r["stage"]))] = total
    heights = {}  # label -> [(hours, height)]
    for path in files:
        stage = int(os.path.basename(path)[6:10])
        if stage not in hours:
            continue
        with h5py.File(path, "r") as h5:
            pts = h5["/points"][...]
            tri = h5["/triangles"][...]
            labels = h5["/cell/label"][...].ravel()
        for lab in np.unique(labels):
            if lab < 11 or lab > 99 or lab % 10 == 0:
                continue
            z = pts[np.unique(tri[labels == lab].ravel()), 2]
            heights.setdefault(int(lab), []).append((hours[stage], (z.max() - z.min()) * 1e3))
    if not heights:
        return
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    st_hours = [hours[int(float(r["stage"]))] for r in stages]
    axes[0].plot(st_hours, column(stages, "cumulative_applied_m3") * 1e9, "o-", ms=3)
    axes[0].set_ylabel("volume removed from the sample [mm$^3$]")
    colours = plt.cm.tab20(np.linspace(0, 1, len(heights)))
    for c, (lab, hz) in zip(colours, sorted(heights.items())):
        hz = np.array(hz)
        axes[1].plot(hz[:, 0], hz[:, 1], "-", color=c, label=f"C{lab}")
    axes[1].set_ylabel("element height (max z - min z) [mm]")
    axes[1].legend(fontsize=6, ncol=3)
    for ax in axes:
        ax.set_xlabel(f"equivalent test hours ({hours_per_revolution:g} h per revolution x amplification)")
        ax.grid(alpha=0.3)
    save(fig, os.path.join(out, "wear_out.png"))


def plot_run(run, elements, hours_per_revolution=28.0):
    out = os.path.join(run, "plots")
    os.makedirs(out, exist_ok=True)
    rows = read_csv(os.path.join(run, "summary.csv"))
    if not rows:
        sys.exit(f"plot_run: '{run}/summary.csv' holds no revolution yet")
    stages = read_csv(os.path.join(run, "stages.csv"))
    plot_wear(rows, out)
    plot_bars(rows, out)
    plot_flow(rows, out)
    plot_stages(stages, out)
    plot_profiles(run, elements, out)
    plot_wear_out(run, stages, out, hours_per_revolution)


def t_quantile(p, dof):
    """Student-t quantile by bisection on the distribution function (Simpson integration of the
    density); the plots need two or three digits. coupling/analysis/interval.cc is the reference."""
    if dof > 1e6:
        dof = 1e6
    c = math.exp(math.lgamma((dof + 1) / 2) - math.lgamma(dof / 2)) / math.sqrt(dof * math.pi)
    def cdf(t, n=2000):
        h = t / n
        f = [c * (1 + (i * h) ** 2 / dof) ** (-(dof + 1) / 2) for i in range(n + 1)]
        return 0.5 + h / 3 * (f[0] + f[-1] + 4 * sum(f[1:-1:2]) + 2 * sum(f[2:-1:2]))
    lo, hi = 0.0, 1.0
    while cdf(hi) < p:
        hi *= 2
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if cdf(mid) < p else (lo, mid)
    return 0.5 * (lo + hi)


def batch_means(x):
    """Mean and 95 % half-width of one run's series: batches of ceil(5 tau) values (at least 5
    batches), tau by Sokal's window; the rule of coupling/analysis/interval.cc."""
    x = np.asarray(x, dtype=float)
    n = len(x)
    d = x - x.mean()
    c0 = float(np.dot(d, d)) / n
    tau = 1.0
    if c0 > 0:
        for lag in range(1, n):
            tau += 2 * float(np.dot(d[:-lag], d[lag:])) / n / c0
            if lag >= 5 * tau:
                break
    b = max(1, min(math.ceil(5 * tau), n // 5))
    k = n // b
    y = x[n - k * b:].reshape(k, b).mean(axis=1)
    se = y.std(ddof=1) / math.sqrt(k)
    return y.mean(), (t_quantile(0.975, k - 1) * se if se > 0 else 0.0)


def across_runs(values):
    """Mean and 95 % half-width across independent runs (t with n - 1 dof)."""
    v = np.asarray(values, dtype=float)
    se = v.std(ddof=1) / math.sqrt(len(v))
    return v.mean(), (t_quantile(0.975, len(v) - 1) * se if se > 0 else 0.0)


def after_steady(rows, first):
    """Rows from revolution `first` on (0: after the run's steady revolution)."""
    if first <= 0:
        steady = int(column(rows[-1:], "steady_revolution")[0])
        if steady == 0:
            return []
        first = steady + 1
    return [r for r in rows if float(r["revolution"]) >= first]


def side_estimate(runs, name, first):
    """Per-revolution figure `name` of one side: batch means of one run, or across runs."""
    series = [column(after_steady(rows, first), name) for rows in runs]
    if len(series) == 1:
        return batch_means(series[0]) if len(series[0]) >= 2 else (series[0].mean(), np.nan)
    return across_runs([x.mean() for x in series])


def plot_compare(side_a, side_b, out, first=0):
    """Both sides' runs on one figure, with 95 % intervals (the statistics of wearsim compare)."""
    os.makedirs(out, exist_ok=True)
    sides = []
    for dirs, label, color in [(side_a, "A", "tab:blue"), (side_b, "B", "tab:orange")]:
        runs = [read_csv(os.path.join(d, "summary.csv")) for d in dirs]
        for d, rows in zip(dirs, runs):
            if not after_steady(rows, first):
                sys.exit(f"plot_run: side {label}: run '{d}' has no revolutions after steady state "
                         "(or after --from); give --from <revolution>")
        stages = [read_csv(os.path.join(d, "stages.csv")) for d in dirs]
        names = ", ".join(os.path.basename(d.rstrip("/")) for d in dirs)
        sides.append((runs, stages, f"{label}: {names}", color))
    fig, axes = plt.subplots(1, 4, figsize=(19, 4.2))
    for runs, _, label, color in sides:
        for k, rows in enumerate(runs):
            axes[0].plot(column(rows, "revolution"), column(rows, "wear_volume_cumulative_m3") * 1e9,
                         "o-", color=color, alpha=0.8, label=label if k == 0 else None)
            axes[1].plot(column(rows, "revolution"), column(rows, "wear_volume_m3") * 1e9, ".-",
                         color=color, alpha=0.5, label=label if k == 0 else None)
        mean, half = side_estimate(runs, "wear_volume_m3", first)
        start = min(float(after_steady(rows, first)[0]["revolution"]) for rows in runs)
        end = max(column(rows, "revolution").max() for rows in runs)
        x = [start, end]
        axes[1].plot(x, [mean * 1e9] * 2, "-", color=color, lw=2)
        if not np.isnan(half):
            axes[1].fill_between(x, (mean - half) * 1e9, (mean + half) * 1e9, color=color, alpha=0.25)
    axes[0].set_xlabel("revolution")
    axes[0].set_ylabel("cumulative wear [mm$^3$]")
    axes[1].set_xlabel("revolution")
    axes[1].set_ylabel("wear per revolution [mm$^3$]\n(band: mean after steady state, 95 %)")
    cols = sorted(k for k in sides[0][0][0][0] if k.startswith("column") and k.endswith("_wear_m3"))
    names = ["wear_volume_m3"] + cols
    x = np.arange(len(names))
    for offset, (runs, _, label, color) in zip((-0.2, 0.2), sides):
        est = [side_estimate(runs, k, first) for k in names]
        axes[2].bar(x + offset, [m * 1e9 for m, _ in est], 0.4, yerr=[h * 1e9 for _, h in est],
                    capsize=3, color=color, label=label)
    axes[2].set_xticks(x, ["wear face"] + [k.replace("_wear_m3", "") for k in cols], rotation=30)
    axes[2].set_ylabel("wear per revolution after steady state [mm$^3$]\n(95 % interval)")
    for runs, stages, label, color in sides:
        n = min(len(s) for s in stages)
        if n == 0:
            continue
        stage = column(stages[0][:n], "stage")
        measured = [ball_von_mises(s[:n]) for s in stages]
        vm = np.array([v for v, _ in measured]) * 1e-6
        if not all(is_ball for _, is_ball in measured):  # a run from before the ball average
            label += " (quadrature-point max)"
        if len(stages) == 1:
            axes[3].plot(stage, vm[0], "o-", color=color, label=label + " (one run: no interval)")
        else:
            est = [across_runs(vm[:, j]) for j in range(n)]
            axes[3].errorbar(stage, [m for m, _ in est], [h for _, h in est], fmt="o-", capsize=3,
                             color=color, label=label)
    axes[3].set_xlabel("stage")
    axes[3].set_ylabel("peak ball-averaged von Mises [MPa]\n(95 % interval)")
    for ax in axes:
        ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
    save(fig, os.path.join(out, "compare.png"))


def main():
    # "--" separates the sides of --compare; argparse would swallow it, so it becomes "::".
    argv = ["::" if a == "--" else a for a in sys.argv[1:]]
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--compare", action="store_true",
                    help="compare runs: <runA> <runB>, or <A1> [<A2> ...] -- <B1> [<B2> ...]")
    ap.add_argument("--from", dest="first", type=int, default=0,
                    help="first revolution averaged (default: after each run's steady revolution)")
    ap.add_argument("--elements", default="C13,C33,C53", help="convex elements to draw profiles of")
    ap.add_argument("--output", default=None, help="folder of the comparison plot")
    ap.add_argument("--hours-per-revolution", type=float, default=28.0,
                    help="test hours one simulated revolution stands for (wear_out.png); "
                         "the reference study's alpha: 2 revolutions = 56 h")
    args = ap.parse_intermixed_args(argv)
    args.runs = [a if a == "::" else tables_of(a) for a in args.runs]
    side_b = []
    if "::" in args.runs:
        k = args.runs.index("::")
        args.runs, side_b = args.runs[:k], args.runs[k + 1:]
        if not args.runs or not side_b or "::" in side_b:
            sys.exit("plot_run: --compare <A1> [<A2> ...] -- <B1> [<B2> ...]: one '--' between "
                     "two non-empty sides")
    if not args.hours_per_revolution > 0:
        sys.exit("plot_run: --hours-per-revolution must be positive")
    if args.compare:
        side_a = args.runs
        if not side_b:
            if len(args.runs) != 2:
                sys.exit("plot_run: --compare takes two run folders, or several per side with '--' "
                         "between the sides")
            side_a, side_b = args.runs[:1], args.runs[1:]
        plot_compare(side_a, side_b, args.output or side_b[0] + "/plots", args.first)
    elif side_b:
        sys.exit("plot_run: '--' separates the two sides of --compare")
    else:
        for run in args.runs:
            plot_run(run, [e.strip() for e in args.elements.split(",") if e.strip()],
                     args.hours_per_revolution)


if __name__ == "__main__":
    main()
