// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_norm: a vector scaled to unit length, pipelined, one vector per clock
// (docs/setup_hw.md#datapath, step 2; the golden model is host::fixed::normalize in
// model/host/setup_fixed.hpp). The input components share any scale (integer codes of the
// geometry span interface or Q44, specular_setup_pkg::UnitFrac); the output is Q44; the zero
// vector gives 0.
//
//   stage 1  sq = x^2 + y^2 + z^2 (exact)
//   stage 2  m = sq 4^k in [2^44, 2^46) (leading-one position); the seed ROM is read
//   stage 3  t = r0^2             stages 4, 5: p = m t, e = 3 - p;  r1 = r0 e / 2
//            (r0 = seed 2^20 exactly: step 1 multiplies the 17-bit seed, t = seed^2 2^4)
//   stage 6  t = r1^2             stages 7, 8: as 4, 5: r2
//   stage 9  u = v r2 2^(k - 23), rounded
// Stages: specular_setup_pkg::NormStages. en_i freezes every stage (pipeline stall). No
// reset: the datapath carries no control state.

`include "specular_assert.svh"

module specular_setup_norm #(
  // Input component width: VecW for Q44 vectors, the interface's VecBits for integer codes
  // (narrower squares and scalings).
  parameter int InW           = specular_setup_pkg::VecW,
  parameter     RsqrtSeedFile = "roms/setup/rsqrt_seed.hex"
) (
  input  logic                                   clk_i,
  input  logic                                   en_i,
  input  logic signed [InW-1:0]                  x_i,
  input  logic signed [InW-1:0]                  y_i,
  input  logic signed [InW-1:0]                  z_i,
  output logic signed [specular_setup_pkg::VecW-1:0] x_o,
  output logic signed [specular_setup_pkg::VecW-1:0] y_o,
  output logic signed [specular_setup_pkg::VecW-1:0] z_o
);

  localparam int W        = specular_setup_pkg::VecW;
  localparam int InBits   = specular_setup_pkg::RsqrtInBits;
  localparam int Frac     = specular_setup_pkg::RsqrtFrac;
  localparam int AddrBits = specular_setup_pkg::RsqrtAddrBits;
  localparam int SeedFrac = specular_setup_pkg::RsqrtSeedFrac;
  localparam int SqBits   = 2 * InW;  // 3 squares of InW-bit values: < 3 2^(2 InW - 2)
  localparam int Stages   = 9;

  if (Stages != specular_setup_pkg::NormStages) begin : gen_stage_check
    `SPEC_PARAM_ERROR("specular_setup_norm: specular_setup_pkg::NormStages disagrees with the stages built here")
  end
  if (InW < 2 || InW > W) begin : gen_width_check
    `SPEC_PARAM_ERROR("specular_setup_norm: InW must be in 2..VecW")
  end

  typedef logic signed [InW-1:0] comp_t;
  // The vector travels beside the reciprocal square root: vec_q[s] after stage s.
  comp_t vx_q [1:Stages-1], vy_q [1:Stages-1], vz_q [1:Stages-1];
  for (genvar s = 1; s < Stages; s++) begin : gen_vec
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        vx_q[s] <= (s == 1) ? x_i : vx_q[s == 1 ? 1 : s - 1];
        vy_q[s] <= (s == 1) ? y_i : vy_q[s == 1 ? 1 : s - 1];
        vz_q[s] <= (s == 1) ? z_i : vz_q[s == 1 ? 1 : s - 1];
      end
    end
  end

  // Stage 1: the squared length.
  logic [SqBits-1:0] sq_q;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      sq_q <= SqBits'(specular_setup_pkg::mul(64'(x_i), 64'(x_i)) + specular_setup_pkg::mul(64'(y_i), 64'(y_i)) +
                      specular_setup_pkg::mul(64'(z_i), 64'(z_i)));
    end
  end

  // Stage 2: even shift into [2^44, 2^46); k = floor((46 - bit width) / 2).
  localparam int ShBits = SqBits > InBits ? SqBits : InBits;  // sq, shifted either way, fits
  logic signed [31:0]   bw;
  logic signed [7:0]    k_d;
  logic [InBits-1:0]    m_d;
  logic [ShBits-1:0]    sq_w;
  assign sq_w = ShBits'(sq_q);
  always_comb begin
    bw = 0;
    for (int b = 0; b < SqBits; b++) begin
      if (sq_q[b]) bw = b + 1;
    end
    k_d = 8'((32'(InBits) - bw) >>> 1);
    if (k_d >= 0) begin
      m_d = InBits'(sq_w << (2 * k_d));
    end else begin
      m_d = InBits'(sq_w >> (-2 * k_d));
    end
  end
  logic [InBits-1:0] m_q [2:Stages-1];
  logic signed [7:0] k_q [2:Stages];
  for (genvar s = 2; s <= Stages; s++) begin : gen_mk
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        k_q[s] <= (s == 2) ? k_d : k_q[s == 2 ? 2 : s - 1];
      end
    end
    if (s < Stages) begin : gen_m
      always_ff @(posedge clk_i) begin
        if (en_i) begin
          m_q[s] <= (s == 2) ? m_d : m_q[s == 2 ? 2 : s - 1];
        end
      end
    end
  end
  // The seed ROM: word a - 2^(AddrBits-2) for address a = m >> (InBits - AddrBits); the zero
  // vector (m = 0) reads word 0 (its output is 0 whatever r is).
  logic [AddrBits-1:0] seed_addr;
  logic [SeedFrac:0]   seed;
  assign seed_addr = m_d[InBits-1 -: 2] == 2'b00 ? '0
                   : AddrBits'(m_d[InBits-1 -: AddrBits] - AddrBits'(1 << (AddrBits - 2)));
  specular_rom #(
    .Width    (SeedFrac + 1),
    .AddrBits (AddrBits),
    .Depth    (3 << (AddrBits - 2)),
    .File     (RsqrtSeedFile)
  ) u_seed_rom (
    .clk_i  (clk_i),
    .en_i   (en_i),
    .addr_i (seed_addr),
    .data_o (seed)
  );

  // Stages 3 .. 8: two Newton-Raphson steps r' = r (3 - m r^2) / 2, three stages each.
  // r, t and e stay within (2^-1, 2^2] of their Q44 unit (t = 4 at m = 2^44): RW bits, signed. Step 1 with
  // r0 = seed 2^(Frac - SeedFrac): t = round(r0^2 2^-Frac) = seed^2 2^(2 (Frac - SeedFrac) - Frac),
  // m t 2^-InBits and r0 e 2^-(Frac + 1) rounded the same from the narrow factors.
  localparam int RW    = Frac + 4;
  localparam int SeedW = SeedFrac + 1;
  localparam int T1Sh  = 2 * (Frac - SeedFrac) - Frac;  // 12: t = seed^2 2^T1Sh
  logic [2*SeedW-1:0]   t1_q;                  // seed^2
  logic [SeedW-1:0]     seed_q3, seed_q4;
  logic signed [RW-1:0] t_q6, e_q4, e_q7, r_q5, r_q6, r_q7, r_q8;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      // step 1
      t1_q    <= (2 * SeedW)'(seed) * (2 * SeedW)'(seed);
      seed_q3 <= seed;
      e_q4    <= RW'((128'sd3 <<< Frac) - specular_setup_pkg::rshift_round(
                     specular_setup_pkg::mul(64'(m_q[3]), 64'(t1_q)), InBits - T1Sh));
      seed_q4 <= seed_q3;
      r_q5    <= RW'(specular_setup_pkg::rshift_round(specular_setup_pkg::mul(64'(seed_q4), 64'(e_q4)),
                                                      Frac + 1 - (Frac - SeedFrac)));
      // step 2
      t_q6 <= RW'(specular_setup_pkg::rshift_round(specular_setup_pkg::mul(64'(r_q5), 64'(r_q5)), Frac));
      r_q6 <= r_q5;
      e_q7 <= RW'((128'sd3 <<< Frac) - specular_setup_pkg::rshift_round(
                  specular_setup_pkg::mul(64'(m_q[6]), 64'(t_q6)), InBits));
      r_q7 <= r_q6;
      r_q8 <= RW'(specular_setup_pkg::rshift_round(specular_setup_pkg::mul(64'(r_q7), 64'(e_q7)), Frac + 1));
    end
  end

  // Stage 9: u = v r 2^(k - 23).
  logic signed [31:0] shift;
  assign shift = 32'(InBits / 2 + Frac - specular_setup_pkg::UnitFrac) - 32'(k_q[8]);
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      x_o <= W'(specular_setup_pkg::rshift_round(specular_setup_pkg::mul(64'(vx_q[8]), 64'(r_q8)), shift));
      y_o <= W'(specular_setup_pkg::rshift_round(specular_setup_pkg::mul(64'(vy_q[8]), 64'(r_q8)), shift));
      z_o <= W'(specular_setup_pkg::rshift_round(specular_setup_pkg::mul(64'(vz_q[8]), 64'(r_q8)), shift));
    end
  end

endmodule
