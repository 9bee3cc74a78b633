// HTML report with inline SVG plots, traces CSV and JSON of a diagnosis.

#include "diagnose/diagnose_report.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/finite_output.hpp"
#include "core/html_text.hpp"
#include "core/output_set.hpp"
#include "core/version.hpp"
#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_change.hpp"
#include "diagnose/diagnose_findings.hpp"

namespace rheomag::diagnose {

namespace {

struct Series {
  std::string label;
  std::string color;
  const std::vector<double>* values;
};

struct Band {
  double t0, t1;
};

/// A line plot of `series` against t over [ta, tb] with shaded bands, as an inline SVG.
std::string svg_plot(const std::string& title, const std::string& ylabel,
                     const std::vector<double>& t, const std::vector<Series>& series,
                     const std::vector<Band>& bands, double ta, double tb) {
  const double W = 900, H = 280, L = 80, R = 20, T = 30, B = 40;
  std::size_t a = std::lower_bound(t.begin(), t.end(), ta) - t.begin();
  std::size_t b = std::upper_bound(t.begin(), t.end(), tb) - t.begin();
  if (b <= a + 1) {
    a = 0;
    b = t.size();
  }
  double lo = 1e300, hi = -1e300;
  for (const auto& s : series)
    for (std::size_t k = a; k < b; ++k) {
      lo = std::min(lo, (*s.values)[k]);
      hi = std::max(hi, (*s.values)[k]);
    }
  if (!(hi > lo)) {
    hi = lo + 1.0;
    lo -= 1.0;
  }
  const double pad = 0.05 * (hi - lo);
  lo -= pad;
  hi += pad;
  const double t0 = t[a], t1 = t[b - 1];
  auto X = [&](double tt) { return L + (tt - t0) / std::max(t1 - t0, 1e-300) * (W - L - R); };
  auto Y = [&](double v) { return T + (hi - v) / (hi - lo) * (H - T - B); };
  std::ostringstream o;
  o << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H
    << "' viewBox='0 0 " << W << ' ' << H << "' font-family='sans-serif' font-size='12'>\n";
  o << "<rect x='0' y='0' width='" << W << "' height='" << H << "' fill='white'/>\n";
  for (const auto& band : bands) {
    const double x0 = X(std::max(band.t0, t0)), x1 = X(std::min(band.t1, t1));
    if (x1 > x0)
      o << "<rect x='" << x0 << "' y='" << T << "' width='" << x1 - x0 << "' height='" << H - T - B
        << "' fill='#f4c7c3' opacity='0.6'/>\n";
  }
  o << "<rect x='" << L << "' y='" << T << "' width='" << W - L - R << "' height='" << H - T - B
    << "' fill='none' stroke='#444'/>\n";
  for (int i = 0; i <= 4; ++i) {
    const double v = lo + (hi - lo) * i / 4.0, tt = t0 + (t1 - t0) * i / 4.0;
    o << "<text x='" << L - 6 << "' y='" << Y(v) + 4 << "' text-anchor='end'>" << html_number(v, 3)
      << "</text><line x1='" << L << "' x2='" << W - R << "' y1='" << Y(v) << "' y2='" << Y(v)
      << "' stroke='#ddd'/>\n";
    o << "<text x='" << X(tt) << "' y='" << H - B + 16 << "' text-anchor='middle'>"
      << html_number(tt, 4) << "</text>\n";
  }
  o << "<text x='" << (L + W - R) / 2 << "' y='" << H - 6
    << "' text-anchor='middle'>t [s]</text>\n";
  o << "<text x='14' y='" << (T + H - B) / 2 << "' transform='rotate(-90 14 " << (T + H - B) / 2
    << ")' text-anchor='middle'>" << html_escape(ylabel) << "</text>\n";
  o << "<text x='" << L << "' y='18' font-weight='bold'>" << html_escape(title) << "</text>\n";
  const std::size_t stride = std::max<std::size_t>(1, (b - a) / 2000);
  double legend_x = W - R - 10;
  // The first series (the measurement) is drawn first, wide and grey, so the models show on top.
  for (auto it = series.begin(); it != series.end(); ++it) {
    o << "<polyline fill='none' stroke='" << it->color << "' stroke-width='"
      << (it == series.begin() ? 2.5 : 1.3) << "' points='";
    for (std::size_t k = a; k < b; k += stride) o << X(t[k]) << ',' << Y((*it->values)[k]) << ' ';
    o << "'/>\n";
    legend_x -= 8.0 * static_cast<double>(it->label.size()) + 30;
    o << "<line x1='" << legend_x << "' x2='" << legend_x + 18 << "' y1='14' y2='14' stroke='"
      << it->color << "' stroke-width='3'/><text x='" << legend_x + 22 << "' y='18'>"
      << html_escape(it->label) << "</text>\n";
  }
  o << "</svg>\n";
  return o.str();
}

/// A candidate's size with the sign free and what derives from it, e.g. "inertance = -2.04e+07
/// Pa s^2/m^3 (moving_mass = -20.4 kg)"; "" when it has none.
std::string signed_size_text(const CandidateScore& c) {
  std::string text;
  for (std::size_t j = 0; j < c.signed_params.size() && j < c.param_names.size(); ++j)
    text += (j == 0 ? "" : ", ") + c.param_names[j] + " = " +
            value_text(c.signed_params[j], c.param_units[j]);
  for (std::size_t j = 0; j < c.signed_derived.size(); ++j)
    text += (j == 0 ? " (" : ", ") + c.signed_derived[j].name + " = " +
            value_text(c.signed_derived[j].value, c.signed_derived[j].unit) +
            (j + 1 == c.signed_derived.size() ? ")" : "");
  return text;
}

}  // namespace

std::string diagnosis_text(const Diagnosis& d) {
  const std::string unit = output_unit(d);
  std::ostringstream o;
  o << "baseline FIT " << percent_text(d.baseline_fit_percent) << " (" << kCalibrationStage
    << ")\n";
  for (const auto& item : d.includes)
    o << "  baseline has " << item.name << ": " << item.source << "\n";
  o << "  nuisance (" << kCalibrationStage << "): " << nuisance_text(d.nuisance) << "\n";
  for (const auto& w : d.mismatch)
    o << "  mismatch of the baseline " << w.t_start << "-" << w.t_end
      << " s: " << percent_text(100 * w.share) << " of its residual energy (" << w.regime << ")\n";
  if (d.findings.empty()) o << "missing physics: none\n";
  for (const auto& f : d.findings) {
    o << "missing physics: " << f.effect->name() << " (accepted at " << selection_stage(f.step)
      << ", FIT " << percent_text(f.fit_percent) << " once added)\n";
    if (!f.params.empty()) {
      o << "    parameters (" << kFinalStage << "):";
      for (std::size_t j = 0; j < f.params.size(); ++j)
        o << (j == 0 ? " " : ", ") << parameter_text(f, j);
      o << "\n";
    }
    for (const auto& q : f.derived)
      o << "    derived: " << q.name << " = " << value_text(q.value, q.unit) << "\n";
    for (const std::string& line : sensitivity_lines(f)) o << "    size: " << line << "\n";
    o << "    " << f.evidence << "\n";
    if (!f.ambiguous_with.empty())
      o << "    " << ambiguity_text(f, d) << "\n    to separate them: " << f.separating_measurement
        << "\n";
  }
  bool signed_header = false;
  for (const auto& c : d.candidates) {
    if (c.signed_params.empty()) continue;
    if (!signed_header) o << "signed sizes against the baseline (" << kSignedSizeStage << "):\n";
    signed_header = true;
    o << "  " << c.effect->name() << ": " << signed_size_text(c) << "\n";
  }
  if (d.reference) {
    o << reference_heading(*d.reference) << ":\n";
    if (d.reference->changes.empty()) o << "  no effect sized on both\n";
    for (const EffectChange& e : d.reference->changes) o << "  " << change_text(e) << "\n";
  }
  o << "final FIT " << percent_text(d.final_fit_percent) << " (" << kFinalStage << ")\n";
  o << "  nuisance (" << kFinalStage << "): " << nuisance_text(d.final_nuisance) << "\n";
  o << "unexplained: " << percent_text(100 * d.unexplained.share)
    << " of the final residual energy lies above the noise floor (noise rms "
    << value_text(d.unexplained.noise_sigma, unit) << ", residual rms "
    << value_text(d.unexplained.residual_rms, unit) << ")\n";
  for (const auto& note : d.notes) o << "note: " << note << "\n";
  return o.str();
}

std::string diagnosis_traces_csv(const Diagnosis& d) {
  std::ostringstream o;
  o.precision(10);
  o << "t,measured,baseline,final,residual_baseline,residual_final\n";
  for (std::size_t k = 0; k < d.t.size(); ++k) {
    const double y = d.measured[k], b = d.baseline.prediction[k], f = d.final_fit.prediction[k];
    o << d.t[k] << ',' << y << ',' << b << ',' << f << ',' << y - b << ',' << y - f << '\n';
  }
  return o.str();
}

std::string diagnosis_html(const Diagnosis& d) {
  const std::size_t n = d.t.size();
  std::vector<double> r0(n), r1(n);
  for (std::size_t k = 0; k < n; ++k) {
    r0[k] = d.measured[k] - d.baseline.prediction[k];
    r1[k] = d.measured[k] - d.final_fit.prediction[k];
  }
  std::vector<Band> bands;
  for (const auto& w : d.mismatch) bands.push_back({w.t_start, w.t_end});
  const std::string unit = output_unit(d);
  const std::string ylabel = d.output_column + " [" + unit + "]";
  std::ostringstream o;
  o << "<!DOCTYPE html>\n<html><head><meta charset='utf-8'><title>rheomag diagnosis</title>\n"
    << "<style>body{font-family:sans-serif;margin:20px;max-width:960px}"
       "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:3px 8px;"
       "text-align:left}h2{margin-top:28px}.ok{color:#1a7f37}.warn{color:#b35900}</style>"
       "</head><body>\n";
  o << "<h1>Diagnosis of " << html_escape(d.recording) << "</h1>\n";
  o << "<p>Output explained: <b>" << html_escape(d.output_column) << "</b>. Baseline FIT "
    << percent_text(d.baseline_fit_percent) << " (" << kCalibrationStage << ") &rarr; final FIT <b>"
    << percent_text(d.final_fit_percent) << "</b> (" << kFinalStage << ").</p>\n";
  o << "<h2>Missing physics</h2>\n";
  if (d.findings.empty()) {
    o << "<p class='ok'>None: the calibrated baseline explains the recording "
         "(no candidate passed both the held-out and the BIC test).</p>\n";
  } else {
    o << "<table><tr><th>#</th><th>effect</th><th>parameters (" << kFinalStage
      << ", &plusmn; 1 s.e.)</th><th>accepted at; FIT once added</th><th>evidence</th></tr>\n";
    int i = 1;
    for (const auto& f : d.findings) {
      o << "<tr><td>" << i++ << "</td><td><b>" << f.effect->name() << "</b>";
      o << "</td><td>";
      for (std::size_t j = 0; j < f.params.size(); ++j)
        o << html_escape(parameter_text(f, j, "\u00b1")) << "<br>";
      for (const auto& q : f.derived)
        o << "<i>derived:</i> " << html_escape(q.name + " = " + value_text(q.value, q.unit))
          << "<br>";
      for (const std::string& line : sensitivity_lines(f))
        o << "<i>size:</i> " << html_escape(line) << "<br>";
      o << "</td><td>" << selection_stage(f.step) << "; " << percent_text(f.fit_percent)
        << "</td><td>" << html_escape(f.evidence);
      if (!f.ambiguous_with.empty())
        o << "<br><span class='warn'>" << html_escape(ambiguity_text(f, d)) << "</span>";
      if (!f.separating_measurement.empty())
        o << "<br><i>To separate: " << html_escape(f.separating_measurement) << "</i>";
      o << "</td></tr>\n";
    }
    o << "</table>\n";
  }
  o << "<h2>Unexplained</h2>\n<p>" << percent_text(100 * d.unexplained.share)
    << " of the final residual energy lies above the white-noise floor (noise rms "
    << value_text(d.unexplained.noise_sigma, unit) << ", residual rms "
    << value_text(d.unexplained.residual_rms, unit) << "; that is "
    << html_number(100 * d.unexplained.baseline_share, 3)
    << " % of the baseline's residual energy): no candidate explains it.</p>\n";
  o << "<h2>What the baseline contained</h2>\n<table><tr><th>item</th><th>value</th>"
       "<th>source</th></tr>\n";
  for (const auto& item : d.includes)
    o << "<tr><td>" << html_escape(item.name) << "</td><td>"
      << (item.unit.empty() && item.value == 0.0
              ? std::string("&ndash;")
              : html_number(item.value) + " " + html_escape(item.unit))
      << "</td><td>" << html_escape(item.source) << "</td></tr>\n";
  const auto& u = d.final_nuisance;
  o << "</table>\n<h2>Recording nuisances (calibrated, not physics)</h2>\n<table>"
    << "<tr><th>stage</th><th>nuisances (delay positive: the output behind the drives)</th></tr>"
    << "<tr><td>" << kCalibrationStage << "</td><td>" << html_escape(nuisance_text(d.nuisance))
    << "</td></tr>\n<tr><td>" << kFinalStage << "</td><td>"
    << html_escape(nuisance_text(d.final_nuisance)) << "</td></tr>\n";
  o << "<tr><td>drive sampling (" << kFinalStage << ")</td><td>" << html_escape(u.sampling)
    << "</td></tr>\n";
  if (u.preyield_flow > 0.0)
    o << "<tr><td>pre-yield smoothness of the static map (" << kFinalStage
      << ")</td><td>plug switch width " << html_escape(value_text(u.preyield_flow, "m^3/s"))
      << "</td></tr>\n";
  if (std::isfinite(u.slit_fraction))
    o << "<tr><td>knee of the static map (" << kFinalStage << ")</td><td>slit_fraction "
      << html_number(u.slit_fraction)
      << " (0: the table's Bingham line; 1: the exact slit law with that line as its "
         "asymptote)</td></tr>\n";
  if (u.velocity_filter_bandwidth > 0.0)
    o << "<tr><td>noisy velocity smoothed (cubic Savitzky-Golay, zero phase)</td><td>-3 dB at "
      << html_number(u.velocity_filter_bandwidth) << " Hz</td></tr>\n";
  if (u.current_reversal_band > 0.0)
    o << "<tr><td>noisy current: the Duhem candidate follows its path (reversals beyond the "
         "noise)</td><td>reversal band "
      << html_escape(value_text(u.current_reversal_band, "A")) << "</td></tr>\n";
  for (const auto& [column, count] : u.motion_glitches)
    o << "<tr><td>single-sample glitches of drive " << html_escape(column)
      << " replaced by their neighbours' path</td><td>" << count
      << (count == 1 ? " sample" : " samples") << "</td></tr>\n";
  for (const auto& [column, sigma] : u.drive_noise)
    o << "<tr><td>noise on drive " << html_escape(column) << "</td><td>" << html_number(sigma)
      << " (rms, SI)</td></tr>\n";
  o << "</table>\n";
  o << "<h2>Measured, baseline and final model</h2>\n"
    << svg_plot("measured vs baseline vs final", ylabel, d.t,
                {{"measured", "#999", &d.measured},
                 {"baseline", "#d62728", &d.baseline.prediction},
                 {"final", "#1f77b4", &d.final_fit.prediction}},
                {}, d.t.front(), d.t.back());
  o << "<h2>Residual before and after (mismatch windows shaded)</h2>\n"
    << svg_plot("residual", ylabel, d.t,
                {{"baseline residual", "#d62728", &r0}, {"final residual", "#1f77b4", &r1}}, bands,
                d.t.front(), d.t.back());
  if (!d.mismatch.empty()) {
    const auto& w = d.mismatch.front();
    const double margin = 0.5 * (w.t_end - w.t_start);
    o << "<h2>Zoom on the worst window (" << html_number(w.t_start) << "&ndash;"
      << html_number(w.t_end) << " s, " << html_escape(w.regime) << ", "
      << percent_text(100 * w.share) << " of the residual energy)</h2>\n"
      << svg_plot("worst window", ylabel, d.t,
                  {{"measured", "#999", &d.measured},
                   {"baseline", "#d62728", &d.baseline.prediction},
                   {"final", "#1f77b4", &d.final_fit.prediction}},
                  {{w.t_start, w.t_end}}, w.t_start - margin, w.t_end + margin);
  }
  o << "<h2>Mismatch windows of the baseline</h2>\n<table><tr><th>t start [s]</th><th>t end "
       "[s]</th><th>share of residual</th><th>regime</th></tr>\n";
  for (const auto& w : d.mismatch)
    o << "<tr><td>" << html_number(w.t_start) << "</td><td>" << html_number(w.t_end) << "</td><td>"
      << percent_text(100 * w.share) << "</td><td>" << html_escape(w.regime) << "</td></tr>\n";
  o << "</table>\n<h2>Residual statistics of the baseline</h2>\n<p>Lag-1 autocorrelation "
    << html_number(d.baseline_stats.lag1_autocorrelation, 3)
    << ", Ljung&ndash;Box Q(20) = " << html_number(d.baseline_stats.ljung_box_q, 4) << " ("
    << (d.baseline_stats.white ? "white" : "not white")
    << "); after: " << (d.final_stats.white ? "white" : "not white")
    << ". Cross-correlation of the measured output with the calibrated baseline's prediction "
       "(its delay already applied): the output lags it by a further "
    << html_number(1e3 * d.baseline_stats.output_lag, 3)
    << " ms.</p>\n<table><tr><th>signal</th>"
       "<th>peak correlation with residual</th><th>lag [s]</th></tr>\n";
  for (const auto& c : d.baseline_stats.correlations)
    o << "<tr><td>" << html_escape(c.signal) << "</td><td>" << html_number(c.value, 3)
      << "</td><td>" << html_number(c.lag, 3) << "</td></tr>\n";
  o << "</table>\n<table><tr><th>loop (input, residual)</th><th>opening</th>"
       "<th>slow/fast</th><th>rate-independent</th></tr>\n";
  for (const auto& l : d.baseline_stats.loops)
    o << "<tr><td>" << html_escape(l.input) << "</td><td>" << html_number(l.opening, 3)
      << "</td><td>" << html_number(l.slow_fast_ratio, 3) << "</td><td>"
      << (l.rate_independent ? "yes" : "no") << "</td></tr>\n";
  o << "</table>\n<h2>Candidates tried (forward selection)</h2>\n<p>Each step fits every "
       "candidate on top of the model so far; screening comes first: a candidate whose "
       "parameter helps at no decade is scored there and not fitted. A candidate tied with the "
       "one accepted at a step is usually screened out at the next: the accepted one already "
       "explains what it would. The signed size is a candidate's size against the baseline with "
       "its sign free ("
    << kSignedSizeStage
    << ").</p>\n<table><tr><th>stage</th><th>effect</th><th>FIT "
       "(selection)</th><th>&Delta;BIC</th><th>outcome</th><th>signed size</th></tr>\n";
  for (const auto& c : d.candidates)
    o << "<tr><td>" << selection_stage(c.step) << "</td><td>" << c.effect->name() << "</td><td>"
      << (c.screened ? std::string("&ndash;") : percent_text(c.fit_percent)) << "</td><td>"
      << html_number(c.delta_bic, 4) << "</td><td>" << html_escape(candidate_outcome(c, d))
      << "</td><td>" << html_escape(signed_size_text(c)) << "</td></tr>\n";
  o << "</table>\n";
  if (d.reference) {
    o << "<h2>Change against the reference recording</h2>\n<p>"
      << html_escape(reference_heading(*d.reference)) << ".</p>\n<ul>";
    for (const EffectChange& e : d.reference->changes)
      o << "<li>" << html_escape(change_text(e)) << "</li>";
    o << "</ul>\n";
  }
  if (!d.notes.empty()) {
    o << "<h2>Notes</h2><ul>";
    for (const auto& note : d.notes) o << "<li>" << html_escape(note) << "</li>";
    o << "</ul>\n";
  }
  o << "</body></html>\n";
  return o.str();
}

void write_diagnosis_outputs(const Diagnosis& d, const std::string& dir) {
  // The three files replace the old diagnosis together: a failure keeps the old set whole.
  OutputSet set(dir, "--out");
  nlohmann::json document = diagnosis_json(d);
  stamp_version(document);
  const std::string json_name = (std::filesystem::path(dir) / "diagnosis.json").string();
  const auto text_file = [&set](const std::string& name, const std::string& text) {
    set.write(name, [&](const std::filesystem::path& to) { write_file_atomically(to, text); });
  };
  text_file("diagnosis.json", finite_json_text(document, json_name, 2) + "\n");
  text_file("report.html", diagnosis_html(d));
  text_file("traces.csv", diagnosis_traces_csv(d));
  set.commit();
}

}  // namespace rheomag::diagnose
