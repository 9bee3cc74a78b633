#pragma once
// Where eddy currents flow: the conductivity of every region for the transient solver, with
// the designers' remedies (slots, laminations, sintered powder) as homogenised models.

#include <string>
#include <vector>

#include "case/problem.hpp"
#include "core/enum_names.hpp"

namespace rheomag::transient {

/// How the azimuthal eddy currents of one region flow (docs/transient.md, "Remedies").
enum class EddyModel {
  solid,      ///< the material's conductivity everywhere in the region
  slotted,    ///< insulating cuts: sigma x `factor` (0 = a full radial slot)
  laminated,  ///< sheets of thickness `size`: no macroscopic path, sheet loss sigma size^2 / 12
  sintered,   ///< insulated particles of diameter `size` (SMC): particle loss sigma size^2 / 20
};

/// Text names of EddyModel (case files).
inline constexpr auto kEddyModelNames = enum_names<EddyModel>({{EddyModel::solid, "solid"},
                                                               {EddyModel::slotted, "slotted"},
                                                               {EddyModel::laminated, "laminated"},
                                                               {EddyModel::sintered, "sintered"}});

/// The remedy of one region (case option [[transient.region]]).
struct RegionEddy {
  std::string region;  ///< region name
  EddyModel model = EddyModel::solid;
  double factor = 1.0;  ///< slotted: conductivity reduction in [0, 1]
  double size = 0.0;    ///< laminated / sintered: sheet or particle size [m]
};

/// Per-region coefficients of the transient weak form (index as Problem::regions):
///   integral sigma dA/dt v dV + integral kappa dB/dt . B(v) dV + integral nu B . B(v) dV = ...
struct EddyCoefficients {
  std::vector<double> sigma;  ///< macroscopic conductivity [S/m] (0 in stranded coils)
  std::vector<double> kappa;  ///< homogenised micro-eddy coefficient H = kappa dB/dt [S m]
  /// True when no region conducts: the field follows the current without delay.
  bool none() const;
};

/// The coefficients of `problem`'s regions: stranded coil regions (turns != 0) carry no eddy
/// current; every other region takes its material's conductivity, modified by its remedy.
/// InputError when a non-coil region's material has no conductivity (Material::conductivity
/// empty; the automatic air has 0), a negative or non-finite one, a remedy names no region, has
/// a factor outside [0, 1] or a size <= 0.
EddyCoefficients eddy_coefficients(const cases::Problem& problem,
                                   const std::vector<RegionEddy>& remedies);

}  // namespace rheomag::transient
