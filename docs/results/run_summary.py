#!/usr/bin/python3
"""A run folder's summary: what the reports in docs/results read of a run, in plain text.

Usage: /usr/bin/python3 docs/results/run_summary.py <run folder> <summary folder>

The run folder is the output folder of a `wearsim run` (or `wearsim dem`) run, with the log
cases/reference-study/run.sh writes beside it (<run folder>.log) when there is one. The summary
folder is replaced by one that holds:

  run.txt          the engine version, the revolutions done, the stage of the last surface
                   and where the profiles cut
  parameters.prm, summary.csv, stages.csv, calibration.prm, part_life.csv, part_wear.csv
                   copied as they are (those the run has; part_life.csv: each element's
                   height and volume and the part's thinnest point per stage; part_wear.csv:
                   the wear each stage applied per label)
  revolutions.csv  per revolution the wear of each column and each element (history.h5),
                   written exactly (Python repr reads back to the same float)
  surface_map.txt  the stage-0 wear face's face centroids by label, to 10 um (the map plot;
                   samples with elements only)
  profiles.csv     the wear face cut along the flow through C13 and C11 on the stage-0 and
                   the last surface (the profile plot)
  elements.csv     each element's highest and lowest z on the stage-0 and the last surface
                   (the element heights)
  ending.txt       how run.sh's last call on the run ended, from the log (no log: no file):
                   stopped by SIGTERM or an error, worn out, or nothing said

A run of the 1 mm convex sample makes about 0.55 MB (0.35 MB of it the map, the same file for
every run of that mesh), a plain one 30 to 50 kB, so that finished runs are kept in the
repository as these folders while their output is not. The reports (reference_study_report.py,
holder_cases_report.py) read summary folders only, with the readers below, which need no h5py.

A run continued from a kept checkpoint (cases/reference-study/keep_running.sh) holds its
stage-0 surface as an index entry only: its stage-0 parts are then taken from the summary
folder it replaces, which its first session wrote. A run that cannot be continued (no
checkpoint: the node-moving scheme starts afresh in every session) does not replace the
summary of the same case (same parameters.prm) when that went further.
"""
import csv
import os
import shutil
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "coupling", "output"))
from run_tables import run_file  # noqa: E402  (a run's file: its part's tables or the run folder's)

PROG = os.path.basename(sys.argv[0])
COPIED = ("parameters.prm", "summary.csv", "stages.csv", "calibration.prm", "part_life.csv", "part_wear.csv",
          "element_life.csv")
MAP_UNIT = 1e-5  # [m] the map's centroids are written to 10 um (far below a pixel of the plot)
PROFILE_LABELS = (13, 11)  # the profiles cut through the middle and the inner leading element


def fail(message):
    sys.exit(f"{PROG}: {message}")


def count_revolutions(folder):
    """The rows of <folder>/summary.csv (0 when it is missing or holds only its header)."""
    path = run_file(folder, "summary.csv")
    if not os.path.isfile(path):
        return 0
    with open(path) as f:
        return max(sum(1 for line in f if line.strip()) - 1, 0)


def read_csv(path):
    """The rows of a CSV file as dicts, numbers as floats."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k, v in list(r.items()):
            try:
                r[k] = float(v)
            except (TypeError, ValueError):
                pass
    return rows


# --- writing a summary -------------------------------------------------------------------

def revolutions_text(run):
    """revolutions.csv from the run's history.h5, or None when it has no revolution records (a
    `wearsim dem` run's history holds fields instead)."""
    import h5py  # the writer's alone: the reports read the summary without it

    path = run_file(run, "history.h5")
    if not os.path.isfile(path):
        return None
    with h5py.File(path, "r") as h:
        if "revolutions" not in h:
            return None
        rev = h["revolutions"]
        revolution = rev["revolution"][:]
        columns = rev["column_wear_m3"][:]
        labels = [int(v) for v in rev["element_labels"][:]] if "element_labels" in rev else []
        elements = rev["element_wear_m3"][:] if labels else np.zeros((len(revolution), 0))
    header = (["revolution"] + [f"column{j + 1}_wear_m3" for j in range(columns.shape[1])]
              + [f"C{lab}_wear_m3" for lab in labels])
    lines = [",".join(header)]
    for k, n in enumerate(revolution):
        values = list(columns[k]) + list(elements[k])
        lines.append(",".join([str(int(n))] + [repr(float(v)) for v in values]))
    return "\n".join(lines) + "\n"


def surface_stages(run):
    """The stages whose surface the run folder holds (surface/stage_NNNN.h5), ascending."""
    d = run_file(run, "surface")
    if not os.path.isdir(d):
        return []
    return sorted(int(f[6:10]) for f in os.listdir(d) if f.startswith("stage_") and f.endswith(".h5"))


def read_surface(run, stage):
    """(points, triangles, labels, wear depth) of a stage's surface, or None when the file is
    only its index entry (a stub a kept checkpoint's resume needs, keep_running.sh)."""
    import h5py

    with h5py.File(os.path.join(run_file(run, "surface"), f"stage_{stage:04d}.h5"), "r") as h:
        if "points" not in h:
            return None
        return (h["points"][:], h["triangles"][:].astype(int), h["cell/label"][:, 0].astype(int),
                h["cell/wear_depth"][:, 0])


def wear_face(labels):
    """The faces of the wear face: the base top (label 3) and the elements (11 and above)."""
    return (labels == 3) | (labels >= 11)


def map_text(surface):
    """surface_map.txt: the wear face's face centroids (x, y) in units of MAP_UNIT by label,
    sorted along y then x, each line the difference from the one before (a label's first from
    0 0: small numbers, a third of the file absolute ones would make); None for a sample
    without elements (nothing to map)."""
    pts, tri, lab, _ = surface
    if not np.any(lab >= 11):
        return None
    c = np.rint(pts[tri].mean(axis=1)[:, :2] / MAP_UNIT).astype(np.int64)
    lines = ["# The wear face at stage 0 (docs/results/run_summary.py): the centroid (x, y) of each",
             f"# face in units of {MAP_UNIT:g} m, sample frame, the faces of a label after its line",
             "# 'label <n> <faces>', sorted along y then x; each line is the difference from the one",
             "# before it (a label's first from 0 0)."]
    for label in sorted(set(lab[wear_face(lab)].tolist())):
        k = c[lab == label]
        k = k[np.lexsort((k[:, 0], k[:, 1]))]
        d = np.diff(k, axis=0, prepend=np.zeros((1, 2), np.int64))
        lines.append(f"label {label} {len(d)}")
        lines += [f"{x} {y}" for x, y in d.tolist()]
    return "\n".join(lines) + "\n"


def section(surface, x0):
    """The wear face (base top and elements) cut by the plane x = x0: the crossing points
    (y, z) sorted along y, with the wear depth of the face crossed there."""
    pts, tri, lab, depth = surface
    keep = np.nonzero(wear_face(lab))[0]
    p = pts[tri[keep]]
    xs = p[:, :, 0] - x0
    ys, zs, fs = [], [], []
    for t in np.nonzero((xs.min(axis=1) <= 0) & (xs.max(axis=1) >= 0))[0]:
        for a, b in ((0, 1), (1, 2), (2, 0)):
            da, db = xs[t, a], xs[t, b]
            if (da <= 0 <= db or db <= 0 <= da) and da != db:
                s = da / (da - db)
                q = p[t, a] + s * (p[t, b] - p[t, a])
                ys.append(q[1])
                zs.append(q[2])
                fs.append(depth[keep[t]])
    order = np.argsort(ys, kind="stable")
    return np.array(ys)[order], np.array(zs)[order], np.array(fs)[order]


def profile_lines(surface):
    """Where the profiles cut: (name, x) for C13 and C11 at the mean x of their face centroids
    on the stage-0 surface, those the sample has."""
    pts, tri, lab, _ = surface
    c = pts[tri].mean(axis=1)
    return [(f"C{k}", float(c[lab == k, 0].mean())) for k in PROFILE_LABELS if np.any(lab == k)]


def profile_rows(lines, stage, surface):
    """The rows of profiles.csv for one surface cut along the given lines: y, z and the wear
    depth in micrometres to 0.1 um (a fiftieth of a pixel of the plot or less)."""
    rows = []
    for name, x0 in lines:
        for y, z, d in zip(*section(surface, x0)):
            rows.append([name, str(stage)] + [f"{v * 1e6:.1f}" for v in (y, z, d)])
    return rows


def element_rows(stage, surface):
    """The rows of elements.csv for one surface: each element's highest and lowest point."""
    pts, tri, lab, _ = surface
    z = pts[tri][:, :, 2]
    return [[str(k), str(stage), repr(float(z[lab == k].max())), repr(float(z[lab == k].min()))]
            for k in np.unique(lab) if k >= 11]


def csv_text(header, rows):
    """A CSV file's text from its header and rows (lists of strings)."""
    return "\n".join([",".join(header)] + [",".join(r) for r in rows]) + "\n"


def unworn_parts(run, old):
    """The stage-0 parts of the summary: {"map": text, "lines": profile lines, "profiles": rows,
    "elements": rows}, from the run's stage-0 surface or, when that is an index stub (a run
    continued from a kept checkpoint), from the old summary its first session wrote."""
    first = read_surface(run, 0)
    if first is not None:
        lines = profile_lines(first)
        return {"map": map_text(first), "lines": lines, "profiles": profile_rows(lines, 0, first),
                "elements": element_rows(0, first)}
    if not os.path.isfile(os.path.join(old, "run.txt")):
        fail(f"'{run}/surface/stage_0000.h5' holds no surface (a run continued from a kept "
             f"checkpoint) and '{old}' no summary to take the stage-0 surface's parts from")
    map_file = os.path.join(old, "surface_map.txt")
    text = None
    if os.path.isfile(map_file):
        with open(map_file) as f:
            text = f.read()
    return {"map": text, "lines": read_profile_lines(old),
            "profiles": [r for r in read_rows(old, "profiles.csv") if r[1] == "0"],
            "elements": [r for r in read_rows(old, "elements.csv") if r[1] == "0"]}


def surface_parts(run, old):
    """({file name: text} of the surface parts, the last surface's stage or None when the run
    holds no surface past stage 0, the profile lines)."""
    stages = surface_stages(run)
    if 0 not in stages:
        return {}, None, []
    unworn = unworn_parts(run, old)
    files = {"surface_map.txt": unworn["map"]}
    last = stages[-1] if stages[-1] > 0 else None
    if last is not None:
        surface = read_surface(run, last)
        if surface is None:
            fail(f"'{run}/surface/stage_{last:04d}.h5', the last surface, holds only its index entry")
        files["profiles.csv"] = csv_text(["line", "stage", "y_um", "z_um", "wear_depth_um"],
                                         unworn["profiles"] + profile_rows(unworn["lines"], last, surface))
        files["elements.csv"] = csv_text(["label", "stage", "top_z_m", "bottom_z_m"],
                                         unworn["elements"] + element_rows(last, surface))
    return files, last, unworn["lines"]


def last_call_ending(log, stages):
    """How the last call of run.sh on the run ended, from its part of the log (from the last
    line starting "=== "): "stopped by SIGTERM in stage k of n", "stopped by an error in stage
    k: <what>" (k the stage after the last in stages.csv, <what> the error's first clause),
    "worn out at N h after stage k: <why>" (the end criterion Coupling/Worn out when met), or
    "" when it tells none of them (finished, still running, or killed without a word)."""
    with open(log, errors="replace") as f:
        lines = [line.strip() for line in f]
    starts = [k for k, line in enumerate(lines) if line.startswith("=== ")]
    last = lines[starts[-1] if starts else 0:]
    stage = int(stages[-1]["stage"]) + 1 if stages else 1
    for line in reversed(last):
        if line.startswith("stopped by SIGTERM in stage"):
            return line.split(" (")[0].split(" at t = ")[0]  # older and current wording
        if line.startswith("part '") and "' worn out at " in line:
            return "worn out at " + line.split("' worn out at ", 1)[1].split(" (Coupling/")[0].split("; ")[0]
        if "error:" in line:
            what = line.split("error:", 1)[1].split("; ")[0].strip()
            return f"stopped by an error in stage {stage}: {what}"
    return ""


def engine_version(run):
    """The engine version on the second line of the run's parameters.prm, or None."""
    with open(run_file(run, "parameters.prm")) as f:
        f.readline()
        line = f.readline()
    return line.split(":", 1)[1].strip() if line.startswith("# Engine version:") else None


def keeps_further_run(run, old):
    """Whether the old summary is of the same case as the run and went further while the run
    cannot be continued (no checkpoint), so that it stays."""
    if os.path.isfile(run_file(run, "checkpoint.h5")) or not os.path.isfile(os.path.join(old, "run.txt")):
        return False
    with open(run_file(run, "parameters.prm")) as a, open(os.path.join(old, "parameters.prm")) as b:
        same_case = a.read() == b.read()
    return same_case and count_revolutions(old) > count_revolutions(run)


def run_text(run, last, lines):
    """run.txt: the engine version, the revolutions done, the last surface's stage and where
    the profiles cut (exact: a later session cuts its last surface there too)."""
    text = (f"# Summary of a run folder, written by docs/results/run_summary.py\n"
            f"engine: {engine_version(run) or 'none named (parameters.prm)'}\n"
            f"revolutions: {count_revolutions(run)}\n"
            f"last surface: {last if last is not None else 'none'}\n")
    return text + "".join(f"profile {name} at x [m]: {x0!r}\n" for name, x0 in lines)


def summary_files(run, old):
    """{file name: text} of the run's summary (old: the summary folder it replaces)."""
    files = {}
    for name in COPIED:
        if os.path.isfile(run_file(run, name)):
            with open(run_file(run, name)) as f:
                files[name] = f.read()
    files["revolutions.csv"] = revolutions_text(run)
    surfaces, last, lines = surface_parts(run, old)
    files.update(surfaces)
    log = os.path.normpath(run) + ".log"
    stages = read_csv(run_file(run, "stages.csv")) if "stages.csv" in files else []
    files["ending.txt"] = last_call_ending(log, stages) + "\n" if os.path.isfile(log) else None
    files["run.txt"] = run_text(run, last, lines)
    return {k: v for k, v in files.items() if v is not None}


def write_summary(files, dest):
    """Replaces the folder dest by one holding files ({name: text}), through a folder beside it."""
    parent = os.path.dirname(os.path.abspath(dest))
    os.makedirs(parent, exist_ok=True)
    tmp = os.path.join(parent, "." + os.path.basename(os.path.abspath(dest)) + ".new")
    shutil.rmtree(tmp, ignore_errors=True)
    os.makedirs(tmp)
    for name, text in files.items():
        with open(os.path.join(tmp, name), "w") as f:
            f.write(text)
    if os.path.isdir(dest):
        shutil.rmtree(dest)
    os.replace(tmp, dest)


def summarise(run, dest):
    """Writes the summary of run folder `run` into `dest`; returns a line saying what it did."""
    for name in ("parameters.prm", "summary.csv"):
        if not os.path.isfile(run_file(run, name)):
            fail(f"'{run}/{name}' does not exist (is '{run}' a wearsim run folder?)")
    if keeps_further_run(run, dest):
        return (f"{dest} kept: its run went further ({count_revolutions(dest)} revolutions) than "
                f"'{run}' ({count_revolutions(run)}), which cannot be continued")
    write_summary(summary_files(run, dest), dest)
    files = os.listdir(dest)
    size = sum(os.path.getsize(os.path.join(dest, f)) for f in files)
    return f"{dest}: {count_revolutions(run)} revolutions of '{run}', {len(files)} files, {size / 1e3:.0f} kB"


# --- reading a summary (the reports) -----------------------------------------------------

def read_run_txt(folder):
    """The `key: value` lines of <folder>/run.txt."""
    out = {}
    with open(os.path.join(folder, "run.txt")) as f:
        for line in f:
            if ":" in line and not line.startswith("#"):
                k, v = line.split(":", 1)
                out[k.strip()] = v.strip()
    return out


def read_revolutions(folder):
    """(element labels, element wear [revolution, element], column wear [revolution, column]) in
    m^3 from revolutions.csv, or ([], None, None) when the summary has none."""
    path = os.path.join(folder, "revolutions.csv")
    if not os.path.isfile(path):
        return [], None, None
    with open(path) as f:
        header = f.readline().strip().split(",")
        values = np.array([[float(v) for v in line.split(",")[1:]] for line in f if line.strip()],
                          dtype=float).reshape(-1, len(header) - 1)
    n_columns = sum(1 for h in header if h.startswith("column"))
    labels = [int(h[1:].split("_")[0]) for h in header if h.startswith("C")]
    return labels, np.ascontiguousarray(values[:, n_columns:]), np.ascontiguousarray(values[:, :n_columns])


def read_map(folder):
    """(centroids [face, (x, y)] in m, labels) of the stage-0 wear face from surface_map.txt, or
    None when the summary has no map."""
    path = os.path.join(folder, "surface_map.txt")
    if not os.path.isfile(path):
        return None
    blocks, labels = [], []
    with open(path) as f:
        lines = [line.split() for line in f if line.strip() and not line.startswith("#")]
    k = 0
    while k < len(lines):
        label, n = int(lines[k][1]), int(lines[k][2])
        d = np.array(lines[k + 1:k + 1 + n], dtype=np.int64).reshape(n, 2)
        blocks.append(np.cumsum(d, axis=0))
        labels += [label] * n
        k += n + 1
    return np.concatenate(blocks) * MAP_UNIT, np.array(labels, dtype=int)


def read_rows(folder, name):
    """The rows after the header of a summary's CSV file as lists of strings (none when the
    summary has no such file)."""
    path = os.path.join(folder, name)
    if not os.path.isfile(path):
        return []
    with open(path) as f:
        return [line.strip().split(",") for line in f.readlines()[1:] if line.strip()]


def read_profile_lines(folder):
    """[(line name, x [m])]: where the profiles cut, from run.txt."""
    return [(k.split()[1], float(v)) for k, v in read_run_txt(folder).items() if k.startswith("profile ")]


def read_profiles(folder):
    """[(line name, x [m], {stage: (y, z, wear depth) arrays [m]})] from profiles.csv."""
    cuts = {name: {} for name, _ in read_profile_lines(folder)}
    for name, stage, y, z, d in read_rows(folder, "profiles.csv"):
        cuts[name].setdefault(int(stage), []).append((float(y) * 1e-6, float(z) * 1e-6, float(d) * 1e-6))
    return [(name, x0, {s: tuple(np.array(c) for c in zip(*pts)) for s, pts in cuts[name].items()})
            for name, x0 in read_profile_lines(folder)]


def read_elements(folder):
    """{stage: {label: (highest z, lowest z) [m]}} from elements.csv."""
    out = {}
    for label, stage, top, bottom in read_rows(folder, "elements.csv"):
        out.setdefault(int(stage), {})[int(label)] = (float(top), float(bottom))
    return out


def main(argv):
    """The command: one run folder summarised into one summary folder."""
    if len(argv) != 2:
        fail("usage: run_summary.py <run folder> <summary folder>")
    print(f"{PROG}: {summarise(argv[0], argv[1])}")


if __name__ == "__main__":
    main(sys.argv[1:])
