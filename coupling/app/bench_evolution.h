#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace wear::coupling {

/// `wearsim bench evolution [--state FILE [--scale F] | --sample convex|plain --depth D]
/// [--mesh-size H] [--evolutions a,b] [--output DIR]`: one stage of wear applied by each
/// surface evolution (FEM/Surface evolution) to the same sample, with its time, steps,
/// remeshes, volume error, the offset of the faces that do not wear, the worst triangle and
/// the distance between the evolutions' results (docs/performance.md).
int run_bench_evolution(const std::vector<std::string>& args, std::ostream& out);

} // namespace wear::coupling
