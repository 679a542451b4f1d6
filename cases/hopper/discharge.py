"""The discharge of a bin's scene run, shared by the hopper studies' reports
(cases/hopper/ranks_report.py, cases/hopper-rim/report.py).

The discharge rate W [kg/s] is the least-squares slope of the outlet's mass
(scene_series.csv, outlet_below_mass_kg) against time over a window of the run; intervals are
the 95 % intervals of Student's t (n - 1 degrees of freedom) of a mean over seeds.
"""
import csv
import math
import os

# two-sided 95 % quantiles of Student's t, by degrees of freedom
T95 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447, 7: 2.365, 8: 2.306,
       9: 2.262, 10: 2.228, 11: 2.201, 12: 2.179, 13: 2.160, 14: 2.145, 15: 2.131}


def rate(series, t_from, t_to):
    """[kg/s] slope of the outlet's mass over t_from <= t <= t_to (the rows land within a
    millisecond); None if the run ends before t_to."""
    t, m = [], []
    with open(series) as f:
        for row in csv.DictReader(f):
            time = float(row["time_s"])
            if t_from - 1e-3 <= time <= t_to + 1e-3:
                t.append(time)
                m.append(float(row["outlet_below_mass_kg"]))
    if not t or t[-1] < t_to - 1e-3:
        return None
    tm, mm = sum(t) / len(t), sum(m) / len(m)
    return sum((a - tm) * (b - mm) for a, b in zip(t, m)) / sum((a - tm) ** 2 for a in t)


def engine(folder):
    """The engine version a run's parameters.prm names."""
    with open(os.path.join(folder, "parameters.prm")) as f:
        for line in f:
            if line.startswith("# Engine version:"):
                return line.split(":", 1)[1].strip()
    return "unknown"


def mean_interval(x):
    """Mean of x and the half-width of its 95 % interval (nan for one value)."""
    n = len(x)
    m = sum(x) / n
    if n < 2:
        return m, float("nan")
    s = math.sqrt(sum((v - m) ** 2 for v in x) / (n - 1))
    return m, T95.get(n - 1, 1.96) * s / math.sqrt(n)
