# SPDX-License-Identifier: Apache-2.0
#
# ctest rtl_filelist: rtl/specular.f (the compile-order filelist, rtl/README.md) against
# the tree. Fails when
#   - a line names a file that does not exist, is not an .sv file or is listed twice;
#   - a `+incdir+DIR` line names no directory;
#   - an .sv file under rtl/ is not listed, except the harnesses of rtl/formal/ and
#     rtl/fpga/ and testbenches (a directory named tb or test, or a file tb_*.sv / *_tb.sv);
#   - an include file (.svh) there is in no `+incdir+` directory.
# This is the one place that lists rtl/ by pattern, on purpose: every build reads the
# filelist instead.
#   cmake -DROOT=<repository root> -P tests/rtl/check_filelist.cmake
cmake_minimum_required(VERSION 3.20)
if(NOT ROOT)
  message(FATAL_ERROR "usage: cmake -DROOT=<repository root> -P check_filelist.cmake")
endif()
set(filelist ${ROOT}/rtl/specular.f)
if(NOT EXISTS ${filelist})
  message(FATAL_ERROR "rtl_filelist: ${filelist} does not exist")
endif()

file(STRINGS ${filelist} lines)
set(listed "")
set(incdirs "")
set(errors "")
set(lineno 0)
foreach(line IN LISTS lines)
  math(EXPR lineno "${lineno} + 1")
  string(STRIP "${line}" entry)
  if(entry STREQUAL "" OR entry MATCHES "^//")
    continue()
  endif()
  if(entry MATCHES "^\\+incdir\\+(.+)$")
    if(NOT IS_DIRECTORY ${ROOT}/${CMAKE_MATCH_1})
      list(APPEND errors "rtl/specular.f:${lineno}: include directory '${CMAKE_MATCH_1}' does not exist")
    endif()
    list(APPEND incdirs ${CMAKE_MATCH_1})
    continue()
  endif()
  if(NOT entry MATCHES "\\.sv$")
    list(APPEND errors "rtl/specular.f:${lineno}: '${entry}' is not an .sv file")
  elseif(NOT EXISTS ${ROOT}/${entry} OR IS_DIRECTORY ${ROOT}/${entry})
    list(APPEND errors "rtl/specular.f:${lineno}: '${entry}' does not exist (paths are relative to the repository root)")
  elseif(entry IN_LIST listed)
    list(APPEND errors "rtl/specular.f:${lineno}: '${entry}' is listed twice")
  endif()
  list(APPEND listed ${entry})
endforeach()

file(GLOB_RECURSE present RELATIVE ${ROOT} ${ROOT}/rtl/*.sv)
list(SORT present)
set(checked 0)
foreach(f IN LISTS present)
  if(f MATCHES "^rtl/(formal|fpga)/" OR f MATCHES "(^|/)(tb|test|tests)/" OR f MATCHES "(^|/)tb_[^/]*\\.sv$"
     OR f MATCHES "_tb\\.sv$")
    continue()
  endif()
  math(EXPR checked "${checked} + 1")
  if(NOT f IN_LIST listed)
    list(APPEND errors "${f} is not in rtl/specular.f (add it in compile order)")
  endif()
endforeach()

file(GLOB_RECURSE headers RELATIVE ${ROOT} ${ROOT}/rtl/*.svh)
foreach(f IN LISTS headers)
  if(f MATCHES "^rtl/(formal|fpga)/" OR f MATCHES "(^|/)(tb|test|tests)/")
    continue()
  endif()
  get_filename_component(dir ${f} DIRECTORY)
  if(NOT dir IN_LIST incdirs)
    list(APPEND errors "${f}: its directory ${dir} is not a +incdir+ line of rtl/specular.f")
  endif()
endforeach()

list(LENGTH listed n)
if(errors)
  list(JOIN errors "\n  " msg)
  message(FATAL_ERROR "rtl_filelist: FAIL\n  ${msg}")
endif()
message(STATUS "rtl_filelist: OK: ${n} files listed, ${checked} synthesizable .sv files under rtl/, all listed and present")
