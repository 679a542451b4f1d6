#!/usr/bin/env python3
"""Writes the floor plates of the rim study (cases/hopper-rim): a square plate 0.24 m wide at
z = 0 with a central orifice whose rim is a regular n-gon with its vertices on the circle of
diameter D, as ASCII STL in metres, one label.

    /usr/bin/python3 cases/hopper-rim/make_plates.py [folder]

writes ring-<n>-<D in mm>.stl for n = 32, 128 and D = 36, 48 mm (6 and 8 diameters of the
6 mm particles), by default beside this script, where the study's case files read them, and
plate-128-48.stl, the plate of cases/bin-vs-liggghts (the 128-gon rim joined to the border by
rays from the centre through its vertices, two triangles per rim edge).

The two ring plates of one D are the same triangles outside a ring round the orifice: a 128-gon
of radius D/2 + RING (its vertices on that circle) joined by rays from the centre to the
square's border, each pair of rays making a quadrilateral of two triangles; the rays at
multiples of 45 degrees end in the square's corners, so the border is the square exactly.
Only the ring between the rim and that 128-gon differs: for the 128-gon rim a quadrilateral
per rim edge, for the 32-gon a fan from each rim edge to the four outer edges it faces. The
plug of the study's case (base.prm) covers the ring while the bed settles, so the bed of a
seed touches the same triangles with either rim until the plug drops.
"""
import math
import os
import sys

HALF = 0.12  # [m] half the plate's width: past the bin's radius of 0.1 m
RING = 0.006  # [m] width of the ring round the orifice where the two rims' plates differ
N_OUTER = 128  # vertices of the ring's outer polygon, the same for every rim


def border_point(angle):
    """Where the ray from the centre at `angle` leaves the square |x|, |y| <= HALF."""
    c, s = math.cos(angle), math.sin(angle)
    t = HALF / max(abs(c), abs(s))
    return (t * c, t * s)


def polygon(n, r):
    return [(r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n))
            for k in range(n)]


def ray_plate(n, diameter):
    """The rim's vertices joined to the border by rays from the centre."""
    r = diameter / 2
    triangles = []
    for k in range(n):
        a0, a1 = 2 * math.pi * k / n, 2 * math.pi * (k + 1) / n
        v0 = (r * math.cos(a0), r * math.sin(a0))
        v1 = (r * math.cos(a1), r * math.sin(a1))
        triangles.append((v0, border_point(a0), border_point(a1)))
        triangles.append((v0, border_point(a1), v1))
    return triangles


def ring_plate(n, diameter):
    """Triangles of the ring plate (counter-clockwise seen from above: normals +z)."""
    if N_OUTER % n != 0:
        raise ValueError("the rim's vertex count must divide %d" % N_OUTER)
    rim = polygon(n, diameter / 2)
    outer = polygon(N_OUTER, diameter / 2 + RING)
    triangles = []
    for k in range(N_OUTER):  # outside the ring: the same for every rim
        a0, a1 = 2 * math.pi * k / N_OUTER, 2 * math.pi * (k + 1) / N_OUTER
        u0, u1 = outer[k], outer[(k + 1) % N_OUTER]
        s0, s1 = border_point(a0), border_point(a1)
        triangles.append((u0, s0, s1))
        triangles.append((u0, s1, u1))
    m = N_OUTER // n  # outer edges per rim edge
    for j in range(n):  # the ring: rim edge j faces outer edges m j .. m j + m - 1
        v0, v1 = rim[j], rim[(j + 1) % n]
        u = [outer[(m * j + i) % N_OUTER] for i in range(m + 1)]
        half = m // 2 if m > 1 else 1
        for i in range(half):  # the first half of the outer edges fan from v0
            triangles.append((v0, u[i], u[i + 1]))
        triangles.append((v0, u[half], v1))
        for i in range(half, m):  # the rest from v1
            triangles.append((v1, u[i], u[i + 1]))
    return triangles


def write_stl(path, triangles, name):
    with open(path + ".tmp", "w") as out:
        out.write("solid %s\n" % name)
        for tri in triangles:
            out.write("  facet normal 0 0 1\n    outer loop\n")
            for x, y in tri:
                out.write("      vertex %.17g %.17g 0\n" % (x, y))
            out.write("    endloop\n  endfacet\n")
        out.write("endsolid %s\n" % name)
    os.replace(path + ".tmp", path)


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    os.makedirs(folder, exist_ok=True)
    plates = [("ring-%d-%d" % (n, d_mm), ring_plate(n, d_mm / 1000))
              for n in (32, 128) for d_mm in (36, 48)]
    plates.append(("plate-128-48", ray_plate(128, 0.048)))
    for name, triangles in plates:
        write_stl(os.path.join(folder, name + ".stl"), triangles, name)
        print("wrote", os.path.join(folder, name + ".stl"))


if __name__ == "__main__":
    main()
