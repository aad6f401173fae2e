# SPDX-License-Identifier: Apache-2.0
#
# specular_filelist(<sources_var> <incdirs_var>): reads rtl/specular.f (the filelist of the
# core, rtl/README.md) and sets <sources_var> to its source files in compile order and
# <incdirs_var> to its include directories (`+incdir+DIR` lines), both as absolute paths.
# `//` comment lines and blank lines are skipped; paths in the file are relative to the
# repository root (the directory above this file). Changing the filelist re-runs CMake.
#
#   include(${PROJECT_SOURCE_DIR}/rtl/specular_filelist.cmake)
#   specular_filelist(RTL_SOURCES RTL_INCDIRS)
#   verilate(my_target SOURCES ${RTL_SOURCES} INCLUDE_DIRS ${RTL_INCDIRS} TOP_MODULE specular_axil)
set(SPECULAR_FILELIST ${CMAKE_CURRENT_LIST_DIR}/specular.f)
get_filename_component(SPECULAR_ROOT ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)

function(specular_filelist sources_var incdirs_var)
  file(STRINGS ${SPECULAR_FILELIST} lines)
  set(sources "")
  set(incdirs "")
  foreach(line IN LISTS lines)
    string(STRIP "${line}" line)
    if(line STREQUAL "" OR line MATCHES "^//")
      continue()
    elseif(line MATCHES "^\\+incdir\\+(.+)$")
      list(APPEND incdirs ${SPECULAR_ROOT}/${CMAKE_MATCH_1})
    else()
      list(APPEND sources ${SPECULAR_ROOT}/${line})
    endif()
  endforeach()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${SPECULAR_FILELIST})
  set(${sources_var} ${sources} PARENT_SCOPE)
  set(${incdirs_var} ${incdirs} PARENT_SCOPE)
endfunction()
