#pragma once
// The plate scene of the scene wear-loop tests: a plate read from STEP slides under a bed of
// 150 particles held by a fixed frame (one wearing part), and the same with the frame's north
// side a second wearing part.
#include "coupling/parameters/case_parameters.h"
#include "meshes/gmsh_session.h"

#include <gmsh.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using wear::coupling::CaseParameters;

// A 120 x 60 x 10 mm plate written by OpenCASCADE as STEP in millimetres: its surfaces are
// numbered x = 0 (1), x = 120 (2), y = 0 (3), y = 60 (4), z = 0 (5), z = 10 (6).
void write_plate(const std::string& path) {
  wear::meshes::GmshSession session("plate");
  gmsh::model::occ::addBox(0, 0, 0, 120, 60, 10);
  gmsh::model::occ::synchronize();
  gmsh::write(path);
}

// One side of the frame: a vertical plane from (x0, y0) to (x1, y1), 0.5 mm above the plate
// (a 4 mm particle cannot pass under it) up to 60 mm.
std::string frame_side(const std::string& name, double x0, double y0, double x1, double y1) {
  std::ostringstream s;
  s << "  subsection Wall " << name << "\n    set Source = plane\n    set Origin = " << x0 << ", "
    << y0 << ", 0.0105\n    set Edge u = " << x1 - x0 << ", " << y1 - y0
    << ", 0\n    set Edge v = 0, 0, 0.05\n    set Mesh size = 0.01\n  end\n";
  return s.str();
}

std::string plate_case(const std::string& dir, const std::string& plate_extra = "",
                       const std::string& schedule = "1 dem-only, 1 staged") {
  return "subsection Scene\n"
         "  set Walls = plate, west, east, south, north\n"
         "  set Domain minimum = -0.1, -0.1, -0.1\n"
         "  set Domain maximum = 0.3, 0.2, 0.2\n"
         "  set Stage duration = 0.1\n"
         "  set Output interval = 0.05\n"
         "  subsection Wall plate\n"
         "    set File = wear_plate.step\n"
         "    set Unit = mm\n"
         "    set Mesh size = 0.004\n"
         "    set Material = sample\n"
         "    set Wears = true\n"
         "    set Wearing surfaces = 6\n"
         "    set Clamped surfaces = 5\n"
         "    set Motion = translation\n"
         "    set Velocity = 0.1, 0, 0\n"
         "    set Start time = 0.1\n" +
         plate_extra + "  end\n" + frame_side("west", 0.005, 0.005, 0.005, 0.055) +
         frame_side("east", 0.055, 0.005, 0.055, 0.055) +
         frame_side("south", 0.005, 0.005, 0.055, 0.005) +
         frame_side("north", 0.005, 0.055, 0.055, 0.055) +
         "  subsection Fields\n"
         "    set Cells = 2, 2, 3\n"
         "    set Minimum = 0.005, 0.005, 0.0105\n"
         "    set Maximum = 0.055, 0.055, 0.0605\n"
         "  end\n"
         "  subsection Fill\n"
         "    set Region = box\n"
         "    set Minimum = 0.008, 0.008, 0.013\n"
         "    set Maximum = 0.052, 0.052, 0.058\n"
         "    set Count = 150\n"
         "  end\n"
         "end\n"
         "subsection DEM\n"
         "  set PSD diameters = 0.004\n"
         "  set PSD mass fractions = 1\n"
         "  set Scaling factor = 1\n"
         "  set Particle shear modulus = 1e7\n"
         "  set Threads = 2\n"
         "end\n"
         "subsection Wear law\n"
         "  set Archard coefficient = 1e-7\n"
         "end\n"
         "subsection Coupling\n"
         "  set Schedule = " +
         schedule +
         "\n"
         "  set Amplification = 100\n"
         "end\n"
         "subsection Output\n"
         "  set Directory = " +
         dir + "\nend\n";
}

std::string plate_case(const std::string& dir, const std::string& plate_extra,
                       const std::string& schedule, const std::string& output_extra) {
  std::string text = plate_case(dir, plate_extra, schedule);
  const auto at = text.rfind("end\n");
  return text.substr(0, at) + output_extra + "end\n";
}

// The plate case with a second wearing part: the frame's north side a 50 x 6 x 50 mm steel
// box that wears on the face towards the bed (surface 3, y = 55 mm) and is bolted at its back
// (surface 4, clamped).
std::string two_part_case(const std::string& text) {
  const std::string north = frame_side("north", 0.005, 0.055, 0.055, 0.055);
  const auto at = text.find(north);
  return text.substr(0, at) +
         "  subsection Wall north\n"
         "    set Source = box\n"
         "    set Origin = 0.005, 0.055, 0.0105\n"
         "    set Axis = 0.05, 0.006, 0.05\n"
         "    set Mesh size = 0.004\n"
         "    set Material = sample\n"
         "    set Wears = true\n"
         "    set Wearing surfaces = 3\n"
         "    set Clamped surfaces = 4\n"
         "  end\n" +
         text.substr(at + north.size());
}

// The plate case for the node-moving (reference) scheme: the plate at rest under the bed, its
// surface moving as a belt's at 0.1 m/s so that the bed slides on it, its nodes moved every 50
// engine steps.
std::string reference_plate_case(const std::string& dir, const std::string& schedule) {
  std::string text = plate_case(dir, "", schedule);
  text.replace(text.find("    set Motion = translation\n"), 29,
               "    set Motion = surface translation\n");
  text.erase(text.find("    set Start time = 0.1\n"), 25);
  text.insert(text.find("subsection DEM\n"),
              "subsection Deformation\n  set Update interval = 50\nend\n");
  return text;
}

CaseParameters read_text(const std::string& name, const std::string& text) {
  std::ofstream(name) << text;
  std::ostringstream warnings;
  return wear::coupling::read_case(name, warnings);
}

// Column `name` of scene_series.csv in the rows after time `after` [s].
std::vector<double> series_after(const std::string& path, const std::string& name, double after) {
  std::ifstream in(path);
  std::string line, cell;
  std::getline(in, line);
  std::stringstream header(line);
  std::size_t column = 0;
  for (std::size_t k = 0; std::getline(header, cell, ','); ++k)
    if (cell == name)
      column = k;
  std::vector<double> values;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::vector<double> cells;
    while (std::getline(row, cell, ','))
      cells.push_back(std::stod(cell));
    if (cells.at(0) > after + 1e-9)
      values.push_back(cells.at(column));
  }
  return values;
}

// The mean of column `name` of scene_series.csv over the windows after time `after` [s],
// each weighted by its length (the time since the row before).
double window_weighted(const std::string& path, const std::string& name, double after) {
  const auto values = series_after(path, name, after);
  const auto times = series_after(path, "time_s", after);
  double sum = 0, before = after;
  for (std::size_t k = 0; k < values.size(); ++k) {
    sum += values[k] * (times[k] - before);
    before = times[k];
  }
  return sum / (before - after);
}

} // namespace
