# SPDX-License-Identifier: Apache-2.0
#
# ctest rtl_iverilog_mul_ecp5_mutant: shows that tb_mul_ecp5 can fail. Copies
# rtl/prim/specular_mul_tile.sv to OUT (never changing rtl/), ties the MULT18X18D's SIGNEDA to 0
# in the copy (a signed tile read as unsigned), compiles the testbench with the copy in place
# of the original and runs it; passes only if the run reports products that differ.
#   cmake -DIVERILOG=iverilog -DVVP=vvp -DROOT=<repo> -DOUT=<dir> "-DSOURCES=<a;b;..>"
#         "-DFLAGS=<iverilog flags>" -P mul_ecp5_mutant.cmake
cmake_minimum_required(VERSION 3.20)
foreach(v IVERILOG VVP ROOT OUT SOURCES FLAGS)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "mul_ecp5_mutant.cmake: -D${v}=... missing")
  endif()
endforeach()
set(mut_file ${ROOT}/rtl/prim/specular_mul_tile.sv)
set(mut_from ".SIGNEDA (Signed)")
set(mut_to ".SIGNEDA (1'b0)")

file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
file(READ ${mut_file} text)
string(FIND "${text}" "${mut_from}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "mul_ecp5_mutant: '${mut_from}' not found in ${mut_file} (RTL changed?)")
endif()
string(REPLACE "${mut_from}" "${mut_to}" text "${text}")
file(WRITE ${OUT}/specular_mul_tile.sv "${text}")
list(TRANSFORM SOURCES REPLACE "^${mut_file}$" "${OUT}/specular_mul_tile.sv")
list(FIND SOURCES ${OUT}/specular_mul_tile.sv found)
if(found EQUAL -1)
  message(FATAL_ERROR "mul_ecp5_mutant: ${mut_file} is not among the sources")
endif()
separate_arguments(flags UNIX_COMMAND "${FLAGS}")
execute_process(COMMAND ${IVERILOG} ${flags} -o ${OUT}/tb.vvp ${SOURCES}
  WORKING_DIRECTORY ${ROOT} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "mul_ecp5_mutant: the mutant does not compile:\n${out}${err}")
endif()
execute_process(COMMAND ${VVP} -n ${OUT}/tb.vvp WORKING_DIRECTORY ${ROOT}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT out MATCHES "tb_mul_ecp5: FAIL \\([0-9]+ products differ\\)")
  message(FATAL_ERROR "mul_ecp5_mutant: the mutant (${mut_to}) was not caught:\n${out}${err}")
endif()
message(STATUS "mul_ecp5_mutant: ${mut_to} caught: ${out}")
