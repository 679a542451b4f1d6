#!/usr/bin/python3
"""Renders a labelled sample surface (binary STL written by `wearsim mesh`, label id in each
facet's attribute field) to a PNG, coloured by region.

usage: /usr/bin/python3 docs/plot_sample.py output/reference-convex/sample.stl docs/images/convex_sample.png
"""
import struct
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection


def read_stl(path):
    with open(path, "rb") as f:
        data = f.read()
    n = struct.unpack_from("<I", data, 80)[0]
    rec = np.frombuffer(data, dtype=np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")]),
                        count=n, offset=84)
    return rec["v"].astype(float), rec["a"].astype(int)


def main():
    tris, labels = read_stl(sys.argv[1])
    keep = labels != 1  # hide the clamped bottom
    tris, labels = tris[keep] * 1e3, labels[keep]
    normals = np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    light = np.array([-0.4, -0.5, 0.77])
    shade = 0.45 + 0.55 * np.clip(normals @ light, 0, 1)
    cmap = plt.get_cmap("tab20")
    base = np.array([0.78, 0.80, 0.84])
    colours = np.array([base if l in (2, 3) else np.array(cmap((l // 10 * 3 + l % 10) % 20)[:3])
                        for l in labels])
    fig = plt.figure(figsize=(8, 6), dpi=120)
    ax = fig.add_subplot(projection="3d")
    ax.add_collection3d(Poly3DCollection(tris, facecolors=colours * shade[:, None], linewidths=0))
    ax.set_xlim(-60, 60); ax.set_ylim(-60, 60); ax.set_zlim(-20, 40)
    ax.set_box_aspect((1, 1, 0.5))
    ax.set_xlabel("x radial [mm]"); ax.set_ylabel("y flow [mm]"); ax.set_zlabel("z [mm]")
    ax.view_init(elev=35, azim=-60)
    ax.set_title("Reference convex sample: 23 half-ellipsoid elements C11..C55, flow along +y")
    fig.tight_layout()
    fig.savefig(sys.argv[2])


if __name__ == "__main__":
    main()
