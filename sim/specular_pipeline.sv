// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_pipeline: the stage counts of rtl/prim/specular_pkg.sv for one configuration's widths,
// as public localparams a Verilator testbench reads (docs/pipeline.md#stage-counts). It
// holds no logic: the testbenches take their expected latencies from here, from the
// definition the RTL is built from, never from a parameter of the model under test or a
// copy of the formulas. The widths have no defaults worth the name: every build passes
// them (roms/build_configs.cmake, <ID>_PIPELINE_ARGS).

module specular_pipeline #(
  parameter int PsiMulFrac   /*verilator public*/ = 0,
  parameter int CosDeltaBits /*verilator public*/ = 0,
  parameter int CosDataBits  /*verilator public*/ = 0,
  parameter bit Blend        /*verilator public*/ = 1'b0
) ();

  function automatic logic [8*TreeTableBits-1:0] tree_table();
    tree_table = '0;
    for (int b = 2; b < TreeTableBits; b++) begin
      tree_table[8*b +: 8] = 8'(specular_pkg::pipe_mul_stages(b));
    end
  endfunction

  if (PsiMulFrac < 2 || CosDeltaBits < 1 || CosDataBits < 1) begin : gen_param_check
    $error("specular_pipeline: set PsiMulFrac, CosDeltaBits and CosDataBits (-G)");
  end

  /* verilator lint_off UNUSEDPARAM */
  localparam int StartLatchStages /*verilator public*/ = specular_pkg::StartLatchStages;
  localparam int AccStages        /*verilator public*/ = specular_pkg::AccStages;
  localparam int OutBufStages     /*verilator public*/ = specular_pkg::OutBufStages;
  localparam int Mul11Stages      /*verilator public*/ = specular_pkg::angle_mul_stages(PsiMulFrac);
  localparam int Rom12Stages      /*verilator public*/ = specular_pkg::cos_k_rom_stages(CosDeltaBits);
  localparam int BlendStages      /*verilator public*/ = specular_pkg::blend_stages(Blend, CosDataBits);
  localparam int Mul13Stages      /*verilator public*/ = specular_pkg::intensity_mul_stages(CosDataBits);
  localparam int PipeDepth        /*verilator public*/ =
      specular_pkg::stream_pipe_depth(PsiMulFrac, CosDeltaBits, CosDataBits, Blend);
  localparam int StreamLatency    /*verilator public*/ =
      specular_pkg::stream_latency(PsiMulFrac, CosDeltaBits, CosDataBits, Blend);
  localparam int UnitLatency      /*verilator public*/ =
      specular_pkg::unit_latency(PsiMulFrac, CosDeltaBits, CosDataBits, Blend);
  // specular_pipe_mul's stages for BBits = b in byte b of TreeStagesTable, b = 2 .. 31 (a
  // standalone multiplier of any width the block tests use).
  localparam int TreeTableBits = 32;
  localparam logic [8*TreeTableBits-1:0] TreeStagesTable /*verilator public*/ = tree_table();
  /* verilator lint_on UNUSEDPARAM */

endmodule
