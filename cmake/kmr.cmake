# Helpers shared by every folder. One way to add a layer, a test or a harness.

# kmr_layer(NAME SOURCES... DEPS lower layers...)  -> static library kmr_NAME
function(kmr_layer name)
  cmake_parse_arguments(L "" "" "SOURCES;DEPS" ${ARGN})
  add_library(kmr_${name} STATIC ${L_SOURCES})
  target_include_directories(kmr_${name} PUBLIC ${PROJECT_SOURCE_DIR}/src)
  target_link_libraries(kmr_${name} PUBLIC ${L_DEPS})
endfunction()

# kmr_gtest(NAME LABEL label SOURCES... LIBS ...) -> GoogleTest binary, each test a ctest test.
# Property tests (LABEL prop) run with a fixed RapidCheck seed so CI is reproducible;
# override with RC_PARAMS="seed=N" to replay or explore.
function(kmr_gtest name)
  cmake_parse_arguments(T "" "LABEL;SEED;TIMEOUT" "SOURCES;LIBS" ${ARGN})
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
  if(T_LABEL STREQUAL "prop")
    set(env "RC_PARAMS=seed=${T_SEED} max_success=100 verbose_progress=0")
  endif()
  gtest_discover_tests(${name}
    DISCOVERY_MODE PRE_TEST
    PROPERTIES LABELS "${T_LABEL}" TIMEOUT ${T_TIMEOUT} ENVIRONMENT "${env}")
endfunction()
