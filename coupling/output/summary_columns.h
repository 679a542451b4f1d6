#pragma once
// summary.csv's per-revolution (per-period) columns of the wear tester's evaluation: wear in
// total, per column and per convex element, forces, speeds, coefficients of variation, steady
// state, fits. run_output.h writes them with the stage columns beside them.
#include "dem/evaluation/tester_evaluation.h"

#include <ostream>
#include <vector>

namespace wear::coupling {

/// The per-revolution columns of summary.csv (no line end); units in the column names.
void write_summary_header(std::ostream& out, int n_columns, const std::vector<int>& element_labels);
/// One revolution's row of those columns (no line end).
void write_summary_row(std::ostream& out, const dem::RevolutionRecord& r,
                       const std::vector<int>& element_labels);

} // namespace wear::coupling
