"""A wearing part's life and the convex/plain ratio over it, from run summaries.

Read by holder_cases_report.py. A run summary (run_summary.py) holds the run's stages.csv and,
from engines that record it, part_life.csv: per stage each convex element's height above its
foot and volume above the foot, and the part's thinnest point above the clamped bottom and its
volume (the `what` column names the element, C<ij>, or `part`), with the equivalent hours the
stages up to it stand for.

Hours: a staged stage stands for (revolutions) x (amplification) x 28 h of the laboratory test
(docs/wear-tester.md); dem-only stages wear nothing and stand for none. A stage's DEM wear
(`dem_wear_volume_m3`, one revolution of Archard wear) is measured on the geometry the stages
before it left, so it is placed at the hours before the stage (`start_hours`); the part's life
after a stage is placed at the hours after it.

The convex/plain ratio at equal hours: the convex run's amplification is limited by its
elements (adaptive amplification), the plain one's seldom is, so their stages stand for
different hours; the plain run's figures are interpolated linearly in hours at the convex
run's, and nothing is extrapolated.
"""
import os

import numpy as np

import run_summary

HOURS_PER_REV = 28.0


def staged(run):
    """The run's staged stages, each with the laboratory hours before it (start_hours) and
    after it (cumulative_hours)."""
    rows, hours = [], 0.0
    for r in run.stages:
        if r["scheme_name"] != "staged":
            continue
        start = hours
        hours += (r["last_revolution"] - r["first_revolution"] + 1) * r["amplification"] * HOURS_PER_REV
        rows.append(dict(r, start_hours=start, cumulative_hours=hours))
    return rows


class Life:
    """One run's part_life.csv: per stage (ascending) the hours, the elements' (height [m],
    volume [m^3]) and the part's (thinnest point [m], volume [m^3]); or, file element_life.csv
    (`wearsim life`), the elements measured again on their unworn footprints, with the engine
    versions that measured them (measured_by)."""

    def __init__(self, run, file="part_life.csv"):
        path = os.path.join(run.path, file)
        self.stages, self.hours, self.elements, self.part = [], {}, {}, {}
        self.measured_by = set()
        if not os.path.isfile(path):
            return
        for r in run_summary.read_csv(path):
            k = int(r["stage"])
            if k not in self.hours:
                self.stages.append(k)
                self.hours[k], self.elements[k] = r["equivalent_hours"], {}
            if "measured_by" in r:
                self.measured_by.add(str(r["measured_by"]))
            if r["what"] == "part":
                self.part[k] = (r["height_m"], r["volume_m3"])
            else:
                self.elements[k][r["what"]] = (r["height_m"], r["volume_m3"])
        self.vanish = float(run.params.get("Vanish height", "0.25e-3"))

    def __bool__(self):
        return bool(self.stages)

    def n_elements(self):
        return len(self.elements[self.stages[0]]) if self.stages else 0

    def element_volume(self, stage):
        """The volume of the elements above their feet [m^3] after the stage."""
        return sum(v for _, v in self.elements[stage].values())

    def n_standing(self, stage):
        """The elements standing higher than the vanish height above their feet after the stage."""
        return sum(1 for h, _ in self.elements[stage].values() if h > self.vanish)

    def element_fraction(self):
        """[(hours, fraction of the unworn element volume left)] over the stages."""
        if not self.stages or not self.n_elements():
            return []
        v0 = self.element_volume(self.stages[0])
        return [(self.hours[k], self.element_volume(k) / v0) for k in self.stages]


def element_label_wear(run):
    """{stage: wear removed from the element labels up to and with the stage [m^3]} from the
    run's part_wear.csv (empty without one; its `cumulative_removed_volume_m3` per label, summed
    over the labels a stage lists: a label gone is no longer listed). Beside the element volume
    lost (Life), it tells the wear from what the life measure adds or takes: an element's
    volume stands above its foot, which moves with the boundary between its label and the
    base's."""
    path = os.path.join(run.path, "part_wear.csv")
    if not os.path.isfile(path):
        return {}
    out = {}
    for r in run_summary.read_csv(path):
        if str(r["label"]).startswith("C"):
            k = int(r["stage"])
            out[k] = out.get(k, 0.0) + r["cumulative_removed_volume_m3"]
    return out


def hours_at_fraction(points, fraction):
    """The hours at which the fraction left first falls to `fraction`, linear between the two
    stages around it; None when it has not yet."""
    for (h0, f0), (h1, f1) in zip(points, points[1:]):
        if f0 > fraction >= f1:
            return h0 + (h1 - h0) * (f0 - fraction) / (f0 - f1)
    return None


def interpolate(hours, xs, ys):
    """ys(xs) at hours, linear; None outside [xs[0], xs[-1]] (nothing extrapolated)."""
    if not xs or hours < xs[0] - 1e-9 or hours > xs[-1] + 1e-9:
        return None
    return float(np.interp(hours, xs, ys))


def rate_ratio(convex, plain):
    """Per staged stage of the convex run whose start the plain run covers: (stage, hours before
    it, convex DEM wear of one revolution [m^3], plain's at the same hours [m^3], ratio)."""
    p = staged(plain)
    xs, ys = [r["start_hours"] for r in p], [r["dem_wear_volume_m3"] for r in p]
    out = []
    for r in staged(convex):
        w = interpolate(r["start_hours"], xs, ys)
        if w is not None and w > 0:
            out.append((int(r["stage"]), r["start_hours"], r["dem_wear_volume_m3"], w,
                        r["dem_wear_volume_m3"] / w))
    return out


def cumulative_ratio(convex, plain):
    """Per staged stage of the convex run whose end the plain run covers: (hours after it, the
    volume the convex stages removed up to it [m^3], the plain ones' at the same hours [m^3],
    ratio)."""
    p = staged(plain)
    xs = [0.0] + [r["cumulative_hours"] for r in p]
    ys = [0.0] + [r["cumulative_applied_m3"] for r in p]
    out = []
    for r in staged(convex):
        w = interpolate(r["cumulative_hours"], xs, ys)
        if w is not None and w > 0:
            out.append((r["cumulative_hours"], r["cumulative_applied_m3"], w, r["cumulative_applied_m3"] / w))
    return out
