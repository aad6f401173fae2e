# SPDX-License-Identifier: Apache-2.0
# X-propagation check (ctest sim_xprop): runs sim_regression once per seed in SEEDS with
# +verilator+rand+reset+2 +verilator+seed+<seed> (every register without reset, every RAM
# word, every X constant random) and compares the output digests, which cover every output
# port of every model in every cycle. Fails when a run fails its checks or any digest differs.
#   cmake -DSIM=path/to/sim_regression -DOUT=dir "-DSEEDS=1;2;3" -P xprop_check.cmake
# Run from the repository root (ROM and scene paths are relative).
if(NOT SIM OR NOT OUT OR NOT SEEDS)
  message(FATAL_ERROR "xprop_check.cmake: SIM, OUT and SEEDS are required")
endif()
file(MAKE_DIRECTORY ${OUT})
set(ARGS --random 2000 --stream-spans 20000)
set(first "")
foreach(seed IN LISTS SEEDS)
  execute_process(
    COMMAND ${SIM} ${ARGS} --images-dir ${OUT}/scenes_${seed} --digest ${OUT}/digest_${seed}.txt
            +verilator+rand+reset+2 +verilator+seed+${seed}
    OUTPUT_FILE ${OUT}/run_${seed}.log ERROR_FILE ${OUT}/run_${seed}.err
    RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    file(READ ${OUT}/run_${seed}.err err)
    message(FATAL_ERROR "sim_xprop: seed ${seed}: sim_regression exit ${rc} (log ${OUT}/run_${seed}.log)\n${err}")
  endif()
  file(READ ${OUT}/digest_${seed}.txt digest)
  string(STRIP "${digest}" digest)
  message(STATUS "seed ${seed}: digest ${digest}")
  if(first STREQUAL "")
    set(first "${digest}")
    set(first_seed ${seed})
  elseif(NOT digest STREQUAL first)
    message(FATAL_ERROR "sim_xprop: outputs depend on uninitialized values: seed ${seed} gives digest ${digest}, "
                        "seed ${first_seed} gave ${first} (logs in ${OUT})")
  endif()
endforeach()
message(STATUS "sim_xprop: ${SEEDS}: identical output digests, every run passed")
