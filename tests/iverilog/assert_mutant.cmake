# SPDX-License-Identifier: Apache-2.0
#
# ctest rtl_iverilog_assert_mutant: shows that a block assertion (rtl/prim/specular_assert.svh)
# fires. Copies the sources of rtl/specular.f (and rtl/prim/specular_assert.svh) to OUT, breaks
# one block invariant in the copy (never in rtl/), compiles it with the testbench and runs
# it; passes only if the run exits non-zero with the expected assertion's report.
# Mutation: specular_out_buf pushes the last stage's pixel whatever the advance (push =
# in_valid_i), so under backpressure a third pixel enters the two-entry buffer; CountMax_A
# (count_q <= 2) must report. (The advance itself stays right, so AdvIsRoom_A holds: with
# scripts/formal.sh's adv_ignores_room mutation instead, AdvIsRoom_A reports first.)
#   cmake -DIVERILOG=iverilog -DVVP=vvp -DROOT=<repo> -DTB=<tb.sv> -DOUT=<dir>
#         "-DRUN_ARGS=+spans=.. +pixels=.. +seed=.." -P assert_mutant.cmake
cmake_minimum_required(VERSION 3.20)
foreach(v IVERILOG VVP ROOT TB OUT RUN_ARGS)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "assert_mutant.cmake: -D${v}=... missing")
  endif()
endforeach()
set(mut_file rtl/prim/specular_out_buf.sv)
set(mut_from "assign push = adv_q & in_valid_i;")
set(mut_to "assign push = in_valid_i;")
set(expect "[SPEC_ASSERT]")
set(expect_name "CountMax_A")

file(REMOVE_RECURSE ${OUT})
include(${ROOT}/rtl/specular_filelist.cmake)
specular_filelist(sources incdirs rtl/core/core.f)
specular_filelist_includes(headers rtl/core/core.f)
# The copy keeps the paths relative to the root: the include files the sources read, then
# the sources.
set(copies ${headers} ${sources})
set(mut_sources "")
set(mut_incdirs "")
foreach(f IN LISTS copies)
  file(RELATIVE_PATH rel ${ROOT} ${f})
  get_filename_component(dir ${OUT}/${rel} DIRECTORY)
  file(MAKE_DIRECTORY ${dir})
  file(COPY_FILE ${f} ${OUT}/${rel})
  if(rel MATCHES "\\.sv$")
    list(APPEND mut_sources ${OUT}/${rel})
  endif()
endforeach()
foreach(d IN LISTS incdirs)
  file(RELATIVE_PATH rel ${ROOT} ${d})
  list(APPEND mut_incdirs -I ${OUT}/${rel})
endforeach()
file(READ ${OUT}/${mut_file} text)
string(FIND "${text}" "${mut_from}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "assert_mutant: '${mut_from}' not found in ${mut_file} (RTL changed?)")
endif()
string(REPLACE "${mut_from}" "${mut_to}" text "${text}")
file(WRITE ${OUT}/${mut_file} "${text}")
message(STATUS "assert_mutant: ${mut_file}: '${mut_from}' -> '${mut_to}'")

execute_process(COMMAND ${IVERILOG} -g2012 ${mut_incdirs} -s tb_specular_stream -o ${OUT}/tb.vvp ${mut_sources} ${TB}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "assert_mutant: the mutant does not compile:\n${out}${err}")
endif()
# ROM files are read relative to the repository root.
separate_arguments(run_args UNIX_COMMAND "${RUN_ARGS}")
execute_process(COMMAND ${VVP} -n ${OUT}/tb.vvp ${run_args}
  WORKING_DIRECTORY ${ROOT}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
string(FIND "${out}${err}" "${expect}" at)
string(FIND "${out}${err}" "${expect_name}" at_name)
if(rc EQUAL 0 OR at EQUAL -1 OR at_name EQUAL -1)
  message(FATAL_ERROR "assert_mutant: FAIL: expected a non-zero exit with '${expect}' from ${expect_name} (exit ${rc})")
endif()
message(STATUS "assert_mutant: PASS: the mutant is stopped by ${expect_name} (exit ${rc})")
