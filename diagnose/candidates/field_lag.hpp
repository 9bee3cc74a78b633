#pragma once
// What the two field-lag candidates share (mr_response_time, eddy_currents: one first-order lag
// between the coil current and the yield stress, told apart only by a flux measurement), and the
// first-order lag block they and coil_inductance put on a fitted model's field input.

#include <vector>

#include "diagnose/candidate.hpp"

namespace rheomag::diagnose::candidates {

/// First-order lag tau y' = u - y of the samples `u` at times `t`, exact for an input linear
/// between samples; starts at rest (y = u).
std::vector<double> first_order_lag(const std::vector<double>& t, const std::vector<double>& u,
                                    double tau);

/// A first-order lag of the field behind the coil current (one time constant): where it applies,
/// its parameter, its block on a fitted model's field input, its evidence and its timing check.
/// The derived candidate names it and switches it on in the rig.
class FieldLag : public Candidate {
 public:
  bool applies(const DiagnosisModel& model) const override;
  std::vector<ParamDef> params(const DiagnosisModel& model) const override;
  bool composes_with_fitted_model() const override { return true; }
  void compose_with_model(FittedModelBlocks& blocks, ParamReader& values,
                          const DiagnosisModel& model) const override;
  std::string evidence(const Diagnosis& d, const ModelFit& fit) const override;
  double timing_lag(const DiagnosisModel& model, const ModelFit& fit) const override;
};

}  // namespace rheomag::diagnose::candidates
