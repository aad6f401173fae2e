# SPDX-License-Identifier: Apache-2.0
# ctest roms_up_to_date: regenerate every build configuration's ROMs (romgen --all) into TMP and
# compare with the committed SRC (the ROM files and build_configs.cmake, the configurations' -G
# flags).
file(REMOVE_RECURSE ${TMP})
execute_process(COMMAND ${ROMGEN} --all --out-dir ${TMP} --quiet RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "romgen failed (${rc})")
endif()
file(GLOB_RECURSE generated RELATIVE ${TMP} ${TMP}/*.hex ${TMP}/build_configs.cmake)
if(NOT generated)
  message(FATAL_ERROR "romgen wrote no .hex files")
endif()
set(stale "")
foreach(f ${generated})
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${TMP}/${f} ${SRC}/${f} RESULT_VARIABLE diff)
  if(NOT diff EQUAL 0)
    list(APPEND stale ${f})
  endif()
endforeach()
if(stale)
  message(FATAL_ERROR "roms/ is out of date (differs from romgen output): ${stale}. Run `make roms` and commit.")
endif()
message(STATUS "roms/ matches romgen output: ${generated}")
