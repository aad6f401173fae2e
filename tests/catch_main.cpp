// SPDX-License-Identifier: Apache-2.0
// The one Catch2 main of every test executable (library catch2_main, CMakeLists.txt): compiled
// once instead of once per executable.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
