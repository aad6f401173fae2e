# SPDX-License-Identifier: Apache-2.0
# The register map of specular_axil, written once in rtl/axi/data/specular_axil.rdl
# (SystemRDL; docs/interfaces.md#register-map), and its generated copies: the RTL's package
# rtl/axi/specular_axil_reg_pkg.sv, the C header rtl/axi/data/specular_axil_regs.h (which
# test_axil.cpp includes) and the table of docs/interfaces.md. Included at the end of
# tests/rtl/CMakeLists.txt, after the target rtl_axi_tests.
#   regmap_up_to_date    regenerates the copies into this build (scripts/regmap.py --check) and
#                        fails naming each committed copy that differs: run `make regmap`.
#                        Installs the pinned PeakRDL tools (scripts/regmap-requirements.txt)
#                        into the build's virtual environment (scripts/tools_venv.py) on first
#                        use; fails with a message when the package index cannot be reached.
#   regmap_stale_caught  the check on copies of the committed files: a hand edit of each
#                        generated copy must fail it, naming that file; an edit of
#                        docs/interfaces.md outside the table must not.
target_include_directories(rtl_axi_tests PRIVATE ${PROJECT_SOURCE_DIR}/rtl/axi/data)

add_test(NAME regmap_up_to_date
  COMMAND ${CMAKE_COMMAND} -E env SPECULAR_VENV=${SPECULAR_VENV}
          /usr/bin/python3 ${PROJECT_SOURCE_DIR}/scripts/regmap.py --check ${CMAKE_CURRENT_BINARY_DIR}/regmap)
add_test(NAME regmap_stale_caught
  COMMAND ${CMAKE_COMMAND} -E env SPECULAR_VENV=${SPECULAR_VENV}
          /usr/bin/python3 ${PROJECT_SOURCE_DIR}/scripts/regmap.py --selftest ${CMAKE_CURRENT_BINARY_DIR}/regmap_selftest)
set_tests_properties(regmap_stale_caught PROPERTIES
  PASS_REGULAR_EXPRESSION "self-test PASS")
set_tests_properties(regmap_up_to_date regmap_stale_caught PROPERTIES TIMEOUT 600 LABELS regmap)
