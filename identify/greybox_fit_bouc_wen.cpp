// The Ceres fit of the modified Bouc-Wen model (14 parameters), one instantiation per
// free-parameter count (with and without the field terms and output smoothing; greybox.cpp
// dispatches to them).

#include "identify/greybox_run_fit.hpp"

namespace rheomag::identify::greybox_detail {

template void run_fit<14, 13>(const FitData&, const lumped::GreyboxSetup&, const ParamGuess&,
                              const GreyboxOptions&, GreyboxFit&);
template void run_fit<14, 12>(const FitData&, const lumped::GreyboxSetup&, const ParamGuess&,
                              const GreyboxOptions&, GreyboxFit&);
template void run_fit<14, 9>(const FitData&, const lumped::GreyboxSetup&, const ParamGuess&,
                             const GreyboxOptions&, GreyboxFit&);
template void run_fit<14, 8>(const FitData&, const lumped::GreyboxSetup&, const ParamGuess&,
                             const GreyboxOptions&, GreyboxFit&);

}  // namespace rheomag::identify::greybox_detail
