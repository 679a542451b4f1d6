#!/usr/bin/env python3
"""How close a node-moving (reference scheme) surface is to folding, stage by stage.

The reference scheme moves the wear-face vertices and keeps the connectivity, so every
stage's surface (<run>/surface/stage_NNNN.h5) has the vertices of stage 0. For each stage this
prints the deepest vertex recession since stage 0 and its ratio to the longest edge at that
vertex on the unworn surface (a node-moving step cannot exceed the edges around it without
folding), the largest turn of a face normal against its unworn direction (an inverted face is
above 90 degrees) and the smallest triangle quality 2 r_in / r_circ (1 equilateral, 0 flat).

usage: surface_distortion.py <run directory> [...]
"""
import glob
import os
import sys

import h5py
import numpy as np


def read_stage(path):
    with h5py.File(path, "r") as f:
        return f["points"][...], f["triangles"][...]


def normals_and_quality(x, t):
    a, b, c = x[t[:, 0]], x[t[:, 1]], x[t[:, 2]]
    n = np.cross(b - a, c - a)
    area2 = np.linalg.norm(n, axis=1)
    la = np.linalg.norm(b - c, axis=1)
    lb = np.linalg.norm(c - a, axis=1)
    lc = np.linalg.norm(a - b, axis=1)
    # 2 r_in / r_circ = 8 area^2 / (la lb lc (la + lb + lc)), written with area2 = 2 area
    quality = 2.0 * area2**2 / (la * lb * lc * (la + lb + lc))
    return n / area2[:, None], quality


def longest_edge_at_vertex(x, t):
    longest = np.zeros(len(x))
    for i, j in ((0, 1), (1, 2), (2, 0)):
        length = np.linalg.norm(x[t[:, i]] - x[t[:, j]], axis=1)
        np.maximum.at(longest, t[:, i], length)
        np.maximum.at(longest, t[:, j], length)
    return longest


def report(run):
    files = sorted(glob.glob(os.path.join(run, "surface", "stage_*.h5")))
    if len(files) < 2:
        sys.exit(f"surface_distortion.py: {run}/surface holds fewer than two stage_*.h5 files")
    x0, t0 = read_stage(files[0])
    n0, q0 = normals_and_quality(x0, t0)
    edge0 = longest_edge_at_vertex(x0, t0)
    print(f"{run}: {len(t0)} faces, unworn smallest quality {q0.min():.3f}")
    print("stage  deepest[mm]  /longest edge  max normal turn[deg]  at x, y [mm]    min quality")
    for path in files[1:]:
        x, t = read_stage(path)
        if len(x) != len(x0) or not np.array_equal(t, t0):
            print(f"{os.path.basename(path)}: other connectivity (remeshed); not a node-moving run")
            return
        d = np.linalg.norm(x - x0, axis=1)
        deepest = int(np.argmax(d))
        n, q = normals_and_quality(x, t)
        turn = np.degrees(np.arccos(np.clip(np.einsum("ij,ij->i", n, n0), -1.0, 1.0)))
        worst = int(np.argmax(turn))
        centre = 1e3 * x[t[worst]].mean(axis=0)
        stage = int(os.path.basename(path)[6:10])
        print(f"{stage:5d}  {1e3 * d[deepest]:11.3f}  {d[deepest] / edge0[deepest]:13.2f}"
              f"  {turn[worst]:20.1f}  {centre[0]:6.1f} {centre[1]:6.1f}  {q.min():11.3f}")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for run in sys.argv[1:]:
        report(run)
