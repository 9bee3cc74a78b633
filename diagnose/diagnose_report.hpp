#pragma once
// Outputs of a diagnosis in a folder: diagnosis.json, a self-contained report.html (inline SVG
// plots) and traces.csv (measured, baseline and final model, residuals).

#include <string>

#include "diagnose/diagnose_run.hpp"

namespace rheomag::diagnose {

/// The plain-text summary of `rheomag diagnose`: each value labelled with the stage it comes from
/// (baseline calibration, selection step N, final fit), parameters with units, FIT to 0.1 %.
std::string diagnosis_text(const Diagnosis& d);

/// The report as one self-contained HTML page (inline SVG, no external resources).
std::string diagnosis_html(const Diagnosis& d);

/// The traces as CSV: t, measured, baseline, final, residual_baseline, residual_final.
std::string diagnosis_traces_csv(const Diagnosis& d);

/// Writes diagnosis.json, report.html and traces.csv into `dir` (created if needed), each
/// atomically (temp file + rename); throws InputError if the folder cannot be written.
void write_diagnosis_outputs(const Diagnosis& d, const std::string& dir);

}  // namespace rheomag::diagnose
