# End-to-end T3.3.4 / L3.3.3: `kmr wellspaced` output judged by kmr_oracle_ws_judge.
# Invoked by ctest with -DKMR=<kmr binary> -DJUDGE=<judge binary> -DWORK=<dir> -DDIM=<2|3>.
set(in "${WORK}/cli_judge_in_${DIM}d.txt")
set(out "${WORK}/cli_judge_out_${DIM}d.txt")
if(DIM EQUAL 2)
  file(WRITE ${in} "# clustered points and a pair 2^-30 apart, dyadic coordinates\n0.5 0.5\n0.5000000009313225746154785 0.5\n0.125 0.75\n0.1328125 0.7578125\n0 0\n1 1\n0.875 0.0625\n0.3125 0.9375\n")
else()
  file(WRITE ${in} "0.5 0.5 0.5\n0.515625 0.5 0.5\n0 0 0\n1 1 1\n0.25 0.75 0.125\n")
endif()
execute_process(COMMAND ${KMR} wellspaced --dim ${DIM} --rho 2 --beta 4 ${in}
  OUTPUT_FILE ${out} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "kmr wellspaced failed (${rc}): ${err}")
endif()
execute_process(COMMAND ${JUDGE} --dim ${DIM} --rho 2 --input ${in} ${out}
  RESULT_VARIABLE rc OUTPUT_VARIABLE verdict ERROR_VARIABLE err)
message(STATUS "${verdict}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "oracle rejects the CLI output (${rc})")
endif()
