#pragma once
// A circuit's flux linkage and inductances against its current.

#include <string>
#include <vector>

#include "magnetostatics/solver.hpp"
#include "plot/figure.hpp"

namespace rheomag::figures {

/// lambda(I) [mWb] above, the secant and incremental inductance L(I) [mH] below, of circuit
/// `circuit` from a current sweep.
plot::Figure inductance_figure(const std::vector<magnetostatics::SweepPoint>& sweep,
                               const std::string& circuit, int width, int height);

}  // namespace rheomag::figures
