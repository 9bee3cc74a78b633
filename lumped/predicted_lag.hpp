#pragma once
// The field lag of a valve predicted from its drawing (coupling/field_lag_prediction.hpp: FE step
// responses with eddy currents, docs/transient.md) as a current-dependent first-order lag for the
// rigs' eddy_currents block.

#include <vector>

namespace rheomag::lumped {

/// A first-order lag whose time constant depends on the current it is driven towards.
struct PredictedLag {
  std::vector<double> current;        ///< [A], increasing, > 0
  std::vector<double> time_constant;  ///< [s] at each current
  /// Time constant at |current| (linear interpolation, held beyond the ends).
  double at(double current) const;
};

}  // namespace rheomag::lumped
