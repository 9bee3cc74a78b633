// The Ceres fit of the physically based damper model (18 parameters), one instantiation per
// free-parameter count (with and without the field terms and output smoothing; greybox.cpp
// dispatches to them).

#include "identify/greybox_run_fit.hpp"

namespace rheomag::identify::greybox_detail {

template void run_fit<18, 18>(const FitData&, const lumped::GreyboxSetup&, const ParamGuess&,
                              const GreyboxOptions&, GreyboxFit&);
template void run_fit<18, 17>(const FitData&, const lumped::GreyboxSetup&, const ParamGuess&,
                              const GreyboxOptions&, GreyboxFit&);
template void run_fit<18, 16>(const FitData&, const lumped::GreyboxSetup&, const ParamGuess&,
                              const GreyboxOptions&, GreyboxFit&);
template void run_fit<18, 12>(const FitData&, const lumped::GreyboxSetup&, const ParamGuess&,
                              const GreyboxOptions&, GreyboxFit&);
template void run_fit<18, 11>(const FitData&, const lumped::GreyboxSetup&, const ParamGuess&,
                              const GreyboxOptions&, GreyboxFit&);

}  // namespace rheomag::identify::greybox_detail
