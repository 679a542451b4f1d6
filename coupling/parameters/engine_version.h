#pragma once
// The engine version a run was made with: the source tree's `git describe --always --dirty`
// at build time (cmake/engine_version.cmake), e.g. "e42c029a1b2c" or "e42c029a1b2c-dirty";
// "unknown" when built outside a git checkout. Written into every run folder's
// parameters.prm so a report can tell which engine made a run.

namespace wear::coupling {

const char* engine_version();

} // namespace wear::coupling
