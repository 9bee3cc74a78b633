// Python: rheomag.Recording (numpy columns) and fit, fit_family, simulate, diagnose — dicts built
// by the library functions behind the CLI's --json.

#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "diagnose/diagnose_report.hpp"
#include "diagnose/diagnose_run.hpp"
#include "identify/current_dependent_fit.hpp"
#include "identify/family_fit_output.hpp"
#include "identify/fit_model_json.hpp"
#include "identify/fit_run.hpp"
#include "identify/motion_lead_search.hpp"
#include "identify/simulate_run.hpp"
#include "lumped/metrics.hpp"
#include "lumped/recording_excerpt.hpp"
#include "lumped/recording_io.hpp"
#include "python/bindings.hpp"

namespace rheomag::python {

namespace {

/// Reads a recording and passes the reader's warnings to Python's warnings module.
lumped::Recording load_recording(const std::string& csv_path) {
  lumped::Recording rec;
  {
    py::gil_scoped_release release;
    rec = lumped::read_recording(csv_path);
  }
  for (const std::string& w : rec.warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, ("rheomag: " + w).c_str(), 1) != 0)
      throw py::error_already_set();  // warnings filtered as errors
  return rec;
}

/// The `hold` argument {name: SI value} as GreyboxOptions::held (sorted by name).
std::vector<std::pair<std::string, double>> holds(const std::map<std::string, double>& hold) {
  return {hold.begin(), hold.end()};
}

/// The `motion_lead` argument as --motion-lead: "auto" (the default leads to search) or a lead in
/// seconds within +-0.1 s.
void read_motion_lead(const py::object& motion_lead, double& lead, std::vector<double>& leads) {
  if (py::isinstance<py::str>(motion_lead)) {
    if (motion_lead.cast<std::string>() != "auto")
      throw InputError("motion_lead: expected \"auto\" or a lead in seconds, got \"" +
                       motion_lead.cast<std::string>() + "\"");
    leads = identify::default_motion_leads();
    return;
  }
  lead = motion_lead.cast<double>();
  if (!(std::abs(lead) <= 0.1))
    throw InputError("motion_lead: expected a lead within +-0.1 s, got " + std::to_string(lead));
}

py::object fit(const std::string& recording, const std::string& model, const std::string& train,
               const std::string& validate, const std::string& mode, const py::object& progress,
               const std::map<std::string, double>& hold, bool keep_inertance,
               const py::object& motion_lead) {
  identify::FitRequest request;
  request.held = holds(hold);
  request.keep_inertance = keep_inertance;
  read_motion_lead(motion_lead, request.motion_lead, request.motion_leads);
  request.recording = recording;
  request.model = model;
  request.train = train;
  request.validate = validate;
  if (mode == "prediction")
    request.mode = identify::EvalMode::prediction;
  else if (mode != "simulation")
    throw InputError("mode: expected \"simulation\" or \"prediction\", got \"" + mode + "\"");
  request.progress = progress_to_python(progress);
  // Warnings of recordings read on the solving thread are not shown (no GIL there).
  request.load_recording = [](const std::string& path) { return lumped::read_recording(path); };
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    j = identify::fit_run_json(identify::run_fit(request));
  }
  return to_python(j);
}

py::object fit_family(const std::vector<std::string>& recordings, const std::string& model,
                      const std::vector<std::string>& predict, int decimation, int starts,
                      double max_substep, bool cross_validate, const py::object& progress,
                      const std::map<std::string, double>& hold, bool keep_inertance,
                      const py::object& motion_lead) {
  std::vector<lumped::Recording> training, prediction;
  for (const std::string& f : recordings) training.push_back(load_recording(f));
  for (const std::string& f : predict) prediction.push_back(load_recording(f));
  if (training.empty()) throw InputError("recordings: expected at least one recording");
  identify::FamilyFitOptions options;
  options.decimation = decimation;
  options.greybox.starts = starts;
  options.greybox.held = holds(hold);
  if (keep_inertance) options.greybox.min_inertance_gain = 0.0;
  options.greybox.max_substep = max_substep;
  options.cross_validate = cross_validate;
  read_motion_lead(motion_lead, options.greybox.motion_lead, options.motion_leads);
  options.greybox.progress = progress_to_python(progress);
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    if (!identify::is_greybox_model(model))
      throw InputError("model: '" + model + "' is not a grey-box model");
    for (const lumped::Recording& r : training) r.require_varying(r.meta.output);
    const identify::FamilyFit r =
        identify::fit_current_dependent(training, model, prediction, options);
    j = identify::family_fit_json(r, training.front().meta, decimation, cross_validate);
  }
  return to_python(j);
}

py::object diagnose_recording(const std::string& recording, const std::string& samples,
                              const std::string& baseline, const std::string& out,
                              const py::object& progress, const std::string& reference) {
  lumped::Recording rec = load_recording(recording);
  diagnose::DiagnoseOptions options;
  if (!reference.empty()) options.reference = load_recording(reference);  // holds the GIL
  options.progress = progress_to_python(progress);
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    if (!samples.empty())
      rec = lumped::excerpt(rec, lumped::parse_sample_range(samples, rec.t.size(), "samples"));
    if (!baseline.empty())
      options.baseline_model =
          diagnose::ModelBaseline{identify::read_fit_model_json(baseline), baseline};
    const diagnose::Diagnosis d = diagnose::diagnose(rec, options);
    if (!out.empty()) diagnose::write_diagnosis_outputs(d, out);
    j = diagnose::diagnosis_json(d);
  }
  return to_python(j);
}

lumped::Recording simulate(const std::string& spec, const std::string& input,
                           const std::vector<std::string>& signals, double duration, double rate,
                           const std::string& out) {
  identify::SimulateRequest request{spec, input, signals, duration, rate, {}};
  std::vector<identify::RangeExcess> beyond;
  lumped::Recording rec;
  {
    py::gil_scoped_release release;
    rec = identify::run_simulate(request, &beyond);
    if (!out.empty()) lumped::write_recording(rec, out);
  }
  // A drive beyond the model's training drive is a UserWarning: the result stands, but it is the
  // model's extrapolation.
  for (const identify::RangeExcess& e : beyond) {
    const std::string text = input + " beyond the drive " + spec + " was fitted on: " + e.text();
    if (PyErr_WarnEx(PyExc_UserWarning, text.c_str(), 1) != 0) throw py::error_already_set();
  }
  return rec;
}

}  // namespace

void bind_identify(py::module_& m) {
  py::class_<lumped::Recording>(m, "Recording",
                                "A recording (CSV + TOML sidecar): time base and SI columns.")
      .def_static("load", &load_recording, py::arg("path"),
                  "Reads REC.csv and its sidecar REC.toml; ValueError on bad input.")
      .def_property_readonly(
          "t", [](const lumped::Recording& r) { return to_numpy(r.t); }, "time [s]")
      .def_property_readonly(
          "columns",
          [](const lumped::Recording& r) {
            py::dict d;
            for (const auto& [name, values] : r.columns) d[py::str(name)] = to_numpy(values);
            return d;
          },
          "{name: numpy array} of the known columns, SI")
      .def_property_readonly("drive", [](const lumped::Recording& r) { return r.meta.drive; })
      .def_property_readonly("output", [](const lumped::Recording& r) { return r.meta.output; })
      .def_property_readonly("path", [](const lumped::Recording& r) { return r.csv_path; });

  m.def("fit", &fit, py::arg("recording"), py::arg("model"), py::arg("train") = "",
        py::arg("validate") = "", py::arg("mode") = "simulation", py::arg("progress") = py::none(),
        py::arg("hold") = std::map<std::string, double>{}, py::arg("keep_inertance") = false,
        py::arg("motion_lead") = "auto",
        "Fits `model` to the recording CSV (as `rheomag fit REC --model M --json`); the dict of "
        "that JSON. progress(event: dict) is called during grey-box fits; hold {name: SI value} "
        "holds grey-box parameters (as --hold); keep_inertance as --keep-inertance; "
        "motion_lead \"auto\" or seconds as --motion-lead.");
  m.def("fit_family", &fit_family, py::arg("recordings"), py::arg("model"),
        py::arg("predict") = std::vector<std::string>{}, py::arg("decimation") = 4,
        py::arg("starts") = 2, py::arg("max_substep") = 2e-3, py::arg("cross_validate") = false,
        py::arg("progress") = py::none(), py::arg("hold") = std::map<std::string, double>{},
        py::arg("keep_inertance") = false, py::arg("motion_lead") = "auto",
        "One grey-box fit over several recordings (as `rheomag fit-family ... --json`); hold "
        "{name: SI value} holds parameters (as --hold); keep_inertance as --keep-inertance; "
        "motion_lead \"auto\" or seconds as --motion-lead.");
  m.def("simulate", &simulate, py::arg("spec"), py::arg("input") = "",
        py::arg("signals") = std::vector<std::string>{}, py::arg("duration") = 10.0,
        py::arg("rate") = 1000.0, py::arg("out") = "",
        "Runs a lumped model spec (TOML) or a fitted model (JSON) on the recording `input` or on "
        "generated `signals` (duration [s], rate [Hz]), as `rheomag simulate`; returns the "
        "simulated Recording (and writes it to `out`, CSV + sidecar, when given).");
  m.def("diagnose", &diagnose_recording, py::arg("recording"), py::arg("samples") = "",
        py::arg("baseline") = "", py::arg("out") = "", py::arg("progress") = py::none(),
        py::arg("reference") = "",
        "The physics a recording shows and its baseline model leaves out (as `rheomag diagnose "
        "REC --json`; samples 'a:b', baseline a fitted-model JSON, reference an earlier "
        "recording of the device to difference the effects' sizes against, out a folder for "
        "diagnosis.json, report.html, traces.csv).");
}

}  // namespace rheomag::python
