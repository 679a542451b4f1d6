#pragma once
// Writes a file atomically: the content goes to "<path>.tmp.<pid>" and is renamed over
// <path> only after it was flushed and closed without error, so a reader never sees a
// half-written file and a crash never destroys the previous version.
#include <functional>
#include <ostream>
#include <string>

namespace wear::meshes {

/// Calls write(stream) on a temporary file next to path, then renames it to path.
/// Throws std::runtime_error naming the path if the folder is not writable or a write fails.
void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                      bool binary = false);

/// Creates a folder and its parents; throws with the path if impossible.
void ensure_directory(const std::string& path);

} // namespace wear::meshes
