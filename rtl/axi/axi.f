// SPDX-License-Identifier: Apache-2.0
//
// rtl/axi/axi.f: the AXI wrappers of the core, specular_axis (AXI4-Stream) and specular_axil (AXI4-Lite registers, docs/interfaces.md).
// Format and use: rtl/README.md#filelists.

-f rtl/core/core.f
+incdir+rtl/axi
rtl/axi/specular_axis.sv
rtl/axi/specular_axil.sv
