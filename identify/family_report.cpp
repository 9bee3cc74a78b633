// HTML report of a family fit (inline SVG loops, parameter and metric tables).

#include "identify/family_report.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/html_text.hpp"
#include "lumped/phenomenological.hpp"

namespace rheomag::identify {

namespace {

/// y against x of the measurement (grey, wide) and the model (blue), as an inline SVG.
std::string svg_loop(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                     const std::vector<double>& x, const std::vector<double>& measured,
                     const std::vector<double>& model) {
  const double W = 430, H = 300, L = 70, R = 12, T = 28, B = 40;
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (std::size_t k = 0; k < x.size(); ++k) {
    x0 = std::min(x0, x[k]);
    x1 = std::max(x1, x[k]);
    for (double v : {measured[k], model[k]})
      if (std::isfinite(v)) {
        y0 = std::min(y0, v);
        y1 = std::max(y1, v);
      }
  }
  if (!(x1 > x0)) x1 = x0 + 1.0;
  if (!(y1 > y0)) y1 = y0 + 1.0;
  const auto X = [&](double v) { return L + (v - x0) / (x1 - x0) * (W - L - R); };
  const auto Y = [&](double v) { return T + (y1 - v) / (y1 - y0) * (H - T - B); };
  std::ostringstream o;
  o << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H
    << "' font-family='sans-serif' font-size='11'>\n<rect width='" << W << "' height='" << H
    << "' fill='white'/>\n<rect x='" << L << "' y='" << T << "' width='" << W - L - R
    << "' height='" << H - T - B << "' fill='none' stroke='#444'/>\n";
  for (int i = 0; i <= 4; ++i) {
    const double yv = y0 + (y1 - y0) * i / 4.0, xv = x0 + (x1 - x0) * i / 4.0;
    o << "<text x='" << L - 5 << "' y='" << Y(yv) + 4 << "' text-anchor='end'>"
      << html_number(yv, 3) << "</text><text x='" << X(xv) << "' y='" << H - B + 14
      << "' text-anchor='middle'>" << html_number(xv, 3) << "</text>\n";
  }
  o << "<text x='" << (L + W - R) / 2 << "' y='" << H - 6 << "' text-anchor='middle'>"
    << html_escape(xlabel) << "</text>\n<text x='12' y='" << (T + H - B) / 2
    << "' transform='rotate(-90 12 " << (T + H - B) / 2 << ")' text-anchor='middle'>"
    << html_escape(ylabel) << "</text>\n<text x='" << L << "' y='18' font-weight='bold'>"
    << html_escape(title) << "</text>\n";
  const std::size_t stride = std::max<std::size_t>(1, x.size() / 3000);
  const auto line = [&](const std::vector<double>& y, const char* color, double width) {
    o << "<polyline fill='none' stroke='" << color << "' stroke-width='" << width << "' points='";
    for (std::size_t k = 0; k < x.size(); k += stride)
      if (std::isfinite(y[k])) o << X(x[k]) << ',' << Y(y[k]) << ' ';
    o << "'/>\n";
  };
  line(measured, "#999", 2.5);
  line(model, "#1f5fbf", 1.2);
  o << "<line x1='" << W - 150 << "' x2='" << W - 132 << "' y1='12' y2='12' stroke='#999' "
    << "stroke-width='3'/><text x='" << W - 128 << "' y='16'>measured</text><line x1='" << W - 70
    << "' x2='" << W - 52 << "' y1='12' y2='12' stroke='#1f5fbf' stroke-width='3'/><text x='"
    << W - 48 << "' y='16'>model</text>\n</svg>\n";
  return o.str();
}

/// Units of the drive/output columns of the recording format.
std::string unit_of(const std::string& column) {
  static const std::map<std::string, std::string> units{
      {"force", "N"},    {"pressure", "Pa"}, {"displacement", "m"}, {"velocity", "m/s"},
      {"flow", "m^3/s"}, {"current", "A"},   {"command", "V"},      {"current_cmd", "A"}};
  const auto it = units.find(column);
  return it == units.end() ? std::string() : " [" + it->second + "]";
}

/// Loops and metrics of one recording.
std::string member_section(const FamilyMember& m, const lumped::Recording& rec,
                           const GreyboxFit& fit, const char* role) {
  const std::vector<double>& y = rec.column(fit.setup.output_column);
  const std::vector<double>& motion = rec.column(fit.setup.motion_column);
  std::ostringstream o;
  o << "<h3>" << html_escape(m.csv_path) << " (" << role << ")</h3>\n<p>field "
    << html_number(m.field) << unit_of(fit.setup.field_column) << ": FIT "
    << html_number(m.metrics.fit_percent, 3) << " %, RMSE "
    << html_number(m.metrics.rmse_percent, 3) << " %, RE " << html_number(m.metrics.re, 3)
    << "</p>\n";
  for (const RangeExcess& e : m.beyond)
    o << "<p>Beyond the training recordings' drive: " << html_escape(e.text()) << "</p>\n";
  o << "<div>";
  const std::string ylabel = fit.setup.output_column + unit_of(fit.setup.output_column);
  if (!fit.setup.position_column.empty())
    o << svg_loop("output vs position",
                  fit.setup.position_column + unit_of(fit.setup.position_column), ylabel,
                  rec.column(fit.setup.position_column), y, m.simulated);
  o << svg_loop("output vs motion", fit.setup.motion_column + unit_of(fit.setup.motion_column),
                ylabel, motion, y, m.simulated)
    << "</div>\n";
  return o.str();
}

/// Rows "name(field) = a + b u + c u^2" at each field level for parameters with per-field terms;
/// for the damper model u is the field the valve sees, tanh(k I) / k (damper_effective_field).
std::string field_dependence(const FamilyFit& r) {
  std::vector<double> levels;
  for (const FamilyMember& m : r.training)
    if (std::none_of(levels.begin(), levels.end(),
                     [&](double l) { return std::abs(l - m.field) < 1e-9 * (1 + std::abs(l)); }))
      levels.push_back(m.field);
  std::sort(levels.begin(), levels.end());
  std::vector<double> values;
  for (const FittedParameter& p : r.fit.params) values.push_back(p.value);
  const bool damper = r.fit.setup.kind == lumped::PhenoKind::damper &&
                      values.size() == lumped::pheno_params(lumped::PhenoKind::damper).size();
  const auto field = [&](double level) {
    return damper ? lumped::pheno_detail::damper_effective_field(values.data(), level) : level;
  };
  const std::vector<FieldDependence> dependent = field_dependent_parameters(r.fit.params);
  if (dependent.empty()) return "<p>(no field-dependent parameters)</p>\n";
  std::ostringstream o;
  o << "<table><tr><th>parameter</th>";
  for (double l : levels) o << "<th>u = " << html_number(l, 3) << "</th>";
  o << "</tr>\n";
  for (const FieldDependence& d : dependent) {
    const FittedParameter& p = r.fit.params[d.base];
    o << "<tr><td>" << html_escape(d.name) << " [" << html_escape(p.unit) << "]</td>";
    for (double l : levels) {
      const double u = field(l);
      o << "<td>"
        << html_number(values[d.base] + values[d.linear] * u +
                       (d.quadratic ? values[*d.quadratic] * u * u : 0.0))
        << "</td>";
    }
    o << "</tr>\n";
  }
  o << "</table>\n";
  return o.str();
}

}  // namespace

std::vector<FieldDependence> field_dependent_parameters(
    const std::vector<FittedParameter>& params) {
  const auto find = [&](const std::string& name) -> std::optional<std::size_t> {
    for (std::size_t k = 0; k < params.size(); ++k)
      if (params[k].name == name) return k;
    return std::nullopt;
  };
  std::vector<FieldDependence> out;
  for (std::size_t k = 0; k < params.size(); ++k) {
    const std::string& name = params[k].name;
    if (const auto linear = find(name + "_per_field")) {
      out.push_back({name, k, *linear, find(name + "_per_field2")});
    } else if (name.size() > 2 && name.compare(name.size() - 2, 2, "_a") == 0) {
      const std::string stem = name.substr(0, name.size() - 2);
      if (const auto b = find(stem + "_b")) out.push_back({stem, k, *b, std::nullopt});
    }
  }
  return out;
}

std::string family_report_html(const FamilyFit& r, const std::vector<lumped::Recording>& training,
                               const std::vector<lumped::Recording>& prediction) {
  if (training.size() != r.training.size() || prediction.size() != r.predicted.size())
    throw InputError("family report: the recordings do not match the fit's members");
  std::ostringstream o;
  o << "<!DOCTYPE html>\n<html><head><meta charset='utf-8'><title>rheomag fit-family: "
    << html_escape(r.fit.model)
    << "</title><style>body{font-family:sans-serif;margin:20px}table{border-collapse:collapse}"
       "td,th{border:1px solid #bbb;padding:3px 8px;text-align:right}svg{margin:4px}"
       "</style></head><body>\n<h1>Family fit: model "
    << html_escape(r.fit.model) << "</h1>\n<p>Fitted jointly on " << r.training.size()
    << " recordings (each weighted by its own spread); " << r.predicted.size()
    << " recordings predicted with the same parameters (free-run simulation)."
    << (r.held_out.empty() ? ""
                           : " Rows &ldquo;held out&rdquo;: each training recording predicted by "
                             "the family fitted without it.")
    << "</p>\n";
  o << "<h2>FIT per recording</h2>\n<table><tr><th>recording</th><th>role</th><th>field</th>"
       "<th>FIT %</th><th>RMSE %</th><th>RE</th><th>band % (1&sigma;, parameters between "
       "recordings)</th><th>repeatability % (the recording's own mean cycle)</th><th>FIT % after "
       "the first steady cycle, pure</th><th>the same with one level (gain, offset on the first "
       "steady cycle)</th><th>reversals: % of the residual energy in % of the samples</th><th>mean "
       "residual of the settled strokes, motion &gt; 0 / &lt; 0</th></tr>\n";
  const auto rows = [&](const std::vector<FamilyMember>& members, const char* role) {
    for (const FamilyMember& m : members)
      o << "<tr><td>" << html_escape(m.csv_path) << "</td><td>" << role
        << (m.beyond.empty() ? std::string()
                             : " (extrapolated: " + html_escape(m.beyond.front().text()) + ")")
        << "</td><td>" << html_number(m.field) << "</td><td>"
        << html_number(m.metrics.fit_percent, 3) << "</td><td>"
        << html_number(m.metrics.rmse_percent, 3) << "</td><td>" << html_number(m.metrics.re, 3)
        << "</td><td>" << (m.band ? html_number(m.band->percent, 3) : std::string("&mdash;"))
        << "</td><td>"
        << (m.repeatability ? html_number(*m.repeatability, 3) : std::string("&mdash;"))
        << "</td><td>"
        << (m.level ? html_number(m.level->pure_fit_percent, 3) : std::string("&mdash;"))
        << "</td><td>"
        << (m.level ? html_number(m.level->fit_percent, 3) + " (gain " +
                          html_number(m.level->gain, 3) + ")"
                    : std::string("&mdash;"))
        << "</td><td>"
        << (m.regimes ? html_number(m.regimes->transition.energy_percent, 2) + " in " +
                            html_number(m.regimes->transition.time_percent, 2)
                      : std::string("&mdash;"))
        << "</td><td>"
        << (m.regimes ? html_number(m.regimes->positive.mean, 3) + " / " +
                            html_number(m.regimes->negative.mean, 3)
                      : std::string("&mdash;"))
        << "</td></tr>\n";
  };
  rows(r.training, "fit");
  rows(r.predicted, "predicted");
  rows(r.held_out, "held out");
  o << "</table>\n<h2>Parameters (SI, &plusmn; one standard error)</h2>\n<table><tr><th>name</th>"
       "<th>value</th><th>standard error</th><th>between recordings</th><th>unit</th>"
       "<th>remark</th></tr>\n";
  const auto se_cell = [](const std::optional<double>& se) {
    return se ? html_number(*se, 3) : std::string("&mdash;");
  };
  for (const FittedParameter& p : r.fit.params)
    o << "<tr><td>" << html_escape(p.name) << "</td><td>" << html_number(p.value, 5) << "</td><td>"
      << se_cell(p.standard_error) << "</td><td>" << se_cell(p.standard_error_between_recordings)
      << "</td><td>" << html_escape(p.unit) << "</td><td>" << html_escape(parameter_remark(p))
      << "</td></tr>\n";
  o << "</table>\n<h2>Field dependence</h2>\n" << field_dependence(r) << "<h2>Loops</h2>\n";
  for (std::size_t i = 0; i < training.size(); ++i)
    o << member_section(r.training[i], training[i], r.fit, "fit");
  for (std::size_t i = 0; i < prediction.size(); ++i)
    o << member_section(r.predicted[i], prediction[i], r.fit, "predicted");
  o << "</body></html>\n";
  return o.str();
}

void write_family_report(const std::filesystem::path& dir, const FamilyFit& fit,
                         const std::vector<lumped::Recording>& training,
                         const std::vector<lumped::Recording>& prediction) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw InputError("--report " + dir.string() + ": cannot create the folder (" + ec.message() +
                     ")");
  write_file_atomically(dir / "report.html", family_report_html(fit, training, prediction));
}

}  // namespace rheomag::identify
