# rheomag_library_headers(LIB): rheomag_LIB exposes only its own headers. Its include folder is
# build/include/LIB, holding one link LIB -> the source folder, so `#include "LIB/x.hpp"` works
# for the library and for what links it, and an include of a folder the library does not link
# (an upward include against docs/architecture.md) does not compile. Installed, the headers are
# in include/rheomag/LIB (cmake/rheomag_install.cmake), so the same #include works.
function(rheomag_library_headers lib)
  set(dir ${CMAKE_BINARY_DIR}/include/${lib})
  if(NOT EXISTS ${dir}/${lib})
    file(MAKE_DIRECTORY ${dir})
    file(CREATE_LINK ${CMAKE_SOURCE_DIR}/${lib} ${dir}/${lib} SYMBOLIC)
  endif()
  target_include_directories(rheomag_${lib} PUBLIC $<BUILD_INTERFACE:${dir}>
                             $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/rheomag>)
endfunction()
