#!/usr/bin/env python3
"""Takes the convex sample's worn surface after stage 23 of the wear-out run, and that
stage's removed volume per face, out of the run's kept checkpoint archive (in the
repository's history) into stage23.h5, the test data of the worn-geometry evolution.

The wear-out of the convex sample in its holder (engine b13327c60d5d, cases/wear-out at
s = 4, amplification 20 adapted to 19.04 in stage 23) stopped in stage 24: "the worn surface
folds at face 15745 (label C54) even in increments of 1/32 of the stage". The archive keeps
the surface after stage 23 (the start of stage 24) and the per-face volume stage 23 removed,
not stage 24's, which was never written: stage 23's volume is the increment a test applies
to the surface (one revolution of the same bed on a surface that changed by 0.4 %).

Written: the sample's volume mesh after stage 23 (vertices in the sample frame [m],
tetrahedra), its boundary surface as triangles of those vertices with their labels (the
labels of meshes::label: bottom 1, sides 2, base 3, element C<j><k> 10 j + k; the sides are
held, the sample stands in its holder), the removed volume per surface face [m^3] and the
stage's amplification. 0.77 MB, gzip-compressed.

usage: /usr/bin/python3 tests/data/wear-out/extract.py   (from the repository root; needs
h5py, git and the history commit 7937c06)
       /usr/bin/python3 tests/data/wear-out/extract.py <run folder> <stage> <engine> <out.h5>
       the same from a run folder of the current layout (parts/sample/, the checkpoint after
       that stage): stage15.h5 beside it from the coarse-grained wear-out's convex run
"""
import io
import os
import subprocess
import sys
import tarfile

import h5py
import numpy as np

ARCHIVE_COMMIT = "7937c06"
ARCHIVE = "cases/reference-study/state/wear-out-convex.tar.xz"
OUT = "tests/data/wear-out/stage23.h5"


def member(tar, name):
    return io.BytesIO(tar.extractfile(name).read())


def from_archive():
    """Stage 23 of the first wear-out run, from its archive in the repository's history."""
    blob = subprocess.run(["git", "show", f"{ARCHIVE_COMMIT}:{ARCHIVE}"], check=True,
                          capture_output=True).stdout
    with tarfile.open(fileobj=io.BytesIO(blob), mode="r:xz") as tar:
        surface = h5py.File(member(tar, "./surface/stage_0023.h5"), "r")
        checkpoint = h5py.File(member(tar, "./checkpoint.h5"), "r")
        stages = tar.extractfile("./stages.csv").read().decode().splitlines()
        write(surface, checkpoint["sample"], stages, 23, "b13327c60d5d",
              f"git show {ARCHIVE_COMMIT}:{ARCHIVE}, stage 23", OUT)


def from_run(run, stage, engine, out):
    """A stage of a run folder of the current engine (the sample's tables in parts/sample/,
    its checkpoint after that stage)."""
    part = os.path.join(run, "parts", "sample")
    with open(os.path.join(part, "stages.csv")) as f:
        stages = f.read().splitlines()
    surface = h5py.File(os.path.join(part, "surface", f"stage_{stage:04d}.h5"), "r")
    checkpoint = h5py.File(os.path.join(run, "checkpoint.h5"), "r")
    write(surface, checkpoint["scene/part_0/sample"], stages, stage, engine,
          f"{run}, stage {stage}", out)


def write(surface, sample, stages, stage, engine, source, out):
    """Writes the stage's surface (in volume-vertex numbers), volume mesh and removed volume."""
    points = surface["points"][:]
    triangles = surface["triangles"][:]
    labels = surface["cell/label"][:, 0]
    removed = surface["cell/stage_removed_volume"][:, 0]
    vertices = sample["vertices"][:]
    tetrahedra = sample["tetrahedra"][:]
    header = stages[0].split(",")
    row = dict(zip(header, stages[stage].split(",")))
    assert row["stage"] == str(stage), row["stage"]
    if not np.allclose(labels, np.round(labels)):
        sys.exit("extract.py: labels are not whole numbers")
    # The surface's vertices are volume vertices, the same doubles: the triangles are written
    # in volume-vertex numbers and the surface's own coordinates left out.
    index = {tuple(v): k for k, v in enumerate(vertices)}
    to_volume = np.array([index.get(tuple(p), -1) for p in points])
    if (to_volume < 0).any():
        sys.exit("extract.py: a surface vertex is not a vertex of the volume mesh")
    with h5py.File(out, "w") as f:
        opts = dict(compression="gzip", compression_opts=9, shuffle=True)
        f.create_dataset("vertices", data=vertices, **opts)
        f.create_dataset("tetrahedra", data=tetrahedra.astype(np.int32), **opts)
        f.create_dataset("triangles", data=to_volume[triangles].astype(np.int32), **opts)
        f.create_dataset("labels", data=np.round(labels).astype(np.int32), **opts)
        f.create_dataset("removed_volume", data=removed, **opts)
        f.attrs["amplification"] = float(row["amplification"])
        f.attrs["engine"] = engine
        f.attrs["source"] = source
    print(f"{out}: {len(vertices)} vertices, {len(tetrahedra)} tetrahedra, "
          f"{len(triangles)} surface faces, {removed.sum() * 1e9:.3f} mm^3 on "
          f"{int((removed > 0).sum())} faces, amplification {float(row['amplification'])}")


def main():
    if len(sys.argv) == 1:
        from_archive()
    elif len(sys.argv) == 5:
        from_run(sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
