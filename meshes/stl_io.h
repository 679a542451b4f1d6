#pragma once
// STL input and output for SurfaceMesh. Labels survive both formats: ASCII writes one
// `solid <label name>` block per label; binary stores the label id in each facet's 16-bit
// attribute field.
#include "meshes/surface_mesh.h"

#include <string>

namespace wear::meshes {

enum class StlFormat { ascii, binary };

/// Reads ASCII or binary STL (detected from the content), merges bit-identical vertices.
/// Facet normals in the file are ignored; the vertex order defines the orientation.
/// Throws std::runtime_error naming the file and the line or facet that is wrong.
SurfaceMesh read_stl(const std::string& path);

/// Writes atomically. ASCII uses 17 significant digits, so doubles round-trip exactly;
/// binary stores 32-bit floats (exact for coordinates already representable as float).
void write_stl(const SurfaceMesh& mesh, const std::string& path, StlFormat format);

} // namespace wear::meshes
