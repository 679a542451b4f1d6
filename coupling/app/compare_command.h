#pragma once
// `wearsim compare <runA> <runB>`: two runs side by side from their history.h5.
#include <ostream>
#include <string>
#include <vector>

namespace wear::coupling {

/// Prints the comparison table; returns the exit code. Throws naming a missing file.
int run_compare_command(const std::vector<std::string>& args, std::ostream& out);

} // namespace wear::coupling
