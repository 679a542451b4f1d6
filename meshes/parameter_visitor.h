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
