// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_pkg: the one definition of the pipeline's stage counts (docs/pipeline.md#stage-counts).
// Every block sizes its delay lines from these functions, the top levels derive PipeDepth
// and Latency from them, and the testbenches read their expected latencies from the same
// functions through sim/specular_pipeline.sv, never from a copy. Changing a stage count is
// an edit here (and, for a register the block does not yet build, in that block). It sits
// with the primitives because every IP sizes its pipeline from it: the multiplier tree's
// count serves the setup and the competitors too, and Icarus 11 cannot evaluate a constant
// function that calls into another package, so the counts cannot be split by IP.
//
// Written for Yosys 0.23, Verilator 5.006 and Icarus 11 alike: functions return through
// their name (Yosys 0.23 has no `return` in constant functions) and callers write
// specular_pkg::f(...) (Yosys 0.23 has no `import` inside a module).

package specular_pkg;

  // ---- Registers outside the multiplier trees (patent block numbers) ----
  // specular_unit: the start latch before the stream accepts the line.
  localparam int StartLatchStages = 1;
  // Register 8 (accumulator 6/7/8): the add split in a low and a high half
  // (specular_accumulator builds exactly two).
  localparam int AccStages = 2;
  // Multiplier 11: one register in front of the tree (|psi| and the coefficient), the
  // ROM 12 address register behind it, then Mul11RetimeStages more registers on the
  // address, weight and zero flag (0 by default; each one is a free register for retiming).
  localparam int Mul11InStages = 1;
  localparam int Mul11OutStages = 1;
  localparam int Mul11RetimeStages = 0;
  // ROM 12: the block-RAM read in front of the interpolation tree, the subtraction
  // v - d t behind it (the direct table is delayed as long).
  localparam int Rom12ReadStages = 1;
  localparam int Rom12OutStages = 1;
  // Multiplier 13: the rounding and output register (output 27) behind the tree.
  localparam int Mul13OutStages = 1;
  // The stream's output buffer (specular_out_buf): one register between the last stage and
  // px_valid_o.
  localparam int OutBufStages = 1;
  // The blend of two ROM 12 reads (Blend = 1, specular_blend; docs/display_exact.md): a register
  // that zeroes each read past its domain, one for the difference c2 - c1 (and 3 w), the tree of
  // the weight product, and the output register (the sum, cos_b).
  localparam int BlendInStages = 1;
  localparam int BlendDiffStages = 1;
  localparam int BlendOutStages = 1;

  // Stages of specular_pipe_mul's radix-4 tree over a b_bits-wide multiplier operand: one
  // register of the selected rows, then one per level of the binary adder tree over the
  // ceil(b_bits / 2) rows.
  function automatic int pipe_mul_stages(input int b_bits);
    pipe_mul_stages = 1 + ((((b_bits + 1) / 2) > 1) ? $clog2((b_bits + 1) / 2) : 0);
  endfunction

  // Tiles of a w-bit signed operand cut into unsigned low tiles of tile_bits - 1 bits and a
  // signed top tile, 1 + ceil((w - tile_bits) / (tile_bits - 1)) of them: specular_pipe_mul
  // with Signed = 1 and the folded setup's specular_setup_fmul.
  function automatic int signed_tiles(input int w, input int tile_bits);
    signed_tiles = (w <= tile_bits) ? 1 : 1 + (w - 2) / (tile_bits - 1);
  endfunction

  // Multiplier 11 (specular_angle_mul), psi_i to addr_o: the tree runs over the
  // 1 + psi_mul_frac bits of |psi|.
  function automatic int angle_mul_stages(input int psi_mul_frac);
    angle_mul_stages = Mul11InStages + pipe_mul_stages(1 + psi_mul_frac) + Mul11OutStages
                       + Mul11RetimeStages;
  endfunction

  // ROM 12 (specular_cos_k_rom), address to cos^k: the tree runs over the cos_delta_bits
  // of the step d.
  function automatic int cos_k_rom_stages(input int cos_delta_bits);
    cos_k_rom_stages = Rom12ReadStages + pipe_mul_stages(cos_delta_bits) + Rom12OutStages;
  endfunction

  // Multiplier 13 (specular_intensity_mul), cos^k to the intensity: the tree runs over the
  // cos_data_bits + 1 bits of cos^k.
  function automatic int intensity_mul_stages(input int cos_data_bits);
    intensity_mul_stages = pipe_mul_stages(cos_data_bits + 1) + Mul13OutStages;
  endfunction

  // The blend (specular_blend), the two reads to cos_b: 0 without it (blend = 0); the tree runs
  // over the cos_data_bits + 2 bits of the offset difference c2 - c1 + 2^(cos_data_bits + 1).
  function automatic int blend_stages(input bit blend, input int cos_data_bits);
    blend_stages = blend ? BlendInStages + BlendDiffStages + pipe_mul_stages(cos_data_bits + 2)
                                  + BlendOutStages : 0;
  endfunction

  // specular_stream's stages from the accept edge to the output buffer (its PipeDepth).
  function automatic int stream_pipe_depth(input int psi_mul_frac, input int cos_delta_bits,
                                           input int cos_data_bits, input bit blend);
    stream_pipe_depth = AccStages + angle_mul_stages(psi_mul_frac)
                        + cos_k_rom_stages(cos_delta_bits) + blend_stages(blend, cos_data_bits)
                        + intensity_mul_stages(cos_data_bits);
  endfunction

  // specular_stream: a span accepted at the edge ending cycle t has pixel 0 on the output
  // in cycle t + stream_latency (px_ready_i high).
  function automatic int stream_latency(input int psi_mul_frac, input int cos_delta_bits,
                                        input int cos_data_bits, input bit blend);
    stream_latency = stream_pipe_depth(psi_mul_frac, cos_delta_bits, cos_data_bits, blend) + OutBufStages;
  endfunction

  // specular_unit: start_i high in cycle s (idle) gives pixel 0 in cycle s + unit_latency.
  function automatic int unit_latency(input int psi_mul_frac, input int cos_delta_bits,
                                      input int cos_data_bits, input bit blend);
    unit_latency = StartLatchStages + stream_latency(psi_mul_frac, cos_delta_bits, cos_data_bits, blend);
  endfunction

endpackage
