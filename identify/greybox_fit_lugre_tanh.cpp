// The Ceres fit of the nine-parameter models (LuGre, hyperbolic tangent), one instantiation per
// free-parameter count (with and without the field terms and output smoothing; greybox.cpp
// dispatches to them).

#include "identify/greybox_run_fit.hpp"

namespace rheomag::identify::greybox_detail {

template void run_fit<9, 9>(const FitData&, const lumped::GreyboxSetup&, const ParamGuess&,
                            const GreyboxOptions&, GreyboxFit&);
template void run_fit<9, 8>(const FitData&, const lumped::GreyboxSetup&, const ParamGuess&,
                            const GreyboxOptions&, GreyboxFit&);
template void run_fit<9, 7>(const FitData&, const lumped::GreyboxSetup&, const ParamGuess&,
                            const GreyboxOptions&, GreyboxFit&);
template void run_fit<9, 6>(const FitData&, const lumped::GreyboxSetup&, const ParamGuess&,
                            const GreyboxOptions&, GreyboxFit&);

}  // namespace rheomag::identify::greybox_detail
