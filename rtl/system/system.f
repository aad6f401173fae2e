// SPDX-License-Identifier: Apache-2.0
//
// rtl/system/system.f: specular_system, geometry spans in and pixels out: the setup, then the core (docs/system.md).
// Format and use: rtl/README.md#filelists.

-f rtl/core/core.f
-f rtl/setup/setup.f
rtl/system/specular_system.sv
