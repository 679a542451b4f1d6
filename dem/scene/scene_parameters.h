#pragma once
// The user's own equipment as walls (issue 33): the Scene subsection of a case file. Each
// wall named in `Scene/Walls` has a subsection `Wall <name>`: where its surface comes from (a
// CAD or mesh file with its length unit, or a primitive), its material, whether it wears and
// how it moves. scene_walls.h builds and checks the surfaces (`wearsim scene`); the scene's
// particles, sources and sinks and its DEM run are the next parts of the issue.
#include "meshes/parameter_visitor.h"
#include "meshes/vec3.h"

#include <string>
#include <vector>

namespace wear::dem {

struct SceneWallParameters {
  std::string name;                    ///< from Scene/Walls
  std::string source = "file";         ///< file | plane | disc | cylinder | cone | box
  std::string file;                    ///< STEP, IGES, BREP or STL (source = file)
  std::string unit = "m";              ///< m | mm, the file's length unit
  double mesh_size = 5e-3;             ///< [m] triangle size for CAD files and primitives
  std::vector<double> origin{0, 0, 0}; ///< [m] plane corner, disc centre, base centre, box corner
  std::vector<double> edge_u{1, 0, 0}; ///< [m] plane: first edge
  std::vector<double> edge_v{0, 1, 0}; ///< [m] plane: second edge
  std::vector<double> axis{0, 0, 1};   ///< [m] disc normal; cylinder/cone axis; box size
  double radius = 0;                   ///< [m] disc, cylinder; cone base
  double radius_top = 0;               ///< [m] cone top
  bool caps = false;                   ///< cylinder, cone: with end discs
  std::string material = "wall";       ///< wall | sample | holder (the DEM subsection's)
  bool wears = false;                  ///< its faces accumulate wear (a closed solid)
  std::string motion = "fixed";        ///< fixed | rotation | translation | oscillation
  std::vector<double> axis_point{0, 0, 0};    ///< [m] rotation
  std::vector<double> rotation_axis{0, 0, 1}; ///< [-] rotation, right-handed
  double angular_velocity = 0;                ///< [rad/s] rotation
  std::vector<double> velocity{0, 0, 0};      ///< [m/s] translation
  std::vector<double> amplitude{0, 0, 0};     ///< [m] oscillation: A sin(2 pi f t)
  double frequency = 0;                       ///< [Hz] oscillation
};

struct SceneParameters {
  std::string wall_names;                        ///< "Walls": comma-separated names, "" for none
  std::vector<SceneWallParameters> walls;        ///< one per name, in that order
  std::vector<double> domain_min{-10, -10, -10}; ///< [m] particles and walls stay inside
  std::vector<double> domain_max{10, 10, 10};    ///< [m]
};

/// The names listed in `text` ("a, b, c"); throws std::invalid_argument naming Scene/Walls
/// for an empty or repeated name or one with characters other than letters, digits, '_' and
/// '-'.
std::vector<std::string> scene_wall_names(const std::string& text);

/// The Scene subsection. `s.walls` must already hold one entry per name of the file (the
/// case reader reads Scene/Walls first), so each wall's subsection is declared and read.
template <typename Visitor>
void visit_parameters(SceneParameters& s, Visitor& v) {
  v.enter("Scene");
  v.text("Walls", s.wall_names,
         "Names of the scene's walls, comma-separated; each has a subsection 'Wall <name>'. "
         "Empty: no scene (the built-in wear tester of the Geometry subsection).");
  v.real_list("Domain minimum", s.domain_min,
              "[m] x, y, z of the domain's lower corner: every wall vertex lies inside.");
  v.real_list("Domain maximum", s.domain_max, "[m] x, y, z of the domain's upper corner.");
  for (auto& w : s.walls) {
    v.enter("Wall " + w.name);
    v.selection("Source", w.source, "file|plane|disc|cylinder|cone|box",
                "Where the surface comes from: a file, or a primitive meshed at Mesh size.");
    v.text("File", w.file,
           "STEP (.step, .stp), IGES (.iges, .igs), BREP (.brep) or STL (.stl), relative to "
           "the working directory (Source = file). CAD surfaces become labels 1, 2, ... in the "
           "file's order (`wearsim scene` lists them); STL labels as stored.");
    v.selection("Unit", w.unit, "m|mm", "Length unit of the file's coordinates.");
    v.real("Mesh size", w.mesh_size, "[m] Triangle size for CAD files and primitives.");
    v.real_list("Origin", w.origin,
                "[m] Plane: a corner; disc: its centre; cylinder, cone: the base centre; box: "
                "the lower corner.");
    v.real_list("Edge u", w.edge_u, "[m] Plane: the first edge from the corner.");
    v.real_list("Edge v", w.edge_v, "[m] Plane: the second edge from the corner.");
    v.real_list("Axis", w.axis,
                "[m] Disc: the normal (any length); cylinder, cone: base to top; box: its size.");
    v.real("Radius", w.radius, "[m] Disc, cylinder; the cone's base.");
    v.real("Top radius", w.radius_top, "[m] The cone's top (0: pointed).");
    v.boolean("Caps", w.caps, "Cylinder, cone: with the end discs (a closed solid).");
    v.selection("Material", w.material, "wall|sample|holder",
                "The DEM material of the wall: one of the DEM subsection's Wall, Sample and "
                "Holder materials.");
    v.boolean("Wears", w.wears,
              "Its faces accumulate Archard load-distance and impulse; a wearing wall must be a "
              "closed solid (the FEM part).");
    v.selection("Motion", w.motion, "fixed|rotation|translation|oscillation",
                "fixed; rotation about Axis point and Rotation axis at Angular velocity; "
                "translation at Velocity; oscillation A sin(2 pi f t) of Amplitude and "
                "Frequency.");
    v.real_list("Axis point", w.axis_point, "[m] A point of the rotation axis.");
    v.real_list("Rotation axis", w.rotation_axis, "[-] Direction of the rotation axis.");
    v.real("Angular velocity", w.angular_velocity, "[rad/s] Right-handed about Rotation axis.");
    v.real_list("Velocity", w.velocity, "[m/s] Translation velocity.");
    v.real_list("Amplitude", w.amplitude, "[m] Oscillation amplitude vector.");
    v.real("Frequency", w.frequency, "[Hz] Oscillation frequency.");
    v.leave();
  }
  v.leave();
}

/// "Scene/Wall <name>": how messages name a wall's parameters.
std::string scene_wall_path(const SceneWallParameters& w);
/// The three values of a checked list (x, y, z) as a vector.
meshes::Vec3 scene_vector(const std::vector<double>& v);

/// Checks the values on their own (list lengths, signs, a file given where needed); throws
/// std::invalid_argument naming the parameter by its case-file path.
void validate(const SceneParameters& s);

} // namespace wear::dem
