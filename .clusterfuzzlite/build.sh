#!/bin/bash -eu
# ClusterFuzzLite / OSS-Fuzz build step: the environment provides CC, CXX, CFLAGS, CXXFLAGS,
# LIB_FUZZING_ENGINE, OUT and WORK; fuzz/oss_fuzz_build.sh honours exactly those.
bash "$SRC/kmr/fuzz/oss_fuzz_build.sh"
