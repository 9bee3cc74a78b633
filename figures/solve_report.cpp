#include "figures/solve_report.hpp"

#include <cmath>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/html_text.hpp"
#include "figures/gap_profile.hpp"
#include "figures/inductance.hpp"

namespace rheomag::figures {

namespace {

/// Every occurrence of `from` in `text` replaced by `to`.
std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos;
       at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

/// "0.706" or "-" for a number that is not finite.
std::string cell(double value, int digits = 4) {
  return std::isfinite(value) ? html_number(value, digits) : std::string("&ndash;");
}

/// The key numbers as HTML tables.
std::string key_numbers(const SolvedCase& s) {
  const magnetostatics::Results& r = s.results;
  std::ostringstream o;
  o << "<p>"
    << (s.solver.problem().symmetry == cases::Symmetry::axisymmetric ? "Axisymmetric" : "Planar")
    << " magnetostatics, P" << s.solver.mesh().order << ": " << r.elements << " elements, "
    << r.dofs << " unknowns, " << r.newton_iterations << " Newton iterations, solved in "
    << html_number(r.seconds, 3) << " s.</p>\n";
  if (!r.gaps.empty()) {
    // Column names as docs/quantities.md defines them (solve's text, JSON and the sweep CSV).
    o << "<h2>Fluid gaps</h2>\n<table><tr><th>gap</th><th>kind</th><th>B_avg [T]</th>"
         "<th>Bn_avg [T]</th><th>B_min_midline [T]</th><th>B_max_midline [T]</th>"
         "<th>B_max_area [T]</th></tr>\n";
    for (const magnetostatics::GapResult& g : r.gaps) {
      o << "<tr><td>" << html_escape(g.name) << "</td><td>"
        << (g.kind == mesh::GapKind::annular ? "annular" : "radial") << "</td><td>"
        << cell(g.b.average) << "</td><td>" << cell(g.b_normal.average) << "</td><td>"
        << cell(g.line_b.minimum) << "</td><td>" << cell(g.line_b.maximum) << "</td><td>"
        << cell(g.b.maximum) << "</td></tr>\n";
    }
    o << "</table>\n";
  }
  if (!r.circuits.empty()) {
    o << "<h2>Circuits</h2>\n<table><tr><th>circuit</th><th>current [A]</th><th>turns</th>"
         "<th>&lambda; [mWb]</th><th>L = &lambda;/I [mH]</th><th>d&lambda;/dI [mH]</th></tr>\n";
    for (const magnetostatics::CircuitResult& c : r.circuits) {
      o << "<tr><td>" << html_escape(c.name) << "</td><td>" << cell(c.current) << "</td><td>"
        << cell(c.turns) << "</td><td>" << cell(1e3 * c.flux_linkage) << "</td><td>"
        << cell(1e3 * c.inductance) << "</td><td>" << cell(1e3 * c.incremental_inductance)
        << "</td></tr>\n";
    }
    o << "</table>\n";
  }
  o << "<p>Stored energy " << cell(r.energy) << " J, co-energy " << cell(r.coenergy) << " J.</p>\n";
  return o.str();
}

}  // namespace

std::string inline_svg(const std::string& svg, const std::string& prefix) {
  std::string text = svg;
  if (text.rfind("<?xml", 0) == 0) text.erase(0, text.find("?>") + 2);
  text = replace_all(text, "id=\"", "id=\"" + prefix);
  text = replace_all(text, "href=\"#", "href=\"#" + prefix);
  return replace_all(text, "url(#", "url(#" + prefix);
}

std::string solve_report_html(const SolvedCase& solved, const FieldMapOptions& options,
                              const std::vector<ReportSection>& sections) {
  std::ostringstream o;
  o << "<!DOCTYPE html>\n<html><head><meta charset='utf-8'><title>rheomag report: "
    << html_escape(solved.name)
    << "</title><style>body{font-family:sans-serif;margin:20px;max-width:1000px}"
       "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:3px 8px;"
       "text-align:right}h2{margin-top:28px}svg{max-width:100%;height:auto}</style>"
       "</head><body>\n<h1>Design report: "
    << html_escape(solved.name) << "</h1>\n"
    << key_numbers(solved);
  int figure = 0;
  auto picture = [&](const plot::Figure& f) {
    o << inline_svg(f.svg(), "f" + std::to_string(figure++) + "-") << "\n";
  };
  o << "<h2>Field map</h2>\n<p>|B| in colour bands, flux lines (equal flux between neighbours), "
       "region outlines and the fluid gaps.</p>\n";
  FieldMapOptions map = options;
  if (map.title.empty()) map.title = solved.name + ": |B| and flux lines";
  picture(draw_field_map(solved.solver, solved.solution, solved.results, map).figure);
  if (!solved.results.gaps.empty()) {
    o << "<h2>B along the gaps</h2>\n<p>Normal and tangential components on the mid-line "
         "(solid) and the walls (dashed).</p>\n";
    for (const magnetostatics::GapResult& g : solved.results.gaps) {
      if (!g.profile.s.empty()) picture(gap_profile_figure(g, 900, 560));
    }
  }
  if (!solved.sweep.empty() && !solved.results.circuits.empty()) {
    o << "<h2>Flux linkage and inductance</h2>\n";
    picture(inductance_figure(solved.sweep, solved.results.circuits.front().name, 900, 800));
  }
  for (const ReportSection& section : sections) {
    o << "<h2>" << html_escape(section.title) << "</h2>\n<p>" << html_escape(section.text)
      << "</p>\n";
    picture(section.figure);
  }
  o << "</body></html>\n";
  return o.str();
}

std::filesystem::path write_solve_report(const std::filesystem::path& dir, const SolvedCase& solved,
                                         const FieldMapOptions& options,
                                         const std::vector<ReportSection>& sections) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw InputError("--out " + dir.string() + ": cannot create the folder (" + ec.message() + ")");
  const std::filesystem::path path = dir / "report.html";
  write_file_atomically(path, solve_report_html(solved, options, sections));
  return path;
}

}  // namespace rheomag::figures
