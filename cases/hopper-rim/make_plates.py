#!/usr/bin/env python3
"""Writes the floor plates of the rim study (cases/hopper-rim): a square plate 0.24 m wide at
z = 0 with a central orifice whose rim is a regular n-gon with its vertices on the circle of
diameter D, as ASCII STL in metres, one label.

    /usr/bin/python3 cases/hopper-rim/make_plates.py [folder]

writes plate-<n>-<D in mm>.stl for n = 32, 128 and D = 36, 48 mm (6 and 8 diameters of the
6 mm particles), by default beside this script, where the study's case files read them. The plate is triangulated by rays from the centre through the rim's
vertices to the square's border: each rim edge (v_k, v_k+1) and the border points s_k, s_k+1
on the same rays make a quadrilateral of two triangles. The rays at multiples of 45 degrees
(n divisible by 8) end in the square's corners, so the border is the square exactly. Only
the rim differs between two plates of the same D; the triangles away from it are long and
thin, which changes nothing for a flat wall (a sphere on a face sees the plane).
"""
import math
import os
import sys

HALF = 0.12  # [m] half the plate's width: past the bin's radius of 0.1 m


def border_point(angle):
    """Where the ray from the centre at `angle` leaves the square |x|, |y| <= HALF."""
    c, s = math.cos(angle), math.sin(angle)
    t = HALF / max(abs(c), abs(s))
    return (t * c, t * s)


def plate(n, diameter):
    r = diameter / 2
    triangles = []
    for k in range(n):
        a0, a1 = 2 * math.pi * k / n, 2 * math.pi * (k + 1) / n
        v0 = (r * math.cos(a0), r * math.sin(a0))
        v1 = (r * math.cos(a1), r * math.sin(a1))
        s0, s1 = border_point(a0), border_point(a1)
        # counter-clockwise seen from above: normals +z
        triangles.append((v0, s0, s1))
        triangles.append((v0, s1, v1))
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
    for n in (32, 128):
        for d_mm in (36, 48):
            name = "plate-%d-%d" % (n, d_mm)
            write_stl(os.path.join(folder, name + ".stl"), plate(n, d_mm / 1000), name)
            print("wrote", os.path.join(folder, name + ".stl"))


if __name__ == "__main__":
    main()
