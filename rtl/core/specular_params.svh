// SPDX-License-Identifier: Apache-2.0
//
// The parameter list of the core, written once. specular_stream, specular_unit,
// specular_axis and specular_axil declare it with `SPECULAR_CORE_PARAMS and hand it on to
// the core they wrap with `SPECULAR_CORE_PARAM_MAP; the formal harnesses hand their reduced
// values on with the same map. A parameter added here reaches every top level at once.
//
// Defaults: the configuration "default" of build_configs() (model/device/rom_image.cpp; its
// -G flags in roms/build_configs.cmake are empty), the blend that meets B2
// (docs/display_exact.md); sim_regression and the block tests refuse a model whose parameters
// differ from that configuration's Format. What each parameter is:
//   CBits, CFrac           C and the intensity: bits, fraction bits (CFrac documentary)
//                          (Format::c_bits, c_frac)
//   AngleBits, AngleFrac   psi0 and dpsi: bits, fraction bits (angle_bits, angle_frac)
//   AccBits                register 8, the angle accumulator (acc_bits)
//   NBits, LenBits         n and l (n_bits, len_bits)
//   CoefBits, CoefFrac     a(n) in ROM 9 (coef_bits, coef_frac)
//   PsiMulFrac             fraction bits of |psi| into multiplier 11 (psi_mul_frac)
//   CosInterp              ROM 12 interpolated (1) or direct, as in the patent (0)
//                          (cos_interp)
//   CosAddrBits, CosDataBits, CosDeltaBits, CosFracBits
//                          ROM 12: address bits per bank, bits of cos^k, of the step d and
//                          of the interpolation weight (cos_addr_bits, ...)
//   NumBanks, BankMaxN     decoder 10: the banks, and the largest n of each (NBits bits per
//                          bank, bank 0 in the least significant bits) (banks, bank_max_n)
//   Blend, WeightBits      the display-exact datapath (docs/display_exact.md): two ROM 12 reads
//                          per pixel (decoder 10's bank and the next), blended by a weight of
//                          WeightBits from ROM 9, whose words are then {a1, a2, w}
//                          (Format::blend, weight_bits)
//   MulTileBits            the multipliers' resources (specular_pipe_mul's TileBits): 0 LUT
//                          trees (iCE40-HX8K), 16 SB_MAC16 tiles (UP5K), 18 MULT18X18D tiles
//                          (ECP5); bit-exact and of equal latency in every style
//                          (docs/pipeline.md#multiplier-styles). Not a Format field: the
//                          arithmetic is the same.
//   Channels               1, or 3 (RGB): a span carries Channels values of C (span_c_i
//                          Channels*CBits wide, channel 0 in the low bits) and a pixel as
//                          many intensities (px_intensity_o likewise): one cos^k per pixel
//                          (multiplier 11, ROM 12, the blend) feeds one multiplier 13 per
//                          channel, each rounding as the scalar one; same stage counts. Not
//                          a Format field: each channel is the scalar device's pixel for its
//                          C (DeviceModel::rgb_pixel). specular_stream and specular_axis
//                          take 3; the register interfaces and the system refuse it.
//   CoefRomFile, CosRomFile  the ROM files, read with $readmemh at elaboration, paths
//                          relative to the working directory (formats: roms/README.md)
// The numeric parameters are /*verilator public*/ (Verilator keeps the metacomment in a
// macro body): a Verilator testbench reads them as static constants of the model's root
// class, e.g. to refuse to run when they differ from Format.
// The list ends without a comma, so a module adds its own parameters after `,`.

`ifndef SPECULAR_PARAMS_SVH
`define SPECULAR_PARAMS_SVH

`define SPECULAR_CORE_PARAMS \
  parameter int CBits        /*verilator public*/ = 16, \
  parameter int CFrac        /*verilator public*/ = 15, \
  parameter int AngleBits    /*verilator public*/ = 32, \
  parameter int AngleFrac    /*verilator public*/ = 28, \
  parameter int AccBits      /*verilator public*/ = 44, \
  parameter int NBits        /*verilator public*/ = 10, \
  parameter int LenBits      /*verilator public*/ = 11, \
  parameter int CoefBits     /*verilator public*/ = 13, \
  parameter int CoefFrac     /*verilator public*/ = 9, \
  parameter int PsiMulFrac   /*verilator public*/ = 15, \
  parameter bit CosInterp    /*verilator public*/ = 1'b1, \
  parameter int CosAddrBits  /*verilator public*/ = 7, \
  parameter int CosDataBits  /*verilator public*/ = 12, \
  parameter int CosDeltaBits /*verilator public*/ = 7, \
  parameter int CosFracBits  /*verilator public*/ = 7, \
  parameter int NumBanks     /*verilator public*/ = 4, \
  parameter logic [NumBanks*NBits-1:0] BankMaxN /*verilator public*/ = \
      {10'd1000, 10'd7, 10'd3, 10'd1}, \
  parameter bit Blend        /*verilator public*/ = 1'b1, \
  parameter int WeightBits   /*verilator public*/ = 10, \
  parameter int MulTileBits  /*verilator public*/ = 0, \
  parameter int Channels     /*verilator public*/ = 1, \
  parameter     CoefRomFile = "roms/blend/b2/coef_blend.hex", \
  parameter     CosRomFile  = "roms/blend/b2/cos_k_1_2_4_8_interp128.hex"

`define SPECULAR_CORE_PARAM_MAP \
  .CBits        (CBits), \
  .CFrac        (CFrac), \
  .AngleBits    (AngleBits), \
  .AngleFrac    (AngleFrac), \
  .AccBits      (AccBits), \
  .NBits        (NBits), \
  .LenBits      (LenBits), \
  .CoefBits     (CoefBits), \
  .CoefFrac     (CoefFrac), \
  .PsiMulFrac   (PsiMulFrac), \
  .CosInterp    (CosInterp), \
  .CosAddrBits  (CosAddrBits), \
  .CosDataBits  (CosDataBits), \
  .CosDeltaBits (CosDeltaBits), \
  .CosFracBits  (CosFracBits), \
  .NumBanks     (NumBanks), \
  .BankMaxN     (BankMaxN), \
  .Blend        (Blend), \
  .WeightBits   (WeightBits), \
  .MulTileBits  (MulTileBits), \
  .Channels     (Channels), \
  .CoefRomFile  (CoefRomFile), \
  .CosRomFile   (CosRomFile)

`endif  // SPECULAR_PARAMS_SVH
