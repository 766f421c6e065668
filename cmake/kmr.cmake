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

# kmr_layer(NAME SOURCES... DEPS lower layers...)  -> static library kmr_NAME, installed as kmr::NAME
function(kmr_layer name)
  cmake_parse_arguments(L "" "" "SOURCES;DEPS" ${ARGN})
  add_library(kmr_${name} STATIC ${L_SOURCES})
  target_include_directories(kmr_${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>
                                                $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/kmr>)
  target_link_libraries(kmr_${name} PUBLIC ${L_DEPS})
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
