// STL reader and writer.
//
// Binary layout: 80-byte header, uint32 facet count, then per facet 12 float32 (normal and
// three vertices) and a uint16 attribute, little-endian. A file is binary when its size is
// exactly 84 + 50 n; otherwise it must parse as ASCII (`solid ... facet normal ... outer loop
// vertex x y z (x3) endloop endfacet ... endsolid`).
#include "meshes/stl_io.h"

#include "meshes/atomic_file.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace wear::meshes {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& msg) {
  throw std::runtime_error("STL file '" + path + "': " + msg);
}

SurfaceMesh read_binary(const std::string& path, const std::vector<char>& data) {
  std::uint32_t n = 0;
  std::memcpy(&n, data.data() + 80, 4);
  SurfaceMesh m;
  m.vertices.reserve(3 * n);
  m.triangles.reserve(n);
  m.face_labels.reserve(n);
  for (std::uint32_t f = 0; f < n; ++f) {
    const char* p = data.data() + 84 + 50 * std::size_t(f);
    float c[12];
    std::memcpy(c, p, sizeof(c));
    std::uint16_t attr = 0;
    std::memcpy(&attr, p + 48, 2);
    for (int k = 0; k < 3; ++k)
      m.vertices.push_back({c[3 + 3 * k], c[4 + 3 * k], c[5 + 3 * k]});
    m.triangles.push_back({3 * f, 3 * f + 1, 3 * f + 2});
    m.face_labels.push_back(attr == 0 ? label::wall : int(attr));
  }
  (void)path;
  return m;
}

SurfaceMesh read_ascii(const std::string& path, const std::string& text) {
  std::istringstream in(text);
  SurfaceMesh m;
  std::string line, word;
  int line_no = 0, current_label = label::wall, n_vertex_in_facet = -1;
  bool in_solid = false;
  while (std::getline(in, line)) {
    ++line_no;
    std::istringstream ls(line);
    if (!(ls >> word))
      continue;
    const std::string where = "line " + std::to_string(line_no) + ": ";
    if (word == "solid") {
      std::string name;
      ls >> name;
      current_label = label::wall;
      if (!name.empty()) {
        try {
          current_label = label::from_name(name);
        } catch (const std::invalid_argument&) {
        }
      }
      in_solid = true;
    } else if (word == "endsolid") {
      in_solid = false;
    } else if (word == "facet") {
      if (!in_solid || n_vertex_in_facet != -1)
        fail(path, where + "'facet' outside a solid or inside another facet");
      n_vertex_in_facet = 0;
    } else if (word == "vertex") {
      if (n_vertex_in_facet < 0 || n_vertex_in_facet >= 3)
        fail(path, where + "'vertex' outside a facet or more than three in one facet");
      Vec3 p;
      if (!(ls >> p.x >> p.y >> p.z))
        fail(path, where + "a vertex needs three numbers");
      m.vertices.push_back(p);
      ++n_vertex_in_facet;
    } else if (word == "endfacet") {
      if (n_vertex_in_facet != 3)
        fail(path, where + "facet with " + std::to_string(std::max(n_vertex_in_facet, 0)) +
                       " vertices, expected 3");
      const auto v = static_cast<std::uint32_t>(m.vertices.size());
      m.triangles.push_back({v - 3, v - 2, v - 1});
      m.face_labels.push_back(current_label);
      n_vertex_in_facet = -1;
    } else if (word != "outer" && word != "endloop") {
      fail(path, where + "unexpected word '" + word + "'");
    }
  }
  if (n_vertex_in_facet != -1)
    fail(path, "file ends inside a facet");
  if (m.triangles.empty())
    fail(path, "no facets found (neither valid ASCII nor binary STL)");
  return m;
}

} // namespace

SurfaceMesh read_stl(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    fail(path, "cannot be opened (missing file or no permission)");
  std::vector<char> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  SurfaceMesh m;
  bool binary = false;
  if (data.size() >= 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, data.data() + 80, 4);
    binary = data.size() == 84 + 50 * std::size_t(n);
  }
  if (binary)
    m = read_binary(path, data);
  else if (data.size() >= 5 && std::string(data.data(), 5) == "solid")
    m = read_ascii(path, std::string(data.begin(), data.end()));
  else
    fail(path, "neither ASCII (starts with 'solid') nor binary (size " +
                   std::to_string(data.size()) + " is not 84 + 50 n)");
  merge_identical_vertices(m);
  m.validate("STL file '" + path + "'");
  return m;
}

void write_stl(const SurfaceMesh& mesh, const std::string& path, StlFormat format) {
  mesh.validate("mesh written to '" + path + "'");
  const auto normals = face_normals(mesh);
  if (format == StlFormat::binary) {
    write_atomically(
        path,
        [&](std::ostream& out) {
          char header[80] = {};
          std::snprintf(header, sizeof(header), "wearsim surface mesh, revision %llu",
                        static_cast<unsigned long long>(mesh.revision()));
          out.write(header, 80);
          const auto n = static_cast<std::uint32_t>(mesh.n_faces());
          out.write(reinterpret_cast<const char*>(&n), 4);
          for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
            float c[12] = {float(normals[f].x), float(normals[f].y), float(normals[f].z)};
            for (int k = 0; k < 3; ++k)
              for (int d = 0; d < 3; ++d)
                c[3 + 3 * k + d] = float(mesh.vertices[mesh.triangles[f][k]][d]);
            out.write(reinterpret_cast<const char*>(c), sizeof(c));
            const int l = mesh.face_labels[f];
            const std::uint16_t attr = (l > 0 && l < 65536) ? std::uint16_t(l) : 0;
            out.write(reinterpret_cast<const char*>(&attr), 2);
          }
        },
        true);
    return;
  }
  write_atomically(path, [&](std::ostream& out) {
    out << std::setprecision(17);
    for (int l : mesh.labels()) {
      out << "solid " << label::name(l) << "\n";
      for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
        if (mesh.face_labels[f] != l)
          continue;
        out << " facet normal " << normals[f].x << ' ' << normals[f].y << ' ' << normals[f].z
            << "\n  outer loop\n";
        for (auto v : mesh.triangles[f])
          out << "   vertex " << mesh.vertices[v].x << ' ' << mesh.vertices[v].y << ' '
              << mesh.vertices[v].z << "\n";
        out << "  endloop\n endfacet\n";
      }
      out << "endsolid " << label::name(l) << "\n";
    }
  });
}

} // namespace wear::meshes
