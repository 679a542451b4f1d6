// The INCLUDE chain of a case file and the parameters each of its files sets more than once
// (case_file_lines.h), found by reading the lines the way deal.II 9.4's ParameterHandler does
// (parse_input and scan_line): each line trimmed; one ending in '\' joined with the next
// (its number that of the first); then everything from '#' dropped, tabs made spaces,
// trimmed again; then a line starting "subsection " or "SUBSECTION " enters a subsection,
// "end"/"END" leaves it, "set "/"SET " names the entry before '=', and "include "/"INCLUDE "
// reads the named file at the current subsection. Anything else the handler refuses itself
// after this walk, so it is skipped here. Why a walk of our own: the handler follows an
// INCLUDE by calling itself, so a file that includes itself (or two that include each other)
// recurses until the stack overflows (a segmentation fault, no message); and it keeps the
// last of two values of one entry without a word, which in one file is a slip (a line
// copied and edited, the old one forgotten), while across files it is how a case
// specialises the one it includes (cases/reference-study/plain-s4.prm).
#include "coupling/parameters/case_file_lines.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <system_error>

namespace wear::coupling {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n"), e = s.find_last_not_of(" \t\r\n");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

bool starts_with(const std::string& s, const std::string& lower, const std::string& upper) {
  return s.compare(0, lower.size(), lower) == 0 || s.compare(0, upper.size(), upper) == 0;
}

/// One file being read: its name as the case or the INCLUDE line wrote it, and the line of
/// the INCLUDE in the file before it in the chain that brought it in.
struct Link {
  std::string name;
  int line = 0;
};

std::string line_of(const Link& including, int line) {
  return "line " + std::to_string(line) + " of " + including.name;
}

[[noreturn]] void refuse_loop(const std::vector<Link>& chain, const std::string& target, int line) {
  std::string s = chain.front().name;
  for (std::size_t k = 1; k < chain.size(); ++k)
    s += (k == 1 ? " includes " : ", which includes ") + chain[k].name + " (" +
         line_of(chain[k - 1], chain[k].line) + ")";
  s += (chain.size() == 1 ? " includes " : ", which includes ") + target + " again (" +
       line_of(chain.back(), line) +
       "): the INCLUDE lines form a loop that never ends; remove the INCLUDE that comes back";
  throw std::invalid_argument(s);
}

std::string join(const std::vector<std::string>& path, const std::string& name) {
  std::string s;
  for (const auto& p : path)
    s += p + "/";
  return s + name;
}

std::string lines_text(const std::vector<int>& lines) {
  std::string s;
  for (std::size_t k = 0; k < lines.size(); ++k)
    s += (k == 0 ? "" : k + 1 == lines.size() ? " and " : ", ") + std::to_string(lines[k]);
  return s;
}

/// Reads the last file of `chain` inside the subsections `path` (an INCLUDEd file is read
/// where its INCLUDE line stands); appends a sentence to `notes` for each entry this file
/// sets more than once.
void walk(std::vector<Link>& chain, std::vector<std::string> path, CaseFileWalk& result) {
  std::vector<std::string>& notes = result.repeated;
  std::ifstream in(chain.back().name);
  if (!in)
    return;                                   // the handler names the file it cannot open
  std::vector<std::string> order;             // entries in the order first set
  std::map<std::string, std::vector<int>> at; // entry -> the lines that set it
  std::string raw, joined;
  int number = 0, first = 0;
  bool continued = false;
  while (std::getline(in, raw)) {
    ++number;
    if (!continued)
      first = number;
    raw = trim(raw);
    if (!raw.empty() && raw.back() == '\\') {
      joined += raw.substr(0, raw.size() - 1);
      continued = true;
      continue;
    }
    std::string line = joined + raw;
    joined.clear();
    continued = false;
    line = line.substr(0, line.find('#'));
    for (char& c : line)
      if (c == '\t')
        c = ' ';
    line = trim(line);
    if (starts_with(line, "subsection ", "SUBSECTION ")) {
      path.push_back(trim(line.substr(11)));
    } else if (starts_with(line, "end", "END")) {
      if (!path.empty())
        path.pop_back();
    } else if (starts_with(line, "set ", "SET ")) {
      const auto eq = line.find('=');
      if (eq == std::string::npos)
        continue;
      const std::string entry = join(path, trim(line.substr(4, eq - 4)));
      auto& lines = at[entry];
      if (lines.empty())
        order.push_back(entry);
      lines.push_back(first);
      result.entries.push_back({entry, chain.back().name, first});
    } else if (starts_with(line, "include ", "INCLUDE ")) {
      const std::string target = trim(line.substr(8));
      std::error_code ignore;
      if (target.empty() || !std::filesystem::exists(target, ignore))
        continue;
      // The same file, however it is spelled (./a.prm, a link): std::filesystem::equivalent
      // compares the files themselves.
      for (const auto& link : chain)
        if (std::filesystem::equivalent(target, link.name, ignore))
          refuse_loop(chain, target, first);
      chain.push_back({target, first});
      walk(chain, path, result);
      chain.pop_back();
    }
  }
  for (const auto& entry : order) {
    const auto& lines = at[entry];
    if (lines.size() < 2)
      continue;
    notes.push_back(
        entry + " is set " +
        (lines.size() == 2 ? std::string("twice") : std::to_string(lines.size()) + " times") +
        " in " + chain.back().name + ", on lines " + lines_text(lines) +
        ": only the last value (line " + std::to_string(lines.back()) +
        ") is used; remove the other line" + (lines.size() > 2 ? "s" : ""));
  }
}

} // namespace

CaseFileWalk walk_case_file(const std::string& path) {
  std::vector<Link> chain{{path, 0}};
  CaseFileWalk result;
  walk(chain, {}, result);
  return result;
}

std::vector<std::string> check_case_file_lines(const std::string& path) {
  return walk_case_file(path).repeated;
}

} // namespace wear::coupling
