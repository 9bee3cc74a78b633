# Install rules (issue 30, docs/library.md): `cmake --install build --prefix P` puts
#   P/bin/rheomag, P/lib/librheomag_LIB.so (or .a with -DBUILD_SHARED_LIBS=OFF),
#   P/include/rheomag/LIB/*.hpp, P/share/rheomag/materials/*.toml (read by the installed
#   libraries, case/material_library.cpp), P/lib/cmake/rheomag/rheomagConfig.cmake with the
#   imported targets rheomag::LIB, and P/lib/pkgconfig/rheomag.pc.
include(CMakePackageConfigHelpers)
set(RHEOMAG_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/rheomag)

set(targets)
foreach(lib ${RHEOMAG_LIBRARIES})
  set_target_properties(rheomag_${lib} PROPERTIES EXPORT_NAME ${lib})
  list(APPEND targets rheomag_${lib})
  install(DIRECTORY ${CMAKE_SOURCE_DIR}/${lib}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/rheomag/${lib}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
install(TARGETS ${targets} EXPORT rheomagTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS rheomag RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/cases/materials/
        DESTINATION ${CMAKE_INSTALL_DATADIR}/rheomag/materials FILES_MATCHING PATTERN "*.toml")
install(EXPORT rheomagTargets NAMESPACE rheomag:: DESTINATION ${RHEOMAG_CMAKE_DIR})

# What the config file must find again: the imported targets the exported link interfaces name.
set(RHEOMAG_STATIC_LIBS OFF)
if(NOT BUILD_SHARED_LIBS)
  set(RHEOMAG_STATIC_LIBS ON)  # private dependencies (CGAL, OpenMP) are needed at link time too
endif()
set(RHEOMAG_WITH_MPI ${MPI_CXX_FOUND})
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/rheomagConfig.cmake.in
  ${CMAKE_BINARY_DIR}/rheomagConfig.cmake INSTALL_DESTINATION ${RHEOMAG_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/rheomagConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/rheomagConfig.cmake ${CMAKE_BINARY_DIR}/rheomagConfigVersion.cmake
        DESTINATION ${RHEOMAG_CMAKE_DIR})

# pkg-config (relocatable: paths relative to the .pc file; meant for the shared libraries, the
# CMake package also handles a static build): every rheomag library, the header-only
# dependencies' own .pc files, and CHOLMOD (its header folder and -lcholmod: Eigen's inline
# CholmodSupport calls it from the headers; no .pc on Debian 12).
set(RHEOMAG_PC_LIBS)
set(order ${RHEOMAG_LIBRARIES})
list(REVERSE order)
foreach(lib ${order})
  string(APPEND RHEOMAG_PC_LIBS " -lrheomag_${lib}")
endforeach()
configure_file(${CMAKE_SOURCE_DIR}/cmake/rheomag.pc.in ${CMAKE_BINARY_DIR}/rheomag.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/rheomag.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
