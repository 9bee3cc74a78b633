// The Ceres fit of the seven-parameter models (Bingham, bi-viscous, Maxwell, Dahl), one
// instantiation per free-parameter count (with and without the field terms and output smoothing;
// greybox.cpp dispatches to them).

#include "identify/greybox_run_fit.hpp"

namespace rheomag::identify::greybox_detail {

template void run_fit<7, 7>(const FitData&, const lumped::GreyboxSetup&, const ParamGuess&,
                            const GreyboxOptions&, GreyboxFit&);
template void run_fit<7, 6>(const FitData&, const lumped::GreyboxSetup&, const ParamGuess&,
                            const GreyboxOptions&, GreyboxFit&);
template void run_fit<7, 5>(const FitData&, const lumped::GreyboxSetup&, const ParamGuess&,
                            const GreyboxOptions&, GreyboxFit&);
template void run_fit<7, 4>(const FitData&, const lumped::GreyboxSetup&, const ParamGuess&,
                            const GreyboxOptions&, GreyboxFit&);

}  // namespace rheomag::identify::greybox_detail
