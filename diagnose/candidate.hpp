#pragma once
// One candidate: a piece of physics the diagnosis may name as missing from the baseline. Each
// candidate lives in its own file under diagnose/candidates/ and is listed once in
// candidate_registry.cpp; the selection, the fit and the report ask it everything that is
// particular to it through this interface and name no candidate themselves.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "diagnose/diagnose_model.hpp"
#include "lumped/recording.hpp"
#include "lumped/rig_model.hpp"

namespace rheomag::diagnose {

struct Diagnosis;
struct ModelFit;

/// Reads the parameter values of the candidates of a layout one after the other (each candidate
/// takes its own, in the order of its params()).
class ParamReader {
 public:
  /// Reads `values` from index `first` on.
  ParamReader(const std::vector<double>& values, std::size_t first)
      : values_(values), next_(first) {}
  /// The next value (std::out_of_range past the end).
  double next() { return values_.at(next_++); }

 private:
  const std::vector<double>& values_;
  std::size_t next_;
};

/// What a candidate acts on when the baseline is a fitted model: the model's inputs (the
/// recording it is run on) and its output (a term added to the model's calibrated output).
struct FittedModelBlocks {
  lumped::Recording& inputs;          ///< the recording the model runs on (columns replaceable)
  std::vector<double>& added_output;  ///< added to the model's scaled and offset output
  const std::string& field_column;    ///< the model's field drive column ("" if none)
  double sign = 1.0;                  ///< sign of the model output's correlation with the velocity
};

/// A quantity derived from a candidate's fitted parameters (e.g. a damper's moving mass).
struct DerivedParam {
  std::string name;
  double value = 0.0;  ///< SI
  std::string unit;    ///< SI unit ("1" when dimensionless)
};

/// A piece of candidate physics (abstract): its name, where it applies, its parameters, how it
/// composes with either kind of baseline, its report text and the rules particular to it (each
/// a virtual hook with a neutral default).
class Candidate {
 public:
  virtual ~Candidate() = default;

  /// Name in the diagnosis output ("compressibility", ...).
  virtual std::string name() const = 0;

  /// True when it can show in `model`'s recording on `model`'s baseline (a sidecar rig or a
  /// fitted model: rig kind, drive mode, columns, noise...).
  virtual bool applies(const DiagnosisModel& model) const = 0;

  /// Parameters it adds (SI, with units), start values scaled to `model`'s recording; the first
  /// is its size (the one whose identifiability is checked and whose decades are screened).
  virtual std::vector<ParamDef> params(const DiagnosisModel& model) const = 0;

  /// Switches it on in the sidecar baseline's rig `spec`, its parameter values read from `values`.
  virtual void switch_on(lumped::RigSpec& spec, ParamReader& values,
                         const DiagnosisModel& model) const = 0;

  /// True when it can be composed with a fitted-model baseline (compose_with_model).
  virtual bool composes_with_fitted_model() const { return false; }

  /// True when on `model` it adds to the output a term linear in its size (its only parameter),
  /// so that the size can also be fitted with its sign free: a recording with less of it than
  /// the baseline comes out negative (CandidateScore::signed_params).
  virtual bool linear_in_size(const DiagnosisModel& /*model*/) const { return false; }

  /// Adds it to a fitted-model baseline as a block on the model's inputs or output, its values
  /// read from `values`. The default throws InputError (see composes_with_fitted_model()).
  virtual void compose_with_model(FittedModelBlocks& blocks, ParamReader& values,
                                  const DiagnosisModel& model) const;

  /// The evidence sentence of a finding of it in `d`, its values as in `fit` (the final model);
  /// the residual's strongest correlation is appended by the caller.
  virtual std::string evidence(const Diagnosis& d, const ModelFit& fit) const = 0;

  /// What measurement would tell it from `other` when both explain the data almost equally; ""
  /// when it has nothing particular to say (the pair is then asked the other way round, and
  /// failing that a generic advice is given).
  virtual std::string separating_measurement(const Candidate& /*other*/) const { return ""; }

  /// Quantities derived from its fitted `params` on `model` that the JSON report gives beside
  /// them (SI).
  virtual std::vector<DerivedParam> derived_params(const DiagnosisModel& /*model*/,
                                                   const std::vector<double>& /*params*/) const {
    return {};
  }

  /// Name of a candidate that is the same block in the rig model ("" if none): while that one
  /// is not in the model and was fitted at this step, this one's fit is that one's renamed.
  virtual std::string same_block_as() const { return ""; }

  /// Start values of its first parameter measured on the recording (e.g. fluid_inertia's
  /// ringing), scored beside the decade grid of its bounds; `current` is the model it is
  /// added to.
  virtual std::vector<double> measured_starts(const DiagnosisModel& /*model*/,
                                              const ModelFit& /*current*/) const {
    return {};
  }

  /// [s] Time constant it adds in `fit` (whose last effect it is) that the recording's own
  /// timing, absorbed by the delay nuisance, could mimic when shorter than a sample (0: none).
  virtual double timing_lag(const DiagnosisModel& /*model*/, const ModelFit& /*fit*/) const {
    return 0.0;
  }

  /// Why its fit `fit` (whose last effect it is) is not told apart from the recording's noise
  /// or timing, continuing a sentence that names it ("": nothing speaks against it).
  virtual std::string implausible(const DiagnosisModel& /*model*/, const ModelFit& /*fit*/) const {
    return "";
  }

  /// True when it remembers the path of the coil current (a rate-independent loop): it is then
  /// driven by the noise-robust path of a noisy measured current (DiagnosisModel::current_path),
  /// since white noise would reverse it at every sample and erase its memory.
  virtual bool follows_current_path() const { return false; }

  /// True when its size rests on the chamber volume (a note says when the sidecar lacks it).
  virtual bool uses_chamber_volume() const { return false; }
};

}  // namespace rheomag::diagnose
