#pragma once
// The TOML model spec of `rheomag simulate` (the "virtual rig"): a rig built from lumped blocks
// with switchable concealed effects and sensor noise, or a ready phenomenological model / TF14.
// The format is documented in docs/dynamics.md; examples are in cases/rigs/.

#include <optional>
#include <string>
#include <vector>

#include "case/case_sections.hpp"
#include "lumped/pheno_simulation.hpp"
#include "lumped/recording.hpp"
#include "lumped/rig_model.hpp"

namespace rheomag::coupling {

/// [lumped] and [identify] are case-file sections reserved for this layer (docs/case-format.md).
inline const bool kLumpedSectionsRegistered =
    cases::register_case_section("lumped") && cases::register_case_section("identify");

/// A phenomenological model with given parameters (from [model] of a spec).
struct PhenoSpec {
  lumped::GreyboxSetup setup;
  std::vector<double> params;  ///< in the order of pheno_params(kind)
};

/// A parsed simulation spec: exactly one of rig, pheno, tf14 or lugre_paper001 is active.
struct SimulationSpec {
  std::string path;
  std::optional<lumped::RigSpec> rig;
  std::optional<PhenoSpec> pheno;
  bool tf14 = false;              ///< paper 000 Table 7 transfer function, current -> pressure
  bool lugre_paper001 = false;    ///< paper 001 eqs. 8-9 + Table 3, velocity + current -> pressure
  double piston_area = 4.524e-4;  ///< [m^2] lugre_paper001: flow = piston_area x velocity
  std::map<std::string, double> sensor_noise;
  unsigned noise_seed = 1;
};

/// Reads a spec file; throws InputError naming the file and key for anything malformed or unknown.
SimulationSpec read_simulation_spec(const std::string& path);

/// Columns the spec's model is driven by.
std::vector<std::string> spec_drive_columns(const SimulationSpec& spec);

/// Runs the spec on the drive columns of `drive`; returns a recording in the fixed format.
lumped::Recording simulate_spec(const SimulationSpec& spec, const lumped::Recording& drive);

}  // namespace rheomag::coupling
