#pragma once
// The step response of a transient run: current, flux linkage and the gaps' |B| against time.

#include <string>

#include "plot/figure.hpp"
#include "transient/transient_solver.hpp"

namespace rheomag::figures {

/// Three panels against t [ms]: the first circuit's current I(t), its flux linkage lambda(t) and
/// each gap's mean |B|(t), each with the flux linkage's t63 and t90 marked (when reached).
plot::Figure transient_step_figure(const transient::TransientResult& result,
                                   const std::string& title, int width, int height);

}  // namespace rheomag::figures
