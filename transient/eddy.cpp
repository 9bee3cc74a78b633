#include "transient/eddy.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace rheomag::transient {

bool EddyCoefficients::none() const {
  auto zero = [](double v) { return v == 0.0; };
  return std::all_of(sigma.begin(), sigma.end(), zero) &&
         std::all_of(kappa.begin(), kappa.end(), zero);
}

namespace {

std::string region_name(const cases::Problem& problem, std::size_t k) {
  const auto& seeds = problem.geometry.regions;
  return k < seeds.size() && !seeds[k].name.empty() ? seeds[k].name : "#" + std::to_string(k);
}

}  // namespace

EddyCoefficients eddy_coefficients(const cases::Problem& problem,
                                   const std::vector<RegionEddy>& remedies) {
  const std::string& where = problem.geometry.source;
  const std::size_t regions = problem.regions.size();
  EddyCoefficients out;
  out.sigma.assign(regions, 0.0);
  out.kappa.assign(regions, 0.0);
  for (std::size_t k = 0; k < regions; ++k) {
    const cases::RegionData& data = problem.regions[k];
    if (data.circuit >= 0 && data.turns != 0.0) continue;  // stranded: no eddy current
    if (data.material < 0 || data.material >= static_cast<int>(problem.materials.size())) continue;
    const cases::Material& m = problem.materials[data.material];
    if (!m.conductivity)
      throw InputError(where + ": material '" + m.name + "' of region '" + region_name(problem, k) +
                       "' states no conductivity; a transient solve needs it (key conductivity "
                       "[S/m], 0 for an insulator)");
    if (!(*m.conductivity >= 0.0) || !std::isfinite(*m.conductivity))
      throw InputError(where + ": material '" + m.name + "' has conductivity " +
                       std::to_string(*m.conductivity) + " S/m; expected a finite number >= 0");
    out.sigma[k] = *m.conductivity;
  }
  for (const RegionEddy& remedy : remedies) {
    std::size_t k = 0;
    while (k < regions && region_name(problem, k) != remedy.region) ++k;
    if (k == regions)
      throw InputError(where + ": eddy-current remedy for region '" + remedy.region +
                       "', which the case does not have");
    const std::string what = where + ": region '" + remedy.region + "' (" +
                             std::string(kEddyModelNames.name(remedy.model)) + ")";
    const double sigma = out.sigma[k];
    switch (remedy.model) {
      case EddyModel::solid:
        break;
      case EddyModel::slotted:
        if (!(remedy.factor >= 0.0 && remedy.factor <= 1.0))
          throw InputError(what + ": factor must be in [0, 1]");
        out.sigma[k] = sigma * remedy.factor;
        break;
      case EddyModel::laminated:
      case EddyModel::sintered:
        if (!(remedy.size > 0.0) || !std::isfinite(remedy.size))
          throw InputError(what + ": size must be a finite length > 0");
        out.sigma[k] = 0.0;
        out.kappa[k] = sigma * remedy.size * remedy.size /
                       (remedy.model == EddyModel::laminated ? 12.0 : 20.0);
        break;
    }
  }
  return out;
}

}  // namespace rheomag::transient
