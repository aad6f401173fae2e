# SPDX-License-Identifier: Apache-2.0
#
# specular_filelist(<sources_var> <incdirs_var> [FILELIST...]): expands RTL filelists (default
# rtl/specular.f, the product; format in rtl/README.md#filelists) with scripts/rtl_filelist.py,
# the one reader of the format, and sets <sources_var> to their sources in compile order and
# <incdirs_var> to their include directories, as absolute paths, each once (the lists of
# several IPs share their dependencies). Filelist paths are relative to the repository root
# (the directory above this file). Changing any filelist read re-runs CMake.
# specular_filelist_includes(<var> [FILELIST...]) sets <var> to the include files their
# sources read (absolute), for a custom command's DEPENDS.
#
#   include(${PROJECT_SOURCE_DIR}/rtl/specular_filelist.cmake)
#   specular_filelist(RTL_SOURCES RTL_INCDIRS rtl/axi/axi.f)
#   verilate(my_target SOURCES ${RTL_SOURCES} INCLUDE_DIRS ${RTL_INCDIRS} TOP_MODULE specular_axil)
get_filename_component(SPECULAR_ROOT ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)
find_program(SPECULAR_FILELIST_PYTHON NAMES python3 REQUIRED)

function(specular_filelist sources_var incdirs_var)
  set(filelists ${ARGN})
  if(NOT filelists)
    set(filelists rtl/specular.f)
  endif()
  foreach(what sources incdirs filelists)
    execute_process(
      COMMAND ${SPECULAR_FILELIST_PYTHON} ${SPECULAR_ROOT}/scripts/rtl_filelist.py --${what} --absolute ${filelists}
      WORKING_DIRECTORY ${SPECULAR_ROOT}
      OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "specular_filelist(${filelists}): ${err}")
    endif()
    string(STRIP "${out}" out)
    string(REPLACE "\n" ";" ${what} "${out}")
  endforeach()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${filelists})
  set(${sources_var} ${sources} PARENT_SCOPE)
  set(${incdirs_var} ${incdirs} PARENT_SCOPE)
endfunction()

function(specular_filelist_includes var)
  execute_process(
    COMMAND ${SPECULAR_FILELIST_PYTHON} ${SPECULAR_ROOT}/scripts/rtl_filelist.py --includes --absolute ${ARGN}
    WORKING_DIRECTORY ${SPECULAR_ROOT}
    OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "specular_filelist_includes(${ARGN}): ${err}")
  endif()
  string(STRIP "${out}" out)
  string(REPLACE "\n" ";" out "${out}")
  set(${var} ${out} PARENT_SCOPE)
endfunction()
