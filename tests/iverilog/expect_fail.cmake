# SPDX-License-Identifier: Apache-2.0
#
# Runs `VVP -n TB ARGS` in WORKDIR and passes only if the run exits non-zero AND its output
# contains EXPECT: a negative test that fails for the intended reason, not for any reason.
#   cmake -DVVP=vvp -DWORKDIR=dir -DTB=tb.vvp "-DARGS=+a +b" "-DEXPECT=text" -P expect_fail.cmake
cmake_minimum_required(VERSION 3.20)
foreach(v VVP WORKDIR TB ARGS EXPECT)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "expect_fail.cmake: -D${v}=... missing")
  endif()
endforeach()
separate_arguments(args UNIX_COMMAND "${ARGS}")
execute_process(COMMAND ${VVP} -n ${TB} ${args}
  WORKING_DIRECTORY ${WORKDIR}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(rc EQUAL 0)
  message(FATAL_ERROR "expect_fail: the run passed (exit 0); it must fail")
endif()
string(FIND "${out}${err}" "${EXPECT}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "expect_fail: the run failed (exit ${rc}) but without '${EXPECT}'")
endif()
message(STATUS "expect_fail: OK: exit ${rc}, output contains '${EXPECT}'")
