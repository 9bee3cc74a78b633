# rheomag_add_tests(LIB): one GoogleTest executable per test_*.cpp in the calling folder,
# linked to rheomag_LIB, with RHEOMAG_TEST_DATA / RHEOMAG_SOURCE_DIR / RHEOMAG_SHARED_DIR defined.
function(rheomag_add_tests lib)
  file(GLOB tests CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/test_*.cpp)
  foreach(src ${tests})
    get_filename_component(name ${src} NAME_WE)
    set(target ${lib}_${name})
    add_executable(${target} ${src})
    target_include_directories(${target} PRIVATE ${CMAKE_SOURCE_DIR})
    target_link_libraries(${target} PRIVATE rheomag_${lib} GTest::gtest_main GTest::gmock)
    target_compile_definitions(${target} PRIVATE
      RHEOMAG_TEST_DATA="${RHEOMAG_TEST_DATA}"
      RHEOMAG_SOURCE_DIR="${RHEOMAG_SOURCE_DIR}"
      RHEOMAG_SHARED_DIR="${RHEOMAG_SOURCE_DIR}/../shared"
      RHEOMAG_BINARY="$<TARGET_FILE:rheomag>")
    add_dependencies(${target} rheomag)
    gtest_discover_tests(${target} TEST_PREFIX "${lib}." DISCOVERY_TIMEOUT 60
                         PROPERTIES LABELS ${lib})
  endforeach()
endfunction()
