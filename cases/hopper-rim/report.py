#!/usr/bin/env python3
"""The rim study's figures (cases/hopper-rim/README.md) from its runs' series.

    /usr/bin/python3 cases/hopper-rim/report.py [output/hopper-rim] [--update-readme]

Per run, the discharge rate W [kg/s] is the least-squares slope of the outlet's mass
(scene_series.csv, outlet_below_mass_kg) against time over 0.7 <= t <= 1.3 s: from 0.25 s
after the plug starts to drop (the flow formed, its first particles fallen the 0.1 m to the
outlet) to the run's end, while the bed still stands well above the orifice. For each orifice D the 32-gon and 128-gon runs of one seed share
their settled bed (the same insertion; the plates differ only at the rim, under the plug),
so the rims are compared seed by seed (the table says for how many seeds the two series agree
to the last digit until the plug drops): the relative difference of a seed,
(W_32 - W_128) / W_128, and its mean over the seeds with the 95 % interval of Student's t
(n - 1 degrees of freedom). The rims agree when that interval contains 0; it is narrow
enough to say so when its half-width is under 4 %.
With --update-readme the table replaces the block between the README's markers.
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "cases", "hopper"))
from discharge import engine, mean_interval, rate  # noqa: E402

T_FROM, T_TO = 0.7, 1.3  # [s]
T_DROP = 0.45  # [s] the plug starts to drop (base.prm)


def same_until_drop(a, b):
    """True when two runs' series hold the same text in every column at every record up to
    the plug's drop: the settled bed shared to the last digit."""
    with open(a) as fa, open(b) as fb:
        ra, rb = fa.read().splitlines(), fb.read().splitlines()
    rows = [(x, y) for x, y in zip(ra[1:], rb[1:]) if float(x.split(",")[0]) <= T_DROP + 1e-6]
    return ra[0] == rb[0] and len(rows) > 0 and all(x == y for x, y in rows)


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    out = args[0] if args else os.path.join(ROOT, "output", "hopper-rim")
    runs = {}
    engines = set()
    for name in sorted(os.listdir(out)):
        m = re.fullmatch(r"(\d+)-(\d+)-s(\d+)", name)
        series = os.path.join(out, name, "scene_series.csv")
        if not m or not os.path.exists(series):
            continue
        w = rate(series, T_FROM, T_TO)
        if w is None:
            continue
        runs[(int(m.group(2)), int(m.group(1)), int(m.group(3)))] = w
        engines.add(engine(os.path.join(out, name)))
    lines = ["Engine version %s; W from 0.7 to 1.3 s; seeds paired (same settled bed)." %
             ", ".join(sorted(engines)), "",
             "| D [mm] | D/d | seeds | same bed to the drop | W 128-gon [kg/s] | W 32-gon [kg/s] | "
             "(W_32 - W_128) / W_128, mean +- 95 % |",
             "|---|---|---|---|---|---|---|"]
    for d_mm in sorted({k[0] for k in runs}):
        seeds = sorted(s for (d, n, s) in runs if d == d_mm and n == 32 and (d, 128, s) in runs)
        if not seeds:
            continue
        w32 = [runs[(d_mm, 32, s)] for s in seeds]
        w128 = [runs[(d_mm, 128, s)] for s in seeds]
        rel = [100 * (a - b) / b for a, b in zip(w32, w128)]
        m128, h128 = mean_interval(w128)
        m32, h32 = mean_interval(w32)
        mr, hr = mean_interval(rel)
        n_same = sum(same_until_drop(os.path.join(out, "32-%d-s%d" % (d_mm, s), "scene_series.csv"),
                                     os.path.join(out, "128-%d-s%d" % (d_mm, s), "scene_series.csv"))
                     for s in seeds)
        lines.append("| %d | %.0f | %d | %d of %d | %.4f +- %.4f | %.4f +- %.4f | %+.2f +- %.2f %% |" %
                     (d_mm, d_mm / 6, len(seeds), n_same, len(seeds), m128, h128, m32, h32, mr, hr))
    text = "\n".join(lines) + "\n"
    print(text, end="")
    if "--update-readme" in sys.argv:
        readme = os.path.join(ROOT, "cases", "hopper-rim", "README.md")
        with open(readme) as f:
            body = f.read()
        begin, end = "<!-- rim-report:begin -->\n", "<!-- rim-report:end -->"
        i, j = body.index(begin) + len(begin), body.index(end)
        with open(readme + ".tmp", "w") as f:
            f.write(body[:i] + text + body[j:])
        os.replace(readme + ".tmp", readme)


if __name__ == "__main__":
    main()
