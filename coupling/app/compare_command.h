#pragma once
// `wearsim compare [--from <k>] <A1> [<A2> ...] -- <B1> [<B2> ...]` (one run per side:
// `wearsim compare <runA> <runB>`): the runs of two sides from their history.h5, summary.csv
// and parameters.prm, every figure as mean +- half-width of its 95 % interval.
#include <ostream>
#include <string>
#include <vector>

namespace wear::coupling {

/// Prints the comparison table; returns the exit code. Throws naming the side and the run
/// folder or file for a missing folder, a run without revolutions after steady state, a side
/// mixing sample kinds or repeating a DEM/Seed, and one run with fewer than 2 revolutions.
int run_compare_command(const std::vector<std::string>& args, std::ostream& out);

} // namespace wear::coupling
