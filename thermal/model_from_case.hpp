#pragma once
// The thermal model of a problem: which regions conduct heat and with what properties (a coil
// region as a winding of copper in insulation), and which condition holds on each outer surface.

#include "case/problem.hpp"
#include "thermal/heat_model.hpp"
#include "thermal/thermal_spec.hpp"

namespace rheomag::thermal {

/// Conductivity and volumetric heat capacity of a region.
struct Conduction {
  double conductivity = 0.0;   ///< [W/(m K)]
  double heat_capacity = 0.0;  ///< [J/(m^3 K)]
};

/// A winding of round wires (conductivity `wire`, area fraction `fill`) in a matrix of enamel,
/// varnish and voids, across its wires (the meridian plane of an axisymmetric coil): the
/// Maxwell-Garnett / Hashin-Shtrikman lower bound for parallel cylinders,
/// k = k_m (k_w + k_m + fill (k_w - k_m)) / (k_w + k_m - fill (k_w - k_m)), and the volume-weighted
/// heat capacity. It underestimates k near the densest packing (fill > 0.7).
Conduction winding_conduction(const Conduction& wire, const Conduction& matrix, double fill);

/// The HeatModel of `problem` (the closed domain the mesh was made from): a region takes part
/// when its material has thermal data (spec.materials first, then the materials library); a coil
/// region is a winding with copper fill `copper_fill`. Surface 0 ("outer surfaces") is convection
/// with spec.convection to spec.ambient; each [[thermal.surface]] rule follows, later rules
/// winning. InputError naming the region when a coil or fluid-gap region has no thermal data.
HeatModel build_heat_model(const cases::Problem& problem, const ThermalSpec& spec,
                           double copper_fill);

}  // namespace rheomag::thermal
