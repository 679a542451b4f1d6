#!/usr/bin/env python3
"""Plots of the chute case (cases/chute): where and how deep the impact liner wears.

    /usr/bin/python3 cases/chute/plot_chute.py [output/chute]

Writes into <run>/plots/: liner_wear_map.png (the cumulative wear depth on the liner's wearing
face after the last stage, in the face's own coordinates: s down the slope from the upper
edge, y across; the worn depth measured from the unworn face), liner_profiles.png (the worn
face along the centreline y = 0 after every staged stage), liner_wear.png (the removed volume
per stage and cumulative, and the largest ball-averaged von Mises stress per stage),
stream_fields.png (the binned solid fraction and velocity of Scene/Fields in the chute's
centre plane, averaged over the last stage's records), and for a law with an impact part
(chute-impact.prm) liner_mechanisms.png (the depth per window worn by sliding and by impact
over the liner face, and each mechanism's volume along the slope).
Needs python3-matplotlib, python3-numpy and python3-h5py (Debian packages).
"""
import csv
import glob
import math
import os
import re
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402

INCLINE = math.radians(35)  # liner.geo: the plate turned about y, down towards +x
WEARING_LABEL = 1006  # S6, the liner's top face (meshes::label::part_surface)


def face_coordinates(points):
    """(s, y, n): s down the slope from the upper edge, y across, n along the unworn face's
    outward normal (0 on the unworn face, negative where it wore) [mm]."""
    down = np.array([math.cos(INCLINE), 0.0, -math.sin(INCLINE)])
    normal = np.array([math.sin(INCLINE), 0.0, math.cos(INCLINE)])
    p = points * 1e3
    return p @ down, p[:, 1], p @ normal


def read_stage(path):
    with h5py.File(path, "r") as h5:
        points = h5["points"][:]
        triangles = h5["triangles"][:]
        labels = h5["cell/label"][:, 0]
        depth = h5["cell/wear_depth"][:, 0] if "cell/wear_depth" in h5 else None
    top = labels == WEARING_LABEL
    return points, triangles[top], depth[top] if depth is not None else None


def main():
    run = sys.argv[1] if len(sys.argv) > 1 else "output/chute"
    liner = os.path.join(run, "parts", "liner")
    stages = sorted(glob.glob(os.path.join(liner, "surface", "stage_*.h5")))
    if len(stages) < 2:
        sys.exit(f"plot_chute: no stage surfaces under '{liner}/surface' (run the case first)")
    out = os.path.join(run, "plots")
    os.makedirs(out, exist_ok=True)

    points, tris, depth = read_stage(stages[-1])
    s, y, _ = face_coordinates(points)
    fig, ax = plt.subplots(figsize=(8, 5))
    t = mtri.Triangulation(s, y, tris)
    pc = ax.tripcolor(t, facecolors=depth * 1e3, cmap="inferno_r", edgecolors="none")
    fig.colorbar(pc, ax=ax, label="cumulative wear depth [mm]")
    ax.set_xlabel("s, down the slope from the upper edge [mm]")
    ax.set_ylabel("y, across [mm]")
    ax.set_aspect("equal")
    ax.set_title(f"liner wear after stage {len(stages) - 1}: largest {depth.max() * 1e3:.2f} mm")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "liner_wear_map.png"), dpi=150)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(8, 4))
    cmap = plt.get_cmap("viridis")
    for k, path in enumerate(stages):
        pts, tr, _ = read_stage(path)
        s, y, n = face_coordinates(pts)
        used = np.unique(tr)
        near = used[np.abs(y[used]) < 3.0]
        order = near[np.argsort(s[near])]
        ax.plot(s[order], n[order], color=cmap(k / max(1, len(stages) - 1)), lw=1,
                label=f"stage {k}" if k in (0, len(stages) - 1) else None)
    ax.set_xlabel("s, down the slope [mm]")
    ax.set_ylabel("face height over the unworn face [mm]")
    ax.set_title("worn profile along the centreline (|y| < 3 mm), every stage")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "liner_profiles.png"), dpi=150)
    plt.close(fig)

    with open(os.path.join(liner, "stages.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    stage = [int(r["stage"]) for r in rows]
    applied = [float(r["applied_volume_m3"]) * 1e9 for r in rows]
    cumulative = [float(r["cumulative_applied_m3"]) * 1e9 for r in rows]
    stress = [float(r["max_von_mises_ball_Pa"]) * 1e-3 for r in rows]
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4))
    a1.bar(stage, applied, color="tab:orange", label="per stage")
    a1.plot(stage, cumulative, "o-", color="tab:blue", label="cumulative")
    a1.set_xlabel("stage")
    a1.set_ylabel("removed volume [mm^3]")
    a1.legend()
    a2.plot(stage, stress, "s-")
    a2.set_xlabel("stage")
    a2.set_ylabel("largest ball-averaged von Mises [kPa]")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "liner_wear.png"), dpi=150)
    plt.close(fig)
    written = "liner_wear_map.png, liner_profiles.png, liner_wear.png"
    if plot_fields(run, out):
        written += ", stream_fields.png"
    if plot_mechanisms(liner, out):
        written += ", liner_mechanisms.png"
    print(f"written to {out}/ ({written})")


def read_vtu_cells(path):
    """Points, triangles and the cell arrays (by name) of an ASCII VTU of meshes::write_vtu."""
    with open(path) as f:
        text = f.read()
    arrays = {}
    for m in re.finditer(r"<DataArray([^>]*)>([^<]*)</DataArray>", text):
        name = re.search(r'Name="([^"]*)"', m.group(1))
        arrays[name.group(1) if name else "points"] = np.array(m.group(2).split(), dtype=float)
    return (arrays["points"].reshape(-1, 3), arrays["connectivity"].astype(int).reshape(-1, 3),
            arrays)


def plot_mechanisms(liner, out):
    """Where the liner wears by sliding and where by impact: the wear-law volume of the staged
    windows (parts/liner/loads/stage_<k>.vtu, each on the surface its loads fell on, not
    amplified) split into its impact part and the rest, summed over the stages on the last
    stage's faces (the mesh moves, it is not remeshed) and divided by the face areas: the
    depth each mechanism removes per 2 s window."""
    files = sorted(glob.glob(os.path.join(liner, "loads", "stage_*.vtu")))[1:]  # staged only
    if not files:
        return False
    total = impact = None
    for path in files:
        points, tris, a = read_vtu_cells(path)
        v, i = a["wear-law volume [m^3]"], a["impact wear-law volume [m^3]"]
        if total is not None and len(v) != len(total):
            total = impact = None  # a remesh: the stages after it only
        total = v if total is None else total + v
        impact = i if impact is None else impact + i
    top = a["label"] == WEARING_LABEL
    if not impact[top].any():
        return False
    e1, e2 = points[tris[:, 1]] - points[tris[:, 0]], points[tris[:, 2]] - points[tris[:, 0]]
    area = 0.5 * np.linalg.norm(np.cross(e1, e2), axis=1)
    n = len(files)
    sliding_depth = (total - impact)[top] / area[top] / n * 1e6  # [um] per window
    impact_depth = impact[top] / area[top] / n * 1e6
    s, y, _ = face_coordinates(points)
    t = mtri.Triangulation(s, y, tris[top])
    fig, axes = plt.subplots(3, 1, figsize=(8, 11))
    top_value = max(sliding_depth.max(), impact_depth.max())
    for ax, depth, what in ((axes[0], sliding_depth, "sliding"), (axes[1], impact_depth, "impact")):
        pc = ax.tripcolor(t, facecolors=depth, cmap="inferno_r", vmin=0, vmax=top_value,
                          edgecolors="none")
        fig.colorbar(pc, ax=ax, label="depth per window [um]")
        ax.set_aspect("equal")
        ax.set_ylabel("y, across [mm]")
        ax.set_title(f"{what}: {depth.dot(area[top]) / area[top].sum():.3g} um mean, "
                     f"{depth.max():.3g} um largest (mean of {n} windows of 2 s)")
    # Along the slope: each mechanism's volume in 10 mm bands of s.
    centroid_s = s[tris[top]].mean(axis=1)
    bands = np.arange(0, 260, 10.0)
    k = np.digitize(centroid_s, bands)
    vs = [((total - impact)[top][k == b]).sum() / n * 1e9 for b in range(1, len(bands))]
    vi = [(impact[top][k == b]).sum() / n * 1e9 for b in range(1, len(bands))]
    mid = 0.5 * (bands[1:] + bands[:-1])
    axes[2].bar(mid, vs, width=9, color="tab:blue", label="sliding")
    axes[2].bar(mid, vi, width=9, bottom=vs, color="tab:red", label="impact")
    axes[2].set_xlabel("s, down the slope from the upper edge [mm]")
    axes[2].set_ylabel("volume per window [mm^3] in 10 mm of s")
    axes[2].legend()
    for ax in axes[:2]:
        ax.set_xlabel("s, down the slope from the upper edge [mm]")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "liner_mechanisms.png"), dpi=150)
    plt.close(fig)
    return True


def plot_fields(run, out):
    """The stream in the chute's centre plane: solid fraction and mass-weighted velocity of
    the binned fields (Scene/Fields), averaged over the records of the last stage."""
    files = sorted(glob.glob(os.path.join(run, "fields", "record_*.h5")))
    if not files:
        return False
    with open(os.path.join(run, "parts", "liner", "stages.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    begin = float(rows[-2]["time_s"]) if len(rows) > 1 else 0.0  # the last stage's start
    phi, vel, last = 0, 0, []
    for path in files:
        with h5py.File(path, "r") as h5:
            if h5.attrs["time"] > begin + 1e-6:  # stages.csv rounds to 10 digits
                last.append((h5["solid_fraction"][:], h5["velocity"][:]))
            lo = [h5.attrs[a + "_minimum"] for a in "xyz"]
            hi = [h5.attrs[a + "_maximum"] for a in "xyz"]
    for p, v in last:
        phi = phi + p / len(last)
        vel = vel + v / len(last)
    nz, ny, nx = phi.shape
    mid = [ny // 2 - 1, ny // 2] if ny % 2 == 0 else [ny // 2]
    phi_xz = phi[:, mid, :].mean(axis=1)
    v_xz = vel[:, mid, :, :].mean(axis=1)
    u, w = v_xz[..., 0], v_xz[..., 2]
    x = lo[0] + (np.arange(nx) + 0.5) * (hi[0] - lo[0]) / nx
    z = lo[2] + (np.arange(nz) + 0.5) * (hi[2] - lo[2]) / nz
    fig, ax = plt.subplots(figsize=(7, 6))
    im = ax.imshow(phi_xz, origin="lower", extent=[lo[0] * 1e3, hi[0] * 1e3, lo[2] * 1e3,
                   hi[2] * 1e3], cmap="Greys", vmin=0)
    fig.colorbar(im, ax=ax, label="solid fraction [-]")
    X, Z = np.meshgrid(x * 1e3, z * 1e3)
    occupied = phi_xz > 0.005
    ax.quiver(X[occupied], Z[occupied], u[occupied], w[occupied], color="tab:red")
    s = np.array([0.0, 250.0])
    ax.plot(s * math.cos(INCLINE), -s * math.sin(INCLINE), "b-", lw=2, label="liner face")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("z [mm]")
    ax.set_title(f"centre plane, mean of the last {len(last)} records")
    ax.legend(loc="upper right")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "stream_fields.png"), dpi=150)
    plt.close(fig)
    return True


if __name__ == "__main__":
    main()
