// The impact liner of cases/chute: a polyethylene plate 250 mm down the slope, 150 mm wide,
// 20 mm thick, its wearing face through the origin, inclined 35 degrees (down towards +x).
// Units: mm. Made into liner.step with gmsh's OpenCASCADE kernel:
//   gmsh liner.geo -0 -format step -o liner.step     (Debian package gmsh)
SetFactory("OpenCASCADE");
Box(1) = {0, -75, -20, 250, 150, 20};
Rotate {{0, 1, 0}, {0, 0, 0}, 35 * Pi / 180} { Volume{1}; }
