#pragma once
// tests/data/pot_core.fem turned into a model with a magnet and a point current: the Air block
// gets H_c = 800 kA/m, the label at (60, 0) mm the direction expression `direction`, and point
// 30, -20 mm the point property "wire" (3 A).

#include <string>

namespace rheomag::testing {

/// The pot core text `text` with the magnet, direction expression and point current above.
inline std::string pot_core_with_magnet(std::string text, const std::string& direction) {
  text.replace(text.find("<H_c> = 0"), 9, "<H_c> = 8e5");
  text.replace(text.find("[PointProps]  =  0"), 18,
               "[PointProps] = 1\n<BeginPoint>\n<PointName> = \"wire\"\n<I_re> = 3\n"
               "<A_re> = 0\n<EndPoint>");
  text.replace(text.find("30\t-20\t0\t0"), 10, "30\t-20\t1\t0");
  const std::size_t label = text.find("60\t0\t1\t-1\t0\t0\t0\t1\t0");
  text.insert(text.find_first_of("\r\n", label), "\t\"" + direction + "\"");
  return text;
}

}  // namespace rheomag::testing
