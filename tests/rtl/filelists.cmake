# SPDX-License-Identifier: Apache-2.0
#
# The filelists and FuseSoC cores as the tools read them (rtl/README.md#filelists); included at
# the end of tests/rtl/CMakeLists.txt. One test per IP (rtl/**/*.manifest) and top:
#   filelists_up_to_date           every generated rtl/**/*.f and *.core is what its manifest
#                                  generates (scripts/rtl_filelist.py --check: names the stale file)
#   filelist_verilator_<ip>_<top>  verilator --lint-only -Wall -f <the IP's .f> --top-module <top>
#                                  from the repository root, no message
#   filelist_iverilog_read_<ip>    iverilog -g2012 -E -c <the IP's .f>: every source and include
#                                  file found through the list alone
#   filelist_iverilog_<ip>_<top>   iverilog -g2012 -c <the IP's .f> -s <top>, then vvp at time 0
#                                  (the ROM loads and parameter checks), for the IPs Icarus 11
#                                  elaborates (FILELIST_IVERILOG_IPS below)
#   fusesoc_install                the pinned FuseSoC into the build's virtual environment (the
#                                  package index on first use; scripts/tools_venv.py)
#   fusesoc_lint_<ip>_<top>        fusesoc run --target=lint[_<top>] of the IP's .core: Verilator
#                                  -Wall on the files the .core lists (scripts/fusesoc_lint.sh)
#   fusesoc_lint_mutant            a .core missing a file must fail its lint
# The same file runs one Icarus test when called as a script (cmake -P, below).

if(CMAKE_SCRIPT_MODE_FILE)
  # cmake -DIV=iverilog -DVVP=vvp -DROOT=... -DLIST=rtl/x/x.f -DTOP=... -DOUT=x.vvp
  #       [-DPARAMS=-Ptop.A=1,...] -P filelists.cmake
  string(REPLACE "," ";" params "${PARAMS}")
  execute_process(COMMAND ${IV} -g2012 -c ${LIST} -s ${TOP} ${params} -o ${OUT}
    WORKING_DIRECTORY ${ROOT} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  # Icarus' "sorry: ... ignored" notes name what it does not implement; they are no errors.
  if(NOT rc EQUAL 0 OR out MATCHES "[Ee]rror|[Ww]arning|give up")
    message(FATAL_ERROR "${out}iverilog -g2012 -c ${LIST} -s ${TOP}: failed (status ${rc})")
  endif()
  execute_process(COMMAND ${VVP} -n ${OUT}
    WORKING_DIRECTORY ${ROOT} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0 OR out MATCHES "ERROR|FATAL|WARNING")
    message(FATAL_ERROR "${out}vvp of ${TOP} from ${LIST}: failed at time 0 (status ${rc})")
  endif()
  message("${TOP} from ${LIST}: compiled by Icarus Verilog and run to time 0")
  return()
endif()

set(FILELIST_ROOT ${PROJECT_SOURCE_DIR})
set(FILELIST_OUT ${CMAKE_CURRENT_BINARY_DIR}/filelists)
file(MAKE_DIRECTORY ${FILELIST_OUT})
# The IPs whose tops Icarus Verilog 11 elaborates: all but phong, whose package's constant
# functions in parameters Icarus 11 does not evaluate; filelist_iverilog_read_<ip> reads its
# list. Of their tops not the folded setup's CORDIC (specular_setup_cordic_fold, SetupII > 1
# only), whose constant functions of constant functions Icarus 11 fails to evaluate.
set(FILELIST_IVERILOG_IPS prim core axi setup system specular)
set(FILELIST_IVERILOG_SKIP_TOPS specular_setup_cordic_fold)

file(GLOB_RECURSE FILELIST_MANIFESTS CONFIGURE_DEPENDS ${FILELIST_ROOT}/rtl/*.manifest)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${FILELIST_MANIFESTS})
execute_process(COMMAND ${SPECULAR_FILELIST_PYTHON} ${FILELIST_ROOT}/scripts/rtl_filelist.py --ips
  WORKING_DIRECTORY ${FILELIST_ROOT} OUTPUT_VARIABLE FILELIST_TABLE ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "tests/rtl/filelists.cmake: scripts/rtl_filelist.py --ips: ${err}")
endif()
string(STRIP "${FILELIST_TABLE}" FILELIST_TABLE)
string(REPLACE "\n" ";" FILELIST_TABLE "${FILELIST_TABLE}")

find_program(FILELIST_IVERILOG iverilog)
find_program(FILELIST_VVP vvp)
if(NOT FILELIST_IVERILOG OR NOT FILELIST_VVP)
  message(STATUS "iverilog/vvp not found: filelist_iverilog_* tests not registered (scripts/install-deps.sh installs iverilog)")
endif()

add_test(NAME filelists_up_to_date
  COMMAND ${SPECULAR_FILELIST_PYTHON} ${FILELIST_ROOT}/scripts/rtl_filelist.py --check ${FILELIST_OUT}/generated)
set(FILELIST_CHECK_TESTS filelists_up_to_date)
set(FILELIST_VERILATOR_TESTS "")
set(FILELIST_FUSESOC_TESTS "")
set(FILELIST_READ_DONE "")
foreach(row IN LISTS FILELIST_TABLE)
  # NAME|FLAT_LIST|VLNV|TARGET|TOP|-GNAME=VALUE,... (scripts/rtl_filelist.py --ips)
  string(REPLACE "|" ";" row "${row}")
  list(GET row 0 ip)
  list(GET row 1 list_file)
  list(GET row 2 vlnv)
  list(GET row 3 target)
  list(GET row 4 top)
  list(LENGTH row n)
  set(gparams "")
  if(n GREATER 5)
    list(GET row 5 gparams)
    string(REPLACE "," ";" gparams "${gparams}")
  endif()

  add_test(NAME filelist_verilator_${ip}_${top}
    COMMAND ${VERILATOR_EXE} --lint-only -Wall -f ${list_file} --top-module ${top} ${gparams}
    WORKING_DIRECTORY ${FILELIST_ROOT})
  list(APPEND FILELIST_VERILATOR_TESTS filelist_verilator_${ip}_${top})

  if(FILELIST_IVERILOG AND FILELIST_VVP)
    if(NOT ip IN_LIST FILELIST_READ_DONE)
      list(APPEND FILELIST_READ_DONE ${ip})
      add_test(NAME filelist_iverilog_read_${ip}
        COMMAND ${FILELIST_IVERILOG} -g2012 -E -c ${list_file} -o ${FILELIST_OUT}/${ip}.E
        WORKING_DIRECTORY ${FILELIST_ROOT})
      list(APPEND FILELIST_CHECK_TESTS filelist_iverilog_read_${ip})
    endif()
    if(ip IN_LIST FILELIST_IVERILOG_IPS AND NOT top IN_LIST FILELIST_IVERILOG_SKIP_TOPS)
      list(TRANSFORM gparams REPLACE "^-G" "-P${top}." OUTPUT_VARIABLE pparams)
      string(REPLACE ";" "," pparams "${pparams}")
      add_test(NAME filelist_iverilog_${ip}_${top}
        COMMAND ${CMAKE_COMMAND} -DIV=${FILELIST_IVERILOG} -DVVP=${FILELIST_VVP} -DROOT=${FILELIST_ROOT}
                -DLIST=${list_file} -DTOP=${top} -DOUT=${FILELIST_OUT}/${ip}_${top}.vvp "-DPARAMS=${pparams}"
                -P ${CMAKE_CURRENT_LIST_FILE})
      list(APPEND FILELIST_CHECK_TESTS filelist_iverilog_${ip}_${top})
    endif()
  endif()

  add_test(NAME fusesoc_lint_${ip}_${top}
    COMMAND bash ${FILELIST_ROOT}/scripts/fusesoc_lint.sh --build-root ${FILELIST_OUT}/fusesoc ${vlnv} ${target}
    WORKING_DIRECTORY ${FILELIST_ROOT})
  list(APPEND FILELIST_FUSESOC_TESTS fusesoc_lint_${ip}_${top})
endforeach()

# Lint output must be empty, not only the exit status zero; each of these takes under 4 s.
set_tests_properties(${FILELIST_VERILATOR_TESTS} PROPERTIES FAIL_REGULAR_EXPRESSION "%Warning|%Error")
set_tests_properties(${FILELIST_VERILATOR_TESTS} ${FILELIST_CHECK_TESTS} PROPERTIES LABELS check)

# FuseSoC: installed once (the fixture), then each lint in its own work directory.
add_test(NAME fusesoc_install COMMAND /usr/bin/python3 ${FILELIST_ROOT}/scripts/tools_venv.py install fusesoc
  WORKING_DIRECTORY ${FILELIST_ROOT})
set_tests_properties(fusesoc_install PROPERTIES FIXTURES_SETUP fusesoc_venv TIMEOUT 600)
add_test(NAME fusesoc_lint_mutant
  COMMAND bash ${FILELIST_ROOT}/scripts/fusesoc_lint.sh --build-root ${FILELIST_OUT}/fusesoc_mutant --mutant
  WORKING_DIRECTORY ${FILELIST_ROOT})
set_tests_properties(${FILELIST_FUSESOC_TESTS} PROPERTIES FAIL_REGULAR_EXPRESSION "%Warning|%Error")
set_tests_properties(${FILELIST_FUSESOC_TESTS} fusesoc_lint_mutant PROPERTIES FIXTURES_REQUIRED fusesoc_venv TIMEOUT 120)
# The build's own virtual environment (CMakeLists.txt: SPECULAR_VENV).
set_tests_properties(fusesoc_install ${FILELIST_FUSESOC_TESTS} fusesoc_lint_mutant PROPERTIES
  ENVIRONMENT SPECULAR_VENV=${SPECULAR_VENV})
