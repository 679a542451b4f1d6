// The VTU writer's text: every number it writes reads back as the double it was.
#include "meshes/vtu_writer.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

TEST_CASE("VTU text holds every double exactly", "[meshes][vtu]") {
  // Points and data of awkward values (no short decimal, the extremes, a subnormal): every
  // number read back from the file's text is the double written, bit for bit.
  wear::meshes::VtuGrid g;
  g.cell_type = wear::meshes::VtkCell::vertex;
  const std::vector<double> values{0.1,     1.0 / 3.0, -2.5e17, 1e-300,   4.9e-324,
                                   1.7e308, -0.0,      6e-3,    2.0 / 7.0};
  for (std::size_t k = 0; k + 2 < values.size(); k += 3) {
    g.points.push_back({values[k], values[k + 1], values[k + 2]});
    g.connectivity.push_back(std::uint32_t(g.points.size() - 1));
  }
  g.point_data.push_back({"v", 3, values});
  write_vtu(g, "exact_numbers.vtu");
  std::ifstream in("exact_numbers.vtu");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // The numbers of the Points array and of the data array "v", in order.
  const auto numbers_after = [&text](const std::string& tag) {
    const auto begin = text.find('>', text.find(tag)) + 1;
    std::istringstream s(text.substr(begin, text.find("</DataArray>", begin) - begin));
    std::vector<double> out;
    std::string word;
    while (s >> word)
      out.push_back(std::strtod(word.c_str(), nullptr));
    return out;
  };
  for (const std::string& tag :
       {std::string("NumberOfComponents=\"3\" format"), std::string("Name=\"v\"")}) {
    const auto read = numbers_after(tag);
    REQUIRE(read.size() == values.size());
    for (std::size_t k = 0; k < values.size(); ++k) {
      INFO(tag << " value " << k);
      CHECK(std::memcmp(&read[k], &values[k], sizeof(double)) == 0);
    }
  }
}
