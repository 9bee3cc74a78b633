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
      RHEOMAG_SHARED_DIR="${RHEOMAG_SHARED_DIR}"
      RHEOMAG_BINARY="$<TARGET_FILE:rheomag>")
    add_dependencies(${target} rheomag)
    # Fuzz tests (test_*fuzz*.cpp) run for a bounded time in CI: each test of them at most 60 s
    # (measured under 1 s each, docs/bad-input.md).
    set(properties LABELS ${lib})
    if(name MATCHES "fuzz")
      list(APPEND properties TIMEOUT 60)
    endif()
    gtest_discover_tests(${target} TEST_PREFIX "${lib}." DISCOVERY_TIMEOUT 60
                         PROPERTIES ${properties})
  endforeach()
endfunction()

# rheomag_add_asan_fuzz(NAME LABEL SOURCES...): a reader fuzz test built with AddressSanitizer +
# UndefinedBehaviorSanitizer from the given sources and the sanitized case layer
# (rheomag_case_asan: case/ and core/, tests/case/CMakeLists.txt), run by CTest as LABEL.NAME.
function(rheomag_add_asan_fuzz name label)
  set(target ${label}_${name})
  add_executable(${target} ${ARGN})
  target_include_directories(${target} PRIVATE ${CMAKE_SOURCE_DIR})
  target_compile_options(${target} PRIVATE ${RHEOMAG_ASAN_FLAGS})
  target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  target_link_libraries(${target} PRIVATE rheomag_case_asan GTest::gtest_main)
  target_compile_definitions(${target} PRIVATE
    RHEOMAG_TEST_DATA="${RHEOMAG_TEST_DATA}" RHEOMAG_SOURCE_DIR="${RHEOMAG_SOURCE_DIR}"
    RHEOMAG_MATERIALS_DIR="${CMAKE_SOURCE_DIR}/cases/materials")
  add_test(NAME ${label}.${name} COMMAND ${target})
  # Bounded in CI: at most 180 s (measured 1-8 s, docs/bad-input.md).
  set_tests_properties(${label}.${name} PROPERTIES LABELS ${label} TIMEOUT 180
                       ENVIRONMENT "ASAN_OPTIONS=detect_leaks=1;UBSAN_OPTIONS=print_stacktrace=1")
endfunction()
