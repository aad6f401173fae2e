# SPDX-License-Identifier: Apache-2.0
# ctest sim_regression_cli: sim_regression's exit codes and JSON summary.
#   -DSIM=<sim_regression> -DTMP=<scratch dir>, run from the repository root.
file(REMOVE_RECURSE ${TMP})
file(MAKE_DIRECTORY ${TMP}/bad_scenes)

function(expect_rc want)
  execute_process(COMMAND ${SIM} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL want)
    message(FATAL_ERROR "sim_regression ${ARGN}: exit ${rc}, expected ${want}\n${out}\n${err}")
  endif()
  set(last_err "${err}" PARENT_SCOPE)
endfunction()

# A scene file that is not JSON: exit 2 naming the file, before anything runs.
file(WRITE ${TMP}/bad_scenes/broken.json "{ \"camera\": ")
expect_rc(2 --scenes-dir ${TMP}/bad_scenes --random 0 --stream-spans 0 --json ${TMP}/bad.json)
if(NOT last_err MATCHES "broken.json")
  message(FATAL_ERROR "the bad-scene message does not name the file: ${last_err}")
endif()
if(EXISTS ${TMP}/bad.json)
  message(FATAL_ERROR "a run refused for a bad scene wrote its JSON")
endif()
# An empty scene directory and an unknown configuration are refused too.
file(MAKE_DIRECTORY ${TMP}/no_scenes)
expect_rc(2 --scenes-dir ${TMP}/no_scenes --random 0 --stream-spans 0)
expect_rc(2 --config nope)
expect_rc(2 --random -1)
# SetupII of the system stage: outside {1, 8, 16, 32, 64}, and 8 when the model is not built.
expect_rc(2 --setup-ii 3 --config default --random 0 --stream-spans 0 --no-scenes)
if(NOT SETUP_II_BUILT)
  expect_rc(2 --setup-ii 1,8 --config default --random 0 --stream-spans 0 --no-scenes)
  if(NOT last_err MATCHES "SPECULAR_SYSTEM_SETUP_II")
    message(FATAL_ERROR "the refused --setup-ii 8 does not name the build option: ${last_err}")
  endif()
endif()

# A short run: the JSON carries the figures the report reads.
# 20,000 spans: the bursts of short spans carry the fill latency within their 0.99 pixels per clock.
expect_rc(0 --config default --random 200 --stream-spans 20000 --no-scenes --json ${TMP}/run.json)
file(READ ${TMP}/run.json j)
string(JSON ok GET "${j}" ok)
string(JSON mism GET "${j}" configs default mismatches)
string(JSON lines GET "${j}" configs default lines)
string(JSON lat GET "${j}" configs default expected_latency)
string(JSON lat_n GET "${j}" configs default latency ${lat})
string(JSON spans GET "${j}" stream spans)
string(JSON ppc GET "${j}" stream pixels_per_clock_short_spans)
string(JSON smism GET "${j}" stream mismatches)
if(NOT ok OR NOT mism EQUAL 0 OR NOT smism EQUAL 0 OR lines LESS 200 OR lat_n LESS 1 OR spans LESS 20000)
  message(FATAL_ERROR "JSON summary: ok=${ok} mismatches=${mism}/${smism} lines=${lines} latency ${lat} x${lat_n} spans=${spans}")
endif()
if(ppc LESS 0.99)
  message(FATAL_ERROR "JSON summary: pixels per clock on short spans ${ppc} < 0.99")
endif()
message(STATUS "sim_regression CLI and JSON: OK (latency ${lat}, ${spans} spans, ${ppc} pixels/clock)")
file(REMOVE_RECURSE ${TMP})
