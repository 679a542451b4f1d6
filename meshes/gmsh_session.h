#pragma once
// RAII guard for the gmsh API: gmsh has one global model, so one session at a time.
#include <string>

namespace wear::meshes {

class GmshSession {
public:
  /// Initialises gmsh quietly (set WEAR_GMSH_VERBOSE=1 to see its log) and adds a model.
  explicit GmshSession(const std::string& model_name);
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

} // namespace wear::meshes
