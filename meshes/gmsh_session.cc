// gmsh session guard. gmsh keeps global state, so nesting sessions is refused rather than
// silently sharing one model.
#include "meshes/gmsh_session.h"

#include <gmsh.h>

#include <cstdlib>
#include <mutex>
#include <stdexcept>

namespace wear::meshes {

namespace {
std::mutex gmsh_mutex;
bool active = false;
} // namespace

GmshSession::GmshSession(const std::string& model_name) {
  std::lock_guard<std::mutex> lock(gmsh_mutex);
  if (active)
    throw std::logic_error("a gmsh session is already open; gmsh has one global model");
  gmsh::initialize(0, nullptr, false);
  const char* verbose = std::getenv("WEAR_GMSH_VERBOSE");
  gmsh::option::setNumber("General.Terminal", verbose && verbose[0] == '1' ? 1 : 0);
  gmsh::option::setNumber("General.Verbosity", verbose && verbose[0] == '1' ? 5 : 1);
  gmsh::model::add(model_name);
  active = true;
}

GmshSession::~GmshSession() {
  std::lock_guard<std::mutex> lock(gmsh_mutex);
  gmsh::finalize();
  active = false;
}

} // namespace wear::meshes
