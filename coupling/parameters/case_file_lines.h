#pragma once
// A case file's lines as deal.II's ParameterHandler reads them (comments, continued lines,
// `subsection`, `end`, `set`, `INCLUDE`), walked before it parses them, for two things the
// handler does not see: an INCLUDE loop (the handler follows it until the stack overflows)
// and a parameter set twice in one file (the handler keeps the last value silently); and
// which entries the files set at all (the handler cannot tell a default from a value set).
#include <string>
#include <vector>

namespace wear::coupling {

/// Walks the case file `path` and every file it INCLUDEs (paths relative to the working
/// directory, as ParameterHandler opens them). Throws std::invalid_argument naming the files
/// and lines of an INCLUDE chain that comes back to a file it is reading ("a.prm includes
/// b.prm (line 4 of a.prm), which includes a.prm again (line 1 of b.prm)"). Returns one
/// sentence per parameter set more than once in the same file, naming its case-file path,
/// the file and the lines. A value set again in another file (an INCLUDEd file, or a file
/// that sets after its INCLUDE line what the included file set) is the documented way to
/// specialise a case and is not reported. Files that cannot be opened are left to the
/// handler, whose message names them.
std::vector<std::string> check_case_file_lines(const std::string& path);

/// One `set` line of a case file or of a file it INCLUDEs.
struct CaseFileEntry {
  std::string path; ///< the entry's case-file path, "DEM/Rotation rate"
  std::string file; ///< the file that sets it, as the case or its INCLUDE line names it
  int line = 0;     ///< the line (the first of a continued line)
};

/// What check_case_file_lines finds, and every entry the files set, in reading order.
struct CaseFileWalk {
  std::vector<std::string> repeated; ///< check_case_file_lines' sentences
  std::vector<CaseFileEntry> entries;
};

/// check_case_file_lines, and the entries set.
CaseFileWalk walk_case_file(const std::string& path);

} // namespace wear::coupling
