// SPDX-License-Identifier: Apache-2.0
//
// rtl/specular.f: the product, every IP of the device (the core, the AXI wrappers, the
// hardware setup, the system). The per-pixel competitors (rtl/competitors/) are not in it.
// Format and use: rtl/README.md#filelists.

-f rtl/core/core.f
-f rtl/axi/axi.f
-f rtl/setup/setup.f
-f rtl/system/system.f
