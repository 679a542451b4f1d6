// Atomic file output: temporary file in the same folder (so rename(2) stays on one file
// system and is atomic), checked stream state, fsync-free close, then rename.
#include "meshes/atomic_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace wear::meshes {

void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                      bool binary) {
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(tmp, binary ? std::ios::binary | std::ios::out : std::ios::out);
    if (!out)
      throw std::runtime_error("cannot write '" + path + "': the folder does not exist or is " +
                               "not writable");
    write(out);
    out.flush();
    if (!out) {
      out.close();
      std::remove(tmp.c_str());
      throw std::runtime_error("writing '" + path + "' failed (disk full?)");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot rename the temporary file onto '" + path + "'");
  }
}

void ensure_directory(const std::string& path) {
  std::error_code ec;
  std::filesystem::create_directories(path, ec);
  if (ec || !std::filesystem::is_directory(path))
    throw std::runtime_error("cannot create output folder '" + path + "': " + ec.message());
}

} // namespace wear::meshes
