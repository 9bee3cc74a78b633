#pragma once
// The device pictures of a design report: what the case's later-layer sections ([valve] flow)
// let rheomag compute beyond the field.

#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "plot/figure.hpp"

namespace rheomag::figures {

/// One titled picture of the report, with a sentence saying what it shows.
struct ReportSection {
  std::string title;
  std::string text;
  plot::Figure figure;
};

/// The valve's pressure drop against flow (10 flows from 0.1 to 2 times each [valve] flow, at
/// 0, 1/2, 1 and 3/2 times `current`) when the case has a fluid, a gap and a [valve] flow;
/// nothing otherwise (a case without them is still reported, without its device curves).
std::vector<ReportSection> device_sections(const cases::Case& c, double current);

}  // namespace rheomag::figures
