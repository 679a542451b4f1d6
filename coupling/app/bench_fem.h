#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace wear::coupling {

/// `wearsim bench fem [--mesh-size H] [--degrees 1,2] [--output DIR]`: the FEM figures of the
/// reference convex sample (docs/performance.md): mesh generation, P1/P2 stress solves
/// (DoFs, CG iterations, wall time), one stage of mesh motion and one remesh.
int run_bench_fem(const std::vector<std::string>& args, std::ostream& out);

} // namespace wear::coupling
