# Helpers shared by every folder. One way to add a layer, a test or a harness.

include(GNUInstallDirs)

# kmr_install_layer(TARGET): installs library kmr_X as kmr::X (export set kmrTargets, see
# cmake/kmrConfig.cmake.in) with the headers of the calling folder under include/kmr/<folder>/.
function(kmr_install_layer target)
  string(REGEX REPLACE "^kmr_" "" short ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${short})
  add_library(kmr::${short} ALIAS ${target})
  install(TARGETS ${target} EXPORT kmrTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  get_filename_component(folder ${CMAKE_CURRENT_SOURCE_DIR} NAME)
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/kmr/${folder} FILES_MATCHING PATTERN "*.hpp")
endfunction()

# Precompiled headers (KMR_PCH; issue 13, the cold build on 2 cores). Three families of targets share
# their compile flags: "lib" (the layers of src/ and the CLI), "test" (GoogleTest binaries) and "prop"
# (GoogleTest + RapidCheck binaries). Each family's header is compiled once, by an object library of
# its own (kmr_pch_FAMILY, an empty file with no flags of its own: GCC rejects a precompiled header
# built with a macro its user lacks, e.g. audit_report_test's KMR_CLAIMS_MD), and reused (REUSE_FROM)
# by every target of the family. The headers are only included earlier than the files include them;
# scripts/sanitize.sh builds without PCH, so a file that forgets an include still breaks CI.
# Default: on for GCC without a compiler launcher; off with ccache (a cache hit skips the compiler
# altogether, and PCH hits in ccache need sloppiness settings). GCC only: clang refuses a PCH built
# with other flags (the fuzz build's sanitizer flags differ between layers) where GCC falls back to
# the plain header.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  set(kmr_pch_default ON)
else()
  set(kmr_pch_default OFF)
endif()
option(KMR_PCH "Precompiled headers, one per target family (default: GCC without ccache)" ${kmr_pch_default})
if(KMR_PCH AND NOT CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  message(FATAL_ERROR "KMR_PCH=ON needs GCC (this is ${CMAKE_CXX_COMPILER_ID}); configure with -DKMR_PCH=OFF")
endif()
set(kmr_pch_lib <algorithm> <array> <cmath> <cstdint> <functional> <map> <optional> <set> <string> <vector>
                <boost/multiprecision/gmp.hpp>)
set(kmr_pch_test ${kmr_pch_lib} <random> <sstream> <gtest/gtest.h>)
set(kmr_pch_prop ${kmr_pch_test} <rapidcheck.h> <rapidcheck/gtest.h>)
set(kmr_pch_libs_lib kmr_gmp)
set(kmr_pch_libs_test kmr_gmp GTest::gtest)
set(kmr_pch_libs_prop kmr_gmp GTest::gtest rapidcheck)

# kmr_pch(TARGET FAMILY): TARGET uses FAMILY's (lib, test or prop) precompiled header. The owner
# library is made at the first call, in that folder, so it gets the folder's flags (the test side's
# KMR_TEST_CXX_FLAGS), which every target of the family shares.
function(kmr_pch target family)
  if(NOT KMR_PCH)
    return()
  endif()
  set(owner kmr_pch_${family})
  if(NOT TARGET ${owner})
    set(empty ${CMAKE_BINARY_DIR}/kmr_pch_${family}.cpp)
    # CONFIGURE writes only when the text changes, so a reconfigure does not rebuild the owners.
    file(CONFIGURE OUTPUT ${empty} CONTENT "// The owner of the ${family} family's precompiled header (cmake/kmr.cmake).\n")
    add_library(${owner} OBJECT ${empty})
    target_link_libraries(${owner} PRIVATE ${kmr_pch_libs_${family}})
    target_precompile_headers(${owner} PRIVATE ${kmr_pch_${family}})
  endif()
  target_precompile_headers(${target} REUSE_FROM ${owner})
endfunction()

# kmr_layer(NAME SOURCES... DEPS lower layers...)  -> static library kmr_NAME, installed as kmr::NAME
function(kmr_layer name)
  cmake_parse_arguments(L "" "" "SOURCES;DEPS" ${ARGN})
  add_library(kmr_${name} STATIC ${L_SOURCES})
  target_include_directories(kmr_${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>
                                                $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/kmr>)
  target_link_libraries(kmr_${name} PUBLIC ${L_DEPS})
  kmr_pch(kmr_${name} lib)
  kmr_install_layer(kmr_${name})
endfunction()

# kmr_test_timeout(TEST SECONDS): the TIMEOUT of a test added with add_test, SECONDS times
# KMR_TEST_TIMEOUT_SCALE when that is set (4 in coverage/run.sh and scripts/sanitize.sh), as
# kmr_gtest does for GoogleTest binaries: -O0 --coverage and sanitizer builds run the same shell-driven
# tests several times slower, more so on a loaded machine.
function(kmr_test_timeout test seconds)
  if(KMR_TEST_TIMEOUT_SCALE)
    math(EXPR seconds "${seconds} * ${KMR_TEST_TIMEOUT_SCALE}")
  endif()
  set_tests_properties(${test} PROPERTIES TIMEOUT ${seconds})
endfunction()

# kmr_gtest(NAME LABEL label SOURCES... LIBS ...) -> GoogleTest binary, each test a ctest test.
# Property tests (LABEL prop) run with a fixed RapidCheck seed so CI is reproducible;
# override with RC_PARAMS="seed=N" to replay or explore.
function(kmr_gtest name)
  cmake_parse_arguments(T "" "LABEL;SEED;TIMEOUT;RC_RUNS" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE ${T_LIBS} GTest::gtest GTest::gtest_main)
  if(T_LABEL STREQUAL "prop")
    target_link_libraries(${name} PRIVATE rapidcheck)
    kmr_pch(${name} prop)
  else()
    kmr_pch(${name} test)
  endif()
  if(NOT T_SEED)
    set(T_SEED 20121)
  endif()
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 600)
  endif()
  if(KMR_TEST_TIMEOUT_SCALE)  # e.g. 4 under sanitizers (scripts/sanitize.sh), which slow tests down
    math(EXPR T_TIMEOUT "${T_TIMEOUT} * ${KMR_TEST_TIMEOUT_SCALE}")
  endif()
  set(env "")
  if(NOT T_RC_RUNS)
    set(T_RC_RUNS 100)  # RC_RUNS: cases per property (long state-machine sequences use fewer)
  endif()
  if(T_LABEL STREQUAL "prop")
    set(env "RC_PARAMS=seed=${T_SEED} max_success=${T_RC_RUNS} verbose_progress=0")
  endif()
  gtest_discover_tests(${name}
    DISCOVERY_MODE PRE_TEST
    PROPERTIES LABELS "${T_LABEL}" TIMEOUT ${T_TIMEOUT} ENVIRONMENT "${env}")
endfunction()
