#pragma once
// The parameter visitor: how a module declares the case-file parameters of its plain struct
// once, beside the struct, without depending on the parameter reader (deal.II). A module
// writes, in its header,
//
//   template <typename Visitor> void visit_parameters(MyParameters& p, Visitor& v);
//
// entering its subsection and naming each parameter, the member it fills and its
// documentation, in the order the case file lists them. coupling/parameters composes the
// modules' functions and passes three visitors over the same calls: one declares (the
// member's current value is the default), one parses (file value into the member), one
// stores (member back into the file); so declaration, parsing and the resolved file never
// disagree. A visitor provides exactly these members:
//
//   void enter(const std::string& subsection);
//   void leave();
//   void real(const std::string& name, double& x, const std::string& doc);
//   void integer(const std::string& name, int& x, int min, int max, const std::string& doc);
//   void unsigned_integer(const std::string& name, unsigned int& x, int min, int max,
//                         const std::string& doc);
//   void count(const std::string& name, std::uint64_t& x, const std::string& doc); // >= 0
//   void boolean(const std::string& name, bool& x, const std::string& doc);
//   /// x is true when the value is `yes`, false when it is `no`.
//   void choice(const std::string& name, bool& x, const std::string& yes,
//               const std::string& no, const std::string& doc);
//   /// `options` lists the allowed values as "a|b|c".
//   void selection(const std::string& name, std::string& x, const std::string& options,
//                  const std::string& doc);
//   void text(const std::string& name, std::string& x, const std::string& doc);
//   void real_list(const std::string& name, std::vector<double>& x, const std::string& doc);
//   void int_list(const std::string& name, std::vector<int>& x, const std::string& doc); // >= 0
//
// Documentation starts with the unit in brackets ("[m] ...") where the value has one. A
// module's visit function only names parameters; validate() beside it checks their values.
#include <cstdint>
#include <string>
#include <vector>

namespace wear::meshes {

/// A visitor that only collects the case-file paths of the parameters it is shown
/// ("DEM/Rotation rate"), for checks that need to know which entries a visit function names.
struct ParameterPaths {
  std::vector<std::string> paths;   ///< in visiting order
  std::vector<std::string> section; ///< the subsections entered

  void enter(const std::string& s) { section.push_back(s); }
  void leave() { section.pop_back(); }
  void real(const std::string& n, double&, const std::string&) { add(n); }
  void integer(const std::string& n, int&, int, int, const std::string&) { add(n); }
  void unsigned_integer(const std::string& n, unsigned int&, int, int, const std::string&) {
    add(n);
  }
  void count(const std::string& n, std::uint64_t&, const std::string&) { add(n); }
  void boolean(const std::string& n, bool&, const std::string&) { add(n); }
  void choice(const std::string& n, bool&, const std::string&, const std::string&,
              const std::string&) {
    add(n);
  }
  void selection(const std::string& n, std::string&, const std::string&, const std::string&) {
    add(n);
  }
  void text(const std::string& n, std::string&, const std::string&) { add(n); }
  void real_list(const std::string& n, std::vector<double>&, const std::string&) { add(n); }
  void int_list(const std::string& n, std::vector<int>&, const std::string&) { add(n); }

private:
  void add(const std::string& name) {
    std::string p;
    for (const auto& s : section)
      p += s + "/";
    paths.push_back(p + name);
  }
};

} // namespace wear::meshes
