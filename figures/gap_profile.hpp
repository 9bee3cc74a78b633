#pragma once
// B along one fluid gap: its components on the mid-line and on the walls against s.

#include "magnetostatics/results.hpp"
#include "plot/figure.hpp"

namespace rheomag::figures {

/// B_n and B_t [T] on the mid-line (solid) and on the two walls (dashed) of `gap` against the
/// distance s [mm] along it, with |B| on the mid-line, its mean and the gap's area average
/// B_avg marked.
plot::Figure gap_profile_figure(const magnetostatics::GapResult& gap, int width, int height);

}  // namespace rheomag::figures
