#pragma once
// OpenMP regions that run inline, without a libgomp team, inside a SerialOpenMp scope.

namespace rheomag::magnetostatics {

/// Number of SerialOpenMp scopes alive on this thread that run the OpenMP regions opened on it
/// inline (0: regions go to libgomp as usual).
int& inline_openmp_depth();

/// True unless RHEOMAG_INLINE_OPENMP=0: whether SerialOpenMp runs regions inline.
bool inline_openmp_enabled();

/// OpenMP regions run inline on this thread so far.
long inline_openmp_regions();

}  // namespace rheomag::magnetostatics
