// The Scene subsection's own checks (scene_parameters.h): names, list lengths, signs.
#include "dem/scene/scene_parameters.h"

#include <cctype>
#include <set>
#include <sstream>
#include <stdexcept>

namespace wear::dem {

std::string scene_wall_path(const SceneWallParameters& w) {
  return "Scene/Wall " + w.name;
}

meshes::Vec3 scene_vector(const std::vector<double>& v) {
  return {v.at(0), v.at(1), v.at(2)};
}

std::vector<std::string> scene_wall_names(const std::string& text_list) {
  std::vector<std::string> names;
  std::set<std::string> seen;
  std::string item;
  std::stringstream in(text_list);
  bool any = false;
  while (std::getline(in, item, ',')) {
    any = true;
    const auto b = item.find_first_not_of(" \t"), e = item.find_last_not_of(" \t");
    const std::string name = b == std::string::npos ? "" : item.substr(b, e - b + 1);
    if (name.empty())
      throw std::invalid_argument("Scene/Walls: '" + text_list + "' has an empty name");
    for (const char c : name)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-')
        throw std::invalid_argument("Scene/Walls: the name '" + name +
                                    "' may hold letters, digits, '_' and '-' only");
    if (!seen.insert(name).second)
      throw std::invalid_argument("Scene/Walls: the name '" + name + "' is listed twice");
    names.push_back(name);
  }
  if (!any && text_list.find_first_not_of(" \t") != std::string::npos)
    throw std::invalid_argument("Scene/Walls: cannot read '" + text_list + "'");
  return names;
}

void validate(const SceneParameters& s) {
  const auto three = [](const std::vector<double>& v, const std::string& what) {
    if (v.size() != 3)
      throw std::invalid_argument(what + ": needs 3 values (x, y, z), got " +
                                  std::to_string(v.size()));
  };
  three(s.domain_min, "Scene/Domain minimum");
  three(s.domain_max, "Scene/Domain maximum");
  for (int d = 0; d < 3; ++d)
    if (!(s.domain_min[d] < s.domain_max[d]))
      throw std::invalid_argument("Scene/Domain minimum must lie below Scene/Domain maximum in "
                                  "every direction");
  for (const auto& w : s.walls) {
    const std::string p = scene_wall_path(w);
    for (const auto& [v, name] : {std::pair{&w.origin, "Origin"},
                                  {&w.edge_u, "Edge u"},
                                  {&w.edge_v, "Edge v"},
                                  {&w.axis, "Axis"},
                                  {&w.axis_point, "Axis point"},
                                  {&w.rotation_axis, "Rotation axis"},
                                  {&w.velocity, "Velocity"},
                                  {&w.amplitude, "Amplitude"}})
      three(*v, p + "/" + name);
    if (w.source == "file" && w.file.empty())
      throw std::invalid_argument(p + "/File: a file is needed with Source = file");
    if (!(w.mesh_size > 0))
      throw std::invalid_argument(p + "/Mesh size must be positive [m], got " +
                                  std::to_string(w.mesh_size));
    if (w.motion == "rotation" && meshes::norm(scene_vector(w.rotation_axis)) == 0)
      throw std::invalid_argument(p + "/Rotation axis must not be zero");
    if (w.motion == "oscillation" && !(w.frequency > 0))
      throw std::invalid_argument(p + "/Frequency must be positive [Hz] for an oscillation");
  }
}

} // namespace wear::dem
