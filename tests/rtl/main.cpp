// SPDX-License-Identifier: Apache-2.0
// Catch2 main of the RTL block tests (tests/rtl).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
