// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup: the scanline setup in hardware, fully pipelined, one span per clock
// (SetupII = 1) or folded over SetupII clocks (docs/setup_hw.md#the-datapath). Bit-exact golden
// model: host::fixed::setup_fixed (model/host/setup_fixed.hpp) at F = 26; the steps below are its
// steps 1 .. 7. Geometry spans in (rtl/prim/specular_geo_ports.svh), descriptors and span_status_o out through
// specular_out_buf, AXI4-Stream rules, asynchronous active-low reset dropping every span in
// flight; the buffer's room (adv) enables every stage, so a stall freezes the whole pipeline.
//
// Why this formulation: it has no cancellation (docs/setup_hw.md#the-setup), so F = 26
// bits suffice and every product fits a few 18x18 DSP tiles.
// Every product is a specular_setup_smul (pipelined; TileBits picks DSP tiles or a LUT
// tree) and every rounding, sum or comparison has a stage of its own: no stage holds more
// than one carry chain plus multiplexers (log2 and exp2: a product inline at SetupII = 1).
//
// Pipeline (tau: registers after the input register; the localparams T* below):
//   0        the input register; step 1, decode: invalid_input, undefined_halfway
//   TN       step 2: N1, N2, H1 normalized (three specular_setup_norm)
//   TM..TQ   step 3: m = N1 + N2; q = m.m, hm = He.m (six multipliers, two sums)
//   TON      opposite normals: q < 2^40 (TON = TQ)
//   TGP      G' = q He - 2 hm m (He for opposite normals); TG1: block-normalized
//   TS       s = G'.N1 (Q26);  TGV: G' - rshift_round(s N1, 25);  TG: block-normalized
//   TX2      step 4: x = H1.G, c = H1 x G (wide), p = H1 x N1 (Q26); TXC: x, c block-normalized
//   TD       c.c and x^2; the flat and opposite-halfway tests (opposite_halfway: c := p)
//   TCH      step 5: c_hat = c / |c| (specular_setup_norm)
//   TNU      N1.u = c_hat.p, |c| = c_hat.c (0 when flat)
//   TCOR     step 6: gamma, lambda (two specular_setup_cordic)
//   TNU..TCC step 7, beside the CORDICs: A^2 = cos^2 t1 + (N1.u)^2, log2, (n/2) log2, C
//   TOUT     gamma clamped, psi0; dpsi = rshift_round(2 gamma recip(l), 33 + floor(log2 l))
//   then     the output buffer
// The three decisions are the signals opposite_normals_q (tau TON), flat_q and
// opposite_halfway_q (tau TD), for a test to peek at.
//
// SetupII = K >= 6 folds it in time (docs/setup_hw.md#the-folded-setup): the same stages
// advance once per slot of K clocks (a slot counter; the advance is the slot's last clock
// with room in the output buffer, so geo_ready_o stays a register function and one span
// enters per slot). A product then takes one stage, or none from K = 9 on (its consumer
// reads the unit's chunk registers in the slot's last clock): every product is a lane of a shared
// specular_setup_fmul (three here, one per normalizer, one each in log2 and exp2) whose
// tile multipliers, ceil(lanes / per-multiplier lanes) of them, fall as K grows; each CORDIC
// is a specular_setup_cordic_fold, a chain of segments of two-clock iterations, a segment a
// stage. The stage counts are the package's functions of K, so the T* below and every delay
// line follow.

`include "specular_assert.svh"
`include "specular_geo_ports.svh"
`include "specular_span_ports.svh"

module specular_setup #(
  parameter int VecBits      = 18,
  parameter int TagBits      = 16,
  // specular_pipe_mul's resources: 18 the ECP5's MULT18X18D tiles, 0 a LUT tree (iCE40).
  parameter int TileBits     = 18,
  // Clocks per span: 1 fully pipelined; K >= 6 the folded setup, whose stages advance once
  // per slot of K clocks and whose products share a few tile multipliers (specular_setup_fmul).
  parameter int SetupII      = 1,
  parameter     SeedFile     = "roms/setup/rsqrt_seed.hex",
  parameter     LogRecipFile = "roms/setup/log_recip.hex",
  parameter     LogValueFile = "roms/setup/log_value.hex",
  parameter     Exp2File     = "roms/setup/exp2.hex",
  parameter     RecipLenFile = "roms/setup/recip_len.hex",
  // The long delay lines of Reset = 0 as block-RAM rings (specular_delay Ram = 1); 0 keeps
  // them in registers, the view of the formal harness (rtl/setup/formal/specular_setup_fv.sv),
  // whose probes read the stages (docs/formal.md#specular_delay-the-ring-buffer).
  parameter bit RamLines     = 1'b1,
  localparam int CBits       = specular_setup_pkg::SpanCBits,
  localparam int AngleBits   = specular_setup_pkg::SpanAngleBits,
  localparam int NBits       = specular_setup_pkg::SpanNBits,
  localparam int LenBits     = specular_setup_pkg::SpanLenBits
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  `SPECULAR_GEO_PORTS,
  `SPECULAR_SPAN_PORTS(output, input, _o, _i),
  output logic [2:0]           span_status_o
);

  localparam int F        = specular_setup_pkg::Frac;
  localparam int U        = specular_setup_pkg::UnitW;      // unit vectors
  localparam int BlkW     = specular_setup_pkg::BlkW;       // block-normalized vectors
  localparam int BBits    = specular_setup_pkg::BlockBits;
  localparam int CW       = specular_setup_pkg::CordicW;
  localparam int CFrac    = specular_setup_pkg::CordicFrac;
  localparam int A2W      = specular_setup_pkg::A2W;
  localparam int AngleFrac = specular_setup_pkg::AngleFrac;
  localparam int RecipLenFrac = specular_setup_pkg::RecipLenFrac;
  localparam int GammaFrac = specular_setup_pkg::GammaFrac;
  localparam int LogFrac  = specular_setup_pkg::LogFrac;
  localparam int LogW     = specular_setup_pkg::LogW;
  localparam int ExpW     = specular_setup_pkg::ExpW;
  localparam int MaxN     = 1000;
  localparam int Up       = CFrac - F;                // Q26 -> Q29
  localparam int VW       = CW - Up;                  // x, |c|, cos t1, N1.u before the CORDIC
  localparam int MW       = U + 1;                    // m = N1 + N2
  localparam int QW       = 2 * MW + 2;               // q
  localparam int HW       = VecBits + MW + 2;         // hm
  localparam int GPW      = HW + MW + 2;              // G' before block normalization
  localparam int SW       = 32;                       // s = G'.N1
  localparam int GVW      = 32;                       // G' - 2 s N1 before block normalization
  localparam int XW       = U + BlkW + 2;             // x, c before block normalization
  localparam int PW       = 2 * U + 2;                // p, cos t1 before rounding
  localparam int CCW      = 2 * BlkW + 2;             // c.c
  localparam int GW       = GammaFrac + 3;            // 2 gamma, Q30
  localparam int RLW      = RecipLenFrac + 2;         // the 1/l mantissa, signed
  localparam logic signed [CW-1:0] Pi = CW'(specular_setup_pkg::Pi);

  // The schedule.
  localparam int NS18  = specular_setup_pkg::norm_stages(VecBits, SetupII);
  localparam int NS30  = specular_setup_pkg::norm_stages(BlkW, SetupII);
  localparam int BS    = specular_setup_pkg::BlockStages;
  localparam int CS    = specular_setup_pkg::cordic_stages(SetupII);
  localparam int LMM   = specular_setup_pkg::smul_stages(MW, SetupII);
  localparam int LQ    = specular_setup_pkg::smul_stages(QW, SetupII);
  localparam int LH    = specular_setup_pkg::smul_stages(HW, SetupII);
  localparam int LS    = specular_setup_pkg::smul_stages(BlkW, SetupII);
  localparam int LSN   = specular_setup_pkg::smul_stages(SW, SetupII);
  localparam int LX    = specular_setup_pkg::smul_stages(BlkW, SetupII);
  localparam int LP    = specular_setup_pkg::smul_stages(U, SetupII);
  localparam int LA    = specular_setup_pkg::smul_stages(VW, SetupII);
  localparam int LNL   = specular_setup_pkg::smul_stages(LogW, SetupII);
  localparam int LDP   = specular_setup_pkg::smul_stages(RLW, SetupII);
  localparam int TN    = NS18;
  localparam int TM    = TN + 1;
  localparam int TQ    = TM + LMM + 2;
  localparam int TON   = TQ;
  localparam int TGP   = TQ + LQ + 1;
  localparam int TG1   = TGP + BS;
  localparam int TS    = TG1 + LS + 3;
  localparam int TGV   = TS + LSN + 2;
  localparam int TG    = TGV + BS;
  localparam int TX2   = TG + LX + 2;
  localparam int TXC   = TX2 + BS;
  localparam int TD    = TXC + LX + 4;
  localparam int TCS   = TD + 1;
  localparam int TCH   = TCS + NS30;
  localparam int TNU   = TCH + LX + 3;
  localparam int TCOR  = TNU + CS;
  localparam int TA    = TNU + LA + 1;
  localparam int TL    = TA + specular_setup_pkg::LogStages;
  localparam int TE    = TL + 1 + LNL + 1;
  localparam int TCC   = TE + specular_setup_pkg::ExpStages;
  localparam int TDP   = TCOR + 1 + LDP + 2;  // dpsi
  // Folded, the CORDICs take one stage and C (log2, exp2) is the later one.
  localparam int TOUT  = (TCC > TDP) ? TCC : TDP;
  localparam int OutBits = CBits + 2 * AngleBits + NBits + LenBits + TagBits + 3;

  if (VecBits < 2 || VecBits > 24 || TagBits < 1) begin : gen_param_check
    `SPEC_PARAM_ERROR("specular_setup: VecBits must be in 2..24 and TagBits >= 1")
  end
  // psi0's rounding below is written for a one-bit shift (Q29 -> Q28); the flat test's guard
  // for |x| <= 2^28 (x^2 <= 2^56).
  if (CFrac - AngleFrac != 1 || BBits != 28) begin : gen_width_check
    `SPEC_PARAM_ERROR("specular_setup: psi0's rounding and the decisions' guards assume CordicFrac = AngleFrac + 1 and BlockBits = 28")
  end
  // Products started together must finish together.
  if (LQ != LH || LP != LX || (SetupII == 1 && TCC > TDP)) begin : gen_sched_check
    `SPEC_PARAM_ERROR("specular_setup: the schedule's parallel multipliers disagree in latency")
  end

  if (SetupII < 1 || (SetupII > 1 && SetupII < specular_setup_pkg::MinFoldII)) begin : gen_ii_check
    `SPEC_PARAM_ERROR("specular_setup: SetupII must be 1 or >= specular_setup_pkg::MinFoldII (6)")
  end

  // The advance: the output buffer's room (a register) and, folded, the slot's last clock, so
  // geo_ready_o stays a function of registers and at most one span enters per slot; every
  // stage moves on it. Folded, the AND of the two is itself a register (adv_q, from their
  // next values): the enable of every stage leaves a flip-flop with no gate before its route
  // across the part (docs/setup_hw.md#the-folded-setup).
  logic adv, buf_adv, buf_adv_d, slot_last, slot_first;
  if (SetupII > 1) begin : gen_slot
    localparam int SlotW = $clog2(SetupII);
    // slot_last_q: the compare of slot_d, registered, so that the advance and the output
    // buffer's push take one gate from registers (their enables reach every stage).
    logic [SlotW-1:0] slot_q, slot_d;
    logic             slot_last_q, adv_q;
    always_comb begin
      if (adv) begin
        slot_d = '0;
      end else if (!slot_last_q) begin
        slot_d = slot_q + SlotW'(1);
      end else begin
        slot_d = slot_q;
      end
    end
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        slot_q      <= '0;
        slot_last_q <= 1'b0;
        adv_q       <= 1'b0;
      end else begin
        slot_q      <= slot_d;
        slot_last_q <= slot_d == SlotW'(SetupII - 1);
        adv_q       <= buf_adv_d && slot_d == SlotW'(SetupII - 1);
      end
    end
    `SPEC_ASSERT(SlotLastIsCount_A, slot_last_q == (slot_q == SlotW'(SetupII - 1)), clk_i, rst_ni)
    `SPEC_ASSERT(AdvIsRoomAndSlot_A, adv_q == (buf_adv && slot_last_q), clk_i, rst_ni)
    assign slot_last  = slot_last_q;
    assign slot_first = slot_q == '0;
    assign adv        = adv_q;
  end else begin : gen_no_slot
    logic unused_buf_adv_d;
    assign unused_buf_adv_d = buf_adv_d;
    assign slot_last  = 1'b1;
    assign slot_first = 1'b1;
    assign adv        = buf_adv;
  end
  assign geo_ready_o = adv;

  // Folded, every product is a lane of one of three shared units (specular_setup_fmul), sized
  // by its widths' tiles: 2 x 2 (F44), 1 x 4 (F18) and 2 x 3 (F6). Every operand holds still
  // for the slot, so one unit serves products of different stages; the lanes are numbered at
  // the sites below. Operands are sign-extended, products cut back to their own widths.
  localparam int F44A = 35, F44B = 35, N44 = 40;
  localparam int F18A = 18, F18B = 69, N18 = 7;
  localparam int F6A  = 35, F6B  = 52, N6  = 3;
  logic [N44*F44A-1:0] f44_a;
  logic [N44*F44B-1:0] f44_b;
  logic [N44*(F44A+F44B)-1:0] f44_p;
  logic [N18*F18A-1:0] f18_a;
  logic [N18*F18B-1:0] f18_b;
  logic [N18*(F18A+F18B)-1:0] f18_p;
  logic [N6*F6A-1:0] f6_a;
  logic [N6*F6B-1:0] f6_b;
  logic [N6*(F6A+F6B)-1:0] f6_p;
  logic unused_fold;
  if (SetupII > 1) begin : gen_fold_units
    logic [N44*(F44A+F44B)-1:0] f44_pc;
    logic [N18*(F18A+F18B)-1:0] f18_pc;
    logic [N6*(F6A+F6B)-1:0]    f6_pc;
    specular_setup_fmul #(.N(N44), .ABits(F44A), .BBits(F44B), .TileBits(TileBits), .SetupII(SetupII),
                          .Stages(specular_setup_pkg::fold_mul_stages(SetupII))) u_f44 (
      .clk_i (clk_i), .en_i (adv), .a_i (f44_a), .b_i (f44_b), .p_o (f44_p), .pc_o (f44_pc));
    specular_setup_fmul #(.N(N18), .ABits(F18A), .BBits(F18B), .TileBits(TileBits), .SetupII(SetupII),
                          .Stages(specular_setup_pkg::fold_mul_stages(SetupII))) u_f18 (
      .clk_i (clk_i), .en_i (adv), .a_i (f18_a), .b_i (f18_b), .p_o (f18_p), .pc_o (f18_pc));
    specular_setup_fmul #(.N(N6), .ABits(F6A), .BBits(F6B), .TileBits(TileBits), .SetupII(SetupII),
                          .Stages(specular_setup_pkg::fold_mul_stages(SetupII))) u_f6 (
      .clk_i (clk_i), .en_i (adv), .a_i (f6_a), .b_i (f6_b), .p_o (f6_p), .pc_o (f6_pc));
    // Each lane reads only its own product's width.
    assign unused_fold = ^{f44_p, f18_p, f6_p, f44_pc, f18_pc, f6_pc};
  end else begin : gen_no_fold_units
    assign {f44_a, f44_b, f44_p, f18_a, f18_b, f18_p, f6_a, f6_b, f6_p} = '0;
    assign unused_fold = ^{f44_a, f44_b, f44_p, f18_a, f18_b, f18_p, f6_a, f6_b, f6_p};
  end

  // ---- tau 0: the input register; step 1 ----
  logic                 in_valid_q;
  logic [3*VecBits-1:0] n1_q, n2_q, h1_q, he_q;
  logic [NBits-1:0]     n_q;
  logic [LenBits-1:0]   len_q;
  logic [CBits-1:0]     scale_q;
  logic [TagBits-1:0]   tag_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      in_valid_q <= 1'b0;
    end else if (adv) begin
      in_valid_q <= geo_valid_i;
    end
  end
  always_ff @(posedge clk_i) begin
    if (adv) begin
      n1_q    <= geo_n1_i;
      n2_q    <= geo_n2_i;
      h1_q    <= geo_h1_i;
      he_q    <= geo_he_i;
      n_q     <= geo_n_i;
      len_q   <= geo_len_i;
      scale_q <= geo_scale_i;
      tag_q   <= geo_tag_i;
    end
  end
  // The input's flags, decided on the inputs and registered with them: the compares sit before
  // the input register, not between it and the block-RAM line that carries the flags.
  logic invalid, undefined, invalid_q, undefined_q;
  always_ff @(posedge clk_i) begin
    if (adv) begin
      invalid_q   <= geo_n_i == '0 || geo_n_i > NBits'(MaxN) || geo_n1_i == '0 || geo_n2_i == '0;
      undefined_q <= geo_h1_i == '0 || geo_he_i == '0;
    end
  end
  // Named wires over the registers: the handshake proof cuts the datapath by these names
  // (docs/formal.md#specular_setup-the-span-handshakes), so they stay where the flags
  // leave for the delay line.
  assign invalid   = invalid_q;
  assign undefined = undefined_q;

  // ---- step 2: N1, N2, H1 (tau 0 -> TN) ----
  logic [3*U-1:0] n1u, n2u, h1u;
  specular_setup_norm #(.InW(VecBits), .TileBits(TileBits), .SetupII(SetupII), .SeedFile(SeedFile)) u_norm_n1 (
    .clk_i (clk_i), .en_i (adv),
    .x_i (n1_q[0 +: VecBits]), .y_i (n1_q[VecBits +: VecBits]), .z_i (n1_q[2*VecBits +: VecBits]),
    .x_o (n1u[0 +: U]), .y_o (n1u[U +: U]), .z_o (n1u[2*U +: U]));
  specular_setup_norm #(.InW(VecBits), .TileBits(TileBits), .SetupII(SetupII), .SeedFile(SeedFile)) u_norm_n2 (
    .clk_i (clk_i), .en_i (adv),
    .x_i (n2_q[0 +: VecBits]), .y_i (n2_q[VecBits +: VecBits]), .z_i (n2_q[2*VecBits +: VecBits]),
    .x_o (n2u[0 +: U]), .y_o (n2u[U +: U]), .z_o (n2u[2*U +: U]));
  specular_setup_norm #(.InW(VecBits), .TileBits(TileBits), .SetupII(SetupII), .SeedFile(SeedFile)) u_norm_h1 (
    .clk_i (clk_i), .en_i (adv),
    .x_i (h1_q[0 +: VecBits]), .y_i (h1_q[VecBits +: VecBits]), .z_i (h1_q[2*VecBits +: VecBits]),
    .x_o (h1u[0 +: U]), .y_o (h1u[U +: U]), .z_o (h1u[2*U +: U]));

  // ---- step 3: m, q, hm (TM -> TQ) ----
  logic [3*MW-1:0]      m_q;
  logic [3*VecBits-1:0] he_m, he_q2, he_gp;
  specular_delay #(.Width(3 * VecBits), .Depth(TM), .Reset(1'b0), .Ram(RamLines)) u_dly_he_m (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (he_q), .q_o (he_m));
  specular_delay #(.Width(3 * VecBits), .Depth(TQ - TM), .Reset(1'b0), .Ram(RamLines)) u_dly_he_q (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (he_m), .q_o (he_q2));
  specular_delay #(.Width(3 * VecBits), .Depth(LQ), .Reset(1'b0), .Ram(RamLines)) u_dly_he_gp (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (he_q2), .q_o (he_gp));
  logic signed [2*MW-1:0]        mm [3];
  logic signed [VecBits+MW-1:0]  hem [3];
  for (genvar i = 0; i < 3; i++) begin : gen_m
    always_ff @(posedge clk_i) begin
      if (adv) m_q[i*MW +: MW] <= MW'($signed(n1u[i*U +: U])) + MW'($signed(n2u[i*U +: U]));
    end
    if (SetupII > 1) begin : gen_mm_fold
      assign f44_a[(0 + i)*F44A +: F44A] = F44A'($signed(m_q[i*MW +: MW]));
      assign f44_b[(0 + i)*F44B +: F44B] = F44B'($signed(m_q[i*MW +: MW]));
      assign mm[i] = (MW + MW)'(f44_p[(0 + i)*(F44A + F44B) +: F44A + F44B]);
    end else begin : gen_mm_pipe
      specular_setup_smul #(.ABits(MW), .BBits(MW), .TileBits(TileBits)) u_mm (
        .clk_i (clk_i), .en_i (adv), .a_i (m_q[i*MW +: MW]), .b_i (m_q[i*MW +: MW]), .p_o (mm[i]));
    end
    if (SetupII > 1) begin : gen_hem_fold
      assign f18_a[(0 + i)*F18A +: F18A] = F18A'($signed(he_m[i*VecBits +: VecBits]));
      assign f18_b[(0 + i)*F18B +: F18B] = F18B'($signed(m_q[i*MW +: MW]));
      assign hem[i] = (VecBits + MW)'(f18_p[(0 + i)*(F18A + F18B) +: F18A + F18B]);
    end else begin : gen_hem_pipe
      specular_setup_smul #(.ABits(VecBits), .BBits(MW), .TileBits(TileBits)) u_hem (
        .clk_i (clk_i), .en_i (adv), .a_i (he_m[i*VecBits +: VecBits]), .b_i (m_q[i*MW +: MW]), .p_o (hem[i]));
    end
  end
  logic signed [QW-1:0] q01_q, q2_q, q_q;
  logic signed [HW-1:0] hm01_q, hm2_q, hm_q;
  always_ff @(posedge clk_i) begin
    if (adv) begin
      q01_q  <= QW'(mm[0]) + QW'(mm[1]);
      q2_q   <= QW'(mm[2]);
      q_q    <= q01_q + q2_q;
      hm01_q <= HW'(hem[0]) + HW'(hem[1]);
      hm2_q  <= HW'(hem[2]);
      hm_q   <= hm01_q + hm2_q;
    end
  end
  // Opposite normals (tau TON, beside q_q): |N1 + N2|^2 < 2^-12, q = q01 + q2 < 2^OnB. Both
  // are sums of squares, so that holds when neither has a bit from OnB up and their low OnB
  // bits do not carry out: one carry chain from the registers, and the decision is ready with
  // q for G' in the next stage even when its products take no stage (the folded setup).
  localparam int OnB = 2 * F - specular_setup_pkg::OppNormLog2;
  logic [OnB:0] q_low_sum;
  assign q_low_sum = {1'b0, q01_q[OnB-1:0]} + {1'b0, q2_q[OnB-1:0]};
  logic opposite_normals_q, opp_n_gp;
  always_ff @(posedge clk_i) begin
    if (adv) opposite_normals_q <= !(|q01_q[QW-1:OnB]) && !(|q2_q[QW-1:OnB]) && !q_low_sum[OnB];
  end
  specular_delay #(.Width(1), .Depth(TQ + LQ - TON), .Reset(1'b0), .Ram(RamLines)) u_dly_oppn_gp (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (opposite_normals_q), .q_o (opp_n_gp));

  // ---- G' = q He - 2 hm m (TQ -> TGP), block-normalized (TG1) ----
  logic [3*MW-1:0]  m_gq;
  specular_delay #(.Width(3 * MW), .Depth(TQ - TM), .Reset(1'b0), .Ram(RamLines)) u_dly_m (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (m_q), .q_o (m_gq));
  logic [3*GPW-1:0] gp_q;
  for (genvar i = 0; i < 3; i++) begin : gen_gp
    logic signed [VecBits+QW-1:0] qhe;
    logic signed [MW+HW-1:0]      hmm;
    if (SetupII > 1) begin : gen_qhe_fold
      assign f18_a[(3 + i)*F18A +: F18A] = F18A'($signed(he_q2[i*VecBits +: VecBits]));
      assign f18_b[(3 + i)*F18B +: F18B] = F18B'($signed(q_q));
      assign qhe = (VecBits + QW)'(f18_p[(3 + i)*(F18A + F18B) +: F18A + F18B]);
    end else begin : gen_qhe_pipe
      specular_setup_smul #(.ABits(VecBits), .BBits(QW), .TileBits(TileBits)) u_qhe (
        .clk_i (clk_i), .en_i (adv), .a_i (he_q2[i*VecBits +: VecBits]), .b_i (q_q), .p_o (qhe));
    end
    if (SetupII > 1) begin : gen_hmm_fold
      assign f6_a[(0 + i)*F6A +: F6A] = F6A'($signed(m_gq[i*MW +: MW]));
      assign f6_b[(0 + i)*F6B +: F6B] = F6B'($signed(hm_q));
      assign hmm = (MW + HW)'(f6_p[(0 + i)*(F6A + F6B) +: F6A + F6B]);
    end else begin : gen_hmm_pipe
      specular_setup_smul #(.ABits(MW), .BBits(HW), .TileBits(TileBits)) u_hmm (
        .clk_i (clk_i), .en_i (adv), .a_i (m_gq[i*MW +: MW]), .b_i (hm_q), .p_o (hmm));
    end
    always_ff @(posedge clk_i) begin
      if (adv) begin
        gp_q[i*GPW +: GPW] <= opp_n_gp ? GPW'($signed(he_gp[i*VecBits +: VecBits]))
                                       : GPW'(qhe) - (GPW'(hmm) <<< 1);
      end
    end
  end
  logic [3*BlkW-1:0] gpn;
  specular_setup_block #(.N(3), .InW(GPW), .Bits(BBits), .SetupII(SetupII)) u_blk_gp (
    .clk_i (clk_i), .en_i (adv), .x_i (gp_q), .x_o (gpn));

  // N1 beside: to TG1 (s), TS (s N1), TG (H1 x G's partner N1 x H1), TCH (p kept since TX2).
  logic [3*U-1:0] n1_g1, n1_s, n1_g, h1_g;
  specular_delay #(.Width(3 * U), .Depth(TG1 - TN), .Reset(1'b0), .Ram(RamLines)) u_dly_n1_g1 (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (n1u), .q_o (n1_g1));
  specular_delay #(.Width(3 * U), .Depth(TS - TG1), .Reset(1'b0), .Ram(RamLines)) u_dly_n1_s (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (n1_g1), .q_o (n1_s));
  specular_delay #(.Width(3 * U), .Depth(TG - TS), .Reset(1'b0), .Ram(RamLines)) u_dly_n1_g (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (n1_s), .q_o (n1_g));
  specular_delay #(.Width(3 * U), .Depth(TG - TN), .Reset(1'b0), .Ram(RamLines)) u_dly_h1_g (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (h1u), .q_o (h1_g));

  // ---- s = rshift_round(G'.N1, 26) (TG1 -> TS) ----
  logic signed [U+BlkW-1:0] sp [3];
  for (genvar i = 0; i < 3; i++) begin : gen_s
    if (SetupII > 1) begin : gen_sp_fold
      assign f44_a[(3 + i)*F44A +: F44A] = F44A'($signed(n1_g1[i*U +: U]));
      assign f44_b[(3 + i)*F44B +: F44B] = F44B'($signed(gpn[i*BlkW +: BlkW]));
      assign sp[i] = (U + BlkW)'(f44_p[(3 + i)*(F44A + F44B) +: F44A + F44B]);
    end else begin : gen_sp_pipe
      specular_setup_smul #(.ABits(U), .BBits(BlkW), .TileBits(TileBits)) u_sp (
        .clk_i (clk_i), .en_i (adv), .a_i (n1_g1[i*U +: U]), .b_i (gpn[i*BlkW +: BlkW]), .p_o (sp[i]));
    end
  end
  logic signed [U+BlkW+1:0] s01_q, s2_q, ssum_q;
  logic signed [SW-1:0]     s_q;
  always_ff @(posedge clk_i) begin
    if (adv) begin
      s01_q  <= (U + BlkW + 2)'(sp[0]) + (U + BlkW + 2)'(sp[1]);
      s2_q   <= (U + BlkW + 2)'(sp[2]);
      ssum_q <= s01_q + s2_q;
      s_q    <= SW'((ssum_q + (U + BlkW + 2)'(64'sd1 <<< (F - 1))) >>> F);
    end
  end

  // ---- G = block_normalize(G' - rshift_round(s N1, 25)) (TS -> TG) ----
  logic [3*BlkW-1:0] gpn_s;
  specular_delay #(.Width(3 * BlkW), .Depth(TS + LSN + 1 - TG1), .Reset(1'b0), .Ram(RamLines)) u_dly_gpn (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (gpn), .q_o (gpn_s));
  logic [3*GVW-1:0] gv_q;
  for (genvar i = 0; i < 3; i++) begin : gen_gv
    logic signed [U+SW-1:0] sn;
    logic signed [GVW-1:0]  t_q;
    if (SetupII > 1) begin : gen_sn_fold
      assign f44_a[(6 + i)*F44A +: F44A] = F44A'($signed(n1_s[i*U +: U]));
      assign f44_b[(6 + i)*F44B +: F44B] = F44B'($signed(s_q));
      assign sn = (U + SW)'(f44_p[(6 + i)*(F44A + F44B) +: F44A + F44B]);
    end else begin : gen_sn_pipe
      specular_setup_smul #(.ABits(U), .BBits(SW), .TileBits(TileBits)) u_sn (
        .clk_i (clk_i), .en_i (adv), .a_i (n1_s[i*U +: U]), .b_i (s_q), .p_o (sn));
    end
    always_ff @(posedge clk_i) begin
      if (adv) begin
        t_q                <= GVW'((sn + (U + SW)'(64'sd1 <<< (F - 2))) >>> (F - 1));
        gv_q[i*GVW +: GVW] <= GVW'($signed(gpn_s[i*BlkW +: BlkW])) - t_q;
      end
    end
  end
  logic [3*BlkW-1:0] g;
  // G' reflected through the plane normal to the unit N1: its length stays in [2^27, sqrt(3) 2^28]
  // (G' block-normalized), so its largest component's top bit is 26, 27 or 28
  // (docs/setup_hw.md#the-rtl); one bit of margin.
  specular_setup_block #(.N(3), .InW(GVW), .Bits(BBits), .SetupII(SetupII),
                              .TopLo(BBits - 2), .TopHi(BBits + 1)) u_blk_g (
    .clk_i (clk_i), .en_i (adv), .x_i (gv_q), .x_o (g));

  // ---- step 4: x = H1.G, c = H1 x G; p = H1 x N1, cos t1 = N1.H1 (TG -> TX2) ----
  // hg[3 j + k] = H1_j G_k, hn[3 j + k] = H1_j N1_k.
  logic signed [U+BlkW-1:0] hg [9];
  logic signed [2*U-1:0]    hn [9];
  for (genvar j = 0; j < 3; j++) begin : gen_hj
    for (genvar k = 0; k < 3; k++) begin : gen_k
      if (SetupII > 1) begin : gen_hg_fold
        assign f44_a[(9 + 3 * j + k)*F44A +: F44A] = F44A'($signed(h1_g[j*U +: U]));
        assign f44_b[(9 + 3 * j + k)*F44B +: F44B] = F44B'($signed(g[k*BlkW +: BlkW]));
        assign hg[3*j+k] = (U + BlkW)'(f44_p[(9 + 3 * j + k)*(F44A + F44B) +: F44A + F44B]);
      end else begin : gen_hg_pipe
        specular_setup_smul #(.ABits(U), .BBits(BlkW), .TileBits(TileBits)) u_hg (
          .clk_i (clk_i), .en_i (adv), .a_i (h1_g[j*U +: U]), .b_i (g[k*BlkW +: BlkW]), .p_o (hg[3*j+k]));
      end
      if (SetupII > 1) begin : gen_hn_fold
        assign f44_a[(18 + 3 * j + k)*F44A +: F44A] = F44A'($signed(h1_g[j*U +: U]));
        assign f44_b[(18 + 3 * j + k)*F44B +: F44B] = F44B'($signed(n1_g[k*U +: U]));
        assign hn[3*j+k] = (U + U)'(f44_p[(18 + 3 * j + k)*(F44A + F44B) +: F44A + F44B]);
      end else begin : gen_hn_pipe
        specular_setup_smul #(.ABits(U), .BBits(U), .TileBits(TileBits)) u_hn (
          .clk_i (clk_i), .en_i (adv), .a_i (h1_g[j*U +: U]), .b_i (n1_g[k*U +: U]), .p_o (hn[3*j+k]));
      end
    end
  end
  logic signed [XW-1:0] x01_q, xz_q, x_q;
  logic signed [PW-1:0] cos01_q, cosz_q, cos_q2;
  logic [3*XW-1:0] c1_q, c2_q;
  logic [3*PW-1:0] p1_q;
  logic [3*BlkW-1:0] p2_q;
  logic signed [BlkW-1:0] cos_x3;
  for (genvar i = 0; i < 3; i++) begin : gen_cross
    localparam int J = (i + 1) % 3;
    localparam int K = (i + 2) % 3;
    always_ff @(posedge clk_i) begin
      if (adv) begin
        // c_i = H1_J G_K - H1_K G_J, p_i likewise with N1.
        c1_q[i*XW +: XW] <= XW'(hg[3*J+K]) - XW'(hg[3*K+J]);
        c2_q[i*XW +: XW] <= c1_q[i*XW +: XW];
        p1_q[i*PW +: PW] <= PW'(hn[3*J+K]) - PW'(hn[3*K+J]);
        p2_q[i*BlkW +: BlkW] <= BlkW'(($signed(p1_q[i*PW +: PW]) + PW'(64'sd1 <<< (F - 1))) >>> F);
      end
    end
  end
  always_ff @(posedge clk_i) begin
    if (adv) begin
      x01_q   <= XW'(hg[0]) + XW'(hg[4]);
      xz_q    <= XW'(hg[8]);
      x_q     <= x01_q + xz_q;
      cos01_q <= PW'(hn[0]) + PW'(hn[4]);
      cosz_q  <= PW'(hn[8]);
      cos_q2  <= cos01_q + cosz_q;
      cos_x3  <= BlkW'((cos_q2 + PW'(64'sd1 <<< (F - 1))) >>> F);
    end
  end
  // x and c block-normalized together (TX2 -> TXC): {c_z, c_y, c_x, x}.
  logic [4*BlkW-1:0] xc;
  // x^2 + |c|^2 = |H1|^2 |G|^2 (Lagrange), |H1| = 2^26, |G| in [2^27, sqrt(3) 2^28]: the largest
  // of the four has its top bit at 51 .. 54 (docs/setup_hw.md#the-rtl).
  specular_setup_block #(.N(4), .InW(XW), .Bits(BBits), .SetupII(SetupII),
                              .TopLo(F + BBits - 3), .TopHi(F + BBits)) u_blk_xc (
    .clk_i (clk_i), .en_i (adv), .x_i ({c2_q, x_q}), .x_o (xc));
  logic signed [BlkW-1:0] xb;
  logic [3*BlkW-1:0]      cb;
  assign xb = xc[0 +: BlkW];
  assign cb = xc[BlkW +: 3*BlkW];

  // ---- the decisions (TXC -> TD) ----
  logic signed [2*BlkW-1:0] ccp [3];
  logic signed [2*BlkW-1:0] xxp;
  for (genvar i = 0; i < 3; i++) begin : gen_cc
    if (SetupII > 1) begin : gen_cc_fold
      assign f44_a[(27 + i)*F44A +: F44A] = F44A'($signed(cb[i*BlkW +: BlkW]));
      assign f44_b[(27 + i)*F44B +: F44B] = F44B'($signed(cb[i*BlkW +: BlkW]));
      assign ccp[i] = (BlkW + BlkW)'(f44_p[(27 + i)*(F44A + F44B) +: F44A + F44B]);
    end else begin : gen_cc_pipe
      specular_setup_smul #(.ABits(BlkW), .BBits(BlkW), .TileBits(TileBits)) u_cc (
        .clk_i (clk_i), .en_i (adv), .a_i (cb[i*BlkW +: BlkW]), .b_i (cb[i*BlkW +: BlkW]), .p_o (ccp[i]));
    end
  end
  if (SetupII > 1) begin : gen_xx_fold
    assign f44_a[(30)*F44A +: F44A] = F44A'($signed(xb));
    assign f44_b[(30)*F44B +: F44B] = F44B'($signed(xb));
    assign xxp = (BlkW + BlkW)'(f44_p[(30)*(F44A + F44B) +: F44A + F44B]);
  end else begin : gen_xx_pipe
    specular_setup_smul #(.ABits(BlkW), .BBits(BlkW), .TileBits(TileBits)) u_xx (
      .clk_i (clk_i), .en_i (adv), .a_i (xb), .b_i (xb), .p_o (xxp));
  end
  logic signed [BlkW-1:0] x_d;  // x at TXC + LX
  specular_delay #(.Width(BlkW), .Depth(LX), .Reset(1'b0), .Ram(RamLines)) u_dly_x_d (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (xb), .q_o (x_d));
  // c.c (f - 1) < x^2 with f = 2^K: c.c >= 2^(60 - K) makes the left side exceed x^2 <= 2^56;
  // below, the left side fits 60 bits.
  localparam int KF = specular_setup_pkg::FlatLog2;
  localparam int KH = specular_setup_pkg::OppHalfLog2;
  logic [CCW-1:0] cc01_q, cc2_q, cc_q;
  logic [63:0]    xx1_q, xx2_q, xx3_q, lhs_f_q, lhs_h_q;
  logic           big_f_q, big_h_q, xpos1_q, xpos2_q, xpos3_q, xneg1_q, xneg2_q, xneg3_q;
  logic           flat_q, opposite_halfway_q;
  always_ff @(posedge clk_i) begin
    if (adv) begin
      cc01_q  <= CCW'(ccp[0]) + CCW'(ccp[1]);
      cc2_q   <= CCW'(ccp[2]);
      xx1_q   <= 64'(xxp);
      xpos1_q <= !x_d[BlkW-1] && x_d != '0;
      xneg1_q <= x_d[BlkW-1];
      cc_q    <= cc01_q + cc2_q;
      xx2_q   <= xx1_q;
      xpos2_q <= xpos1_q;
      xneg2_q <= xneg1_q;
      big_f_q <= cc_q >= CCW'(64'd1 << (60 - KF));
      big_h_q <= cc_q >= CCW'(64'd1 << (60 - KH));
      lhs_f_q <= (64'(cc_q[60-KF-1:0]) << KF) - 64'(cc_q[60-KF-1:0]);
      lhs_h_q <= (64'(cc_q[60-KH-1:0]) << KH) - 64'(cc_q[60-KH-1:0]);
      xx3_q   <= xx2_q;
      xpos3_q <= xpos2_q;
      xneg3_q <= xneg2_q;
      flat_q             <= xpos3_q && !big_f_q && lhs_f_q < xx3_q;
      opposite_halfway_q <= xneg3_q && !big_h_q && lhs_h_q < xx3_q;
    end
  end

  // ---- step 5: c := p for opposite halfway vectors; c_hat, N1.u, |c| (TD -> TNU) ----
  logic [3*BlkW-1:0] c_td, p_td, csel_q, c_nu, p_nu;
  specular_delay #(.Width(3 * BlkW), .Depth(TD - TXC), .Reset(1'b0), .Ram(RamLines)) u_dly_c_td (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (cb), .q_o (c_td));
  specular_delay #(.Width(3 * BlkW), .Depth(TD - TX2), .Reset(1'b0), .Ram(RamLines)) u_dly_p_td (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (p2_q), .q_o (p_td));
  always_ff @(posedge clk_i) begin
    if (adv) csel_q <= opposite_halfway_q ? p_td : c_td;
  end
  logic [3*U-1:0] ch;
  specular_setup_norm #(.InW(BlkW), .TileBits(TileBits), .SetupII(SetupII), .SeedFile(SeedFile)) u_norm_c (
    .clk_i (clk_i), .en_i (adv),
    .x_i (csel_q[0 +: BlkW]), .y_i (csel_q[BlkW +: BlkW]), .z_i (csel_q[2*BlkW +: BlkW]),
    .x_o (ch[0 +: U]), .y_o (ch[U +: U]), .z_o (ch[2*U +: U]));
  specular_delay #(.Width(3 * BlkW), .Depth(TCH - TCS), .Reset(1'b0), .Ram(RamLines)) u_dly_c_nu (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (csel_q), .q_o (c_nu));
  specular_delay #(.Width(3 * BlkW), .Depth(TCH - TD), .Reset(1'b0), .Ram(RamLines)) u_dly_p_nu (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (p_td), .q_o (p_nu));
  logic signed [U+BlkW-1:0] chp [3], chc [3];
  for (genvar i = 0; i < 3; i++) begin : gen_nu
    if (SetupII > 1) begin : gen_chp_fold
      assign f44_a[(31 + i)*F44A +: F44A] = F44A'($signed(ch[i*U +: U]));
      assign f44_b[(31 + i)*F44B +: F44B] = F44B'($signed(p_nu[i*BlkW +: BlkW]));
      assign chp[i] = (U + BlkW)'(f44_p[(31 + i)*(F44A + F44B) +: F44A + F44B]);
    end else begin : gen_chp_pipe
      specular_setup_smul #(.ABits(U), .BBits(BlkW), .TileBits(TileBits)) u_chp (
        .clk_i (clk_i), .en_i (adv), .a_i (ch[i*U +: U]), .b_i (p_nu[i*BlkW +: BlkW]), .p_o (chp[i]));
    end
    if (SetupII > 1) begin : gen_chc_fold
      assign f44_a[(34 + i)*F44A +: F44A] = F44A'($signed(ch[i*U +: U]));
      assign f44_b[(34 + i)*F44B +: F44B] = F44B'($signed(c_nu[i*BlkW +: BlkW]));
      assign chc[i] = (U + BlkW)'(f44_p[(34 + i)*(F44A + F44B) +: F44A + F44B]);
    end else begin : gen_chc_pipe
      specular_setup_smul #(.ABits(U), .BBits(BlkW), .TileBits(TileBits)) u_chc (
        .clk_i (clk_i), .en_i (adv), .a_i (ch[i*U +: U]), .b_i (c_nu[i*BlkW +: BlkW]), .p_o (chc[i]));
    end
  end
  logic flat_nu;
  specular_delay #(.Width(1), .Depth(TNU - 1 - TD), .Reset(1'b0), .Ram(RamLines)) u_dly_flat_nu (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (flat_q), .q_o (flat_nu));
  localparam int DW = U + BlkW + 2;
  logic signed [DW-1:0] nu01_q, nu2_q, nus_q, cl01_q, cl2_q, cls_q;
  logic signed [VW-1:0] nu_q, cl_q;
  always_ff @(posedge clk_i) begin
    if (adv) begin
      nu01_q <= DW'(chp[0]) + DW'(chp[1]);
      nu2_q  <= DW'(chp[2]);
      nus_q  <= nu01_q + nu2_q;
      cl01_q <= DW'(chc[0]) + DW'(chc[1]);
      cl2_q  <= DW'(chc[2]);
      cls_q  <= cl01_q + cl2_q;
      nu_q   <= flat_nu ? '0 : VW'((nus_q + DW'(64'sd1 <<< (F - 1))) >>> F);
      cl_q   <= flat_nu ? '0 : VW'((cls_q + DW'(64'sd1 <<< (F - 1))) >>> F);
    end
  end

  // ---- step 6: the angles (TNU -> TCOR) ----
  logic signed [BlkW-1:0] x_nu, cos_nu;
  specular_delay #(.Width(BlkW), .Depth(TNU - TXC), .Reset(1'b0), .Ram(RamLines)) u_dly_x_nu (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (xb), .q_o (x_nu));
  specular_delay #(.Width(BlkW), .Depth(TNU - (TX2 + 1)), .Reset(1'b0), .Ram(RamLines)) u_dly_cos_nu (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (cos_x3), .q_o (cos_nu));
  logic signed [CW-1:0] gamma_raw, lambda;
  if (SetupII > 1) begin : gen_cordic_fold
    // Segments of two-clock iterations (docs/setup_hw.md#the-folded-cordic): every segment
    // starts on the slot's first clock (the operands hold still for the slot) and is done
    // before its last, whose advance registers the last segment's angle.
    localparam int Rounds = specular_setup_pkg::cordic_rounds(SetupII);
    logic signed [CW-1:0] g_angle, l_angle;
    logic                 g_done, l_done;
    specular_setup_cordic_fold #(.W(CW), .Frac(CFrac), .Iters(specular_setup_pkg::CordicIters),
                                 .Rounds(Rounds)) u_cordic_gamma (
      .clk_i (clk_i), .rst_ni (rst_ni), .start_i (slot_first), .x_i (CW'(x_nu) <<< Up),
      .y_i (CW'(cl_q) <<< Up), .angle_o (g_angle), .done_o (g_done));
    specular_setup_cordic_fold #(.W(CW), .Frac(CFrac), .Iters(specular_setup_pkg::CordicIters),
                                 .Rounds(Rounds)) u_cordic_lambda (
      .clk_i (clk_i), .rst_ni (rst_ni), .start_i (slot_first), .x_i (CW'(cos_nu) <<< Up),
      .y_i (CW'(nu_q) <<< Up), .angle_o (l_angle), .done_o (l_done));
    always_ff @(posedge clk_i) begin
      if (adv) begin
        gamma_raw <= g_angle;
        lambda    <= l_angle;
      end
    end
    // The schedule's premise: the angles are final at every advance.
    `SPEC_ASSERT(CordicDone_A, !adv || (g_done && l_done), clk_i, rst_ni)
  end else begin : gen_cordic_pipe
    logic unused_first;
    assign unused_first = slot_first;
    specular_setup_cordic u_cordic_gamma (
      .clk_i (clk_i), .en_i (adv), .x_i (CW'(x_nu) <<< Up), .y_i (CW'(cl_q) <<< Up), .angle_o (gamma_raw));
    specular_setup_cordic u_cordic_lambda (
      .clk_i (clk_i), .en_i (adv), .x_i (CW'(cos_nu) <<< Up), .y_i (CW'(nu_q) <<< Up), .angle_o (lambda));
  end

  // ---- step 7: A^2 and C beside the CORDICs (TNU -> TCC) ----
  logic signed [2*VW-1:0] cos2, nu2;
  if (SetupII > 1) begin : gen_cos2_fold
    assign f44_a[(37)*F44A +: F44A] = F44A'($signed(VW'(cos_nu)));
    assign f44_b[(37)*F44B +: F44B] = F44B'($signed(VW'(cos_nu)));
    assign cos2 = (VW + VW)'(f44_p[(37)*(F44A + F44B) +: F44A + F44B]);
  end else begin : gen_cos2_pipe
    specular_setup_smul #(.ABits(VW), .BBits(VW), .TileBits(TileBits)) u_cos2 (
      .clk_i (clk_i), .en_i (adv), .a_i (VW'(cos_nu)), .b_i (VW'(cos_nu)), .p_o (cos2));
  end
  if (SetupII > 1) begin : gen_nu2_fold
    assign f44_a[(38)*F44A +: F44A] = F44A'($signed(nu_q));
    assign f44_b[(38)*F44B +: F44B] = F44B'($signed(nu_q));
    assign nu2 = (VW + VW)'(f44_p[(38)*(F44A + F44B) +: F44A + F44B]);
  end else begin : gen_nu2_pipe
    specular_setup_smul #(.ABits(VW), .BBits(VW), .TileBits(TileBits)) u_nu2 (
      .clk_i (clk_i), .en_i (adv), .a_i (nu_q), .b_i (nu_q), .p_o (nu2));
  end
  logic signed [A2W-1:0] a2_q;
  always_ff @(posedge clk_i) begin
    if (adv) a2_q <= A2W'(cos2) + A2W'(nu2);
  end
  logic signed [LogW-1:0] log2_a, log2_a2_q;
  specular_setup_log2 #(.AmpW(A2W), .SetupII(SetupII), .TileBits(TileBits), .LogRecipFile(LogRecipFile), .LogValueFile(LogValueFile)) u_log2 (
    .clk_i (clk_i), .en_i (adv), .a_i (a2_q), .log2_o (log2_a));
  always_ff @(posedge clk_i) begin
    // log2_unit reads A^2 (Q52) as Q44.
    if (adv) log2_a2_q <= log2_a - LogW'(64'sd1 <<< (LogFrac + 3));
  end
  logic [NBits-1:0] n_l;
  specular_delay #(.Width(NBits), .Depth(TL + 1), .Reset(1'b0), .Ram(RamLines)) u_dly_n_l (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (n_q), .q_o (n_l));
  logic signed [NBits+LogW:0] nl;
  if (SetupII > 1) begin : gen_nl_fold
    assign f18_a[(6)*F18A +: F18A] = F18A'($signed($signed({1'b0, n_l})));
    assign f18_b[(6)*F18B +: F18B] = F18B'($signed(log2_a2_q));
    assign nl = (NBits + 1 + LogW)'(f18_p[(6)*(F18A + F18B) +: F18A + F18B]);
  end else begin : gen_nl_pipe
    specular_setup_smul #(.ABits(NBits + 1), .BBits(LogW), .TileBits(TileBits)) u_nl (
      .clk_i (clk_i), .en_i (adv), .a_i ($signed({1'b0, n_l})), .b_i (log2_a2_q), .p_o (nl));
  end
  logic signed [ExpW-1:0] e_q;
  always_ff @(posedge clk_i) begin
    if (adv) e_q <= ExpW'((nl + (NBits + LogW + 1)'(1)) >>> 1);
  end
  logic [CBits-1:0] scale_e, c_cc, c_out;
  specular_delay #(.Width(CBits), .Depth(TE), .Reset(1'b0), .Ram(RamLines)) u_dly_scale (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (scale_q), .q_o (scale_e));
  logic sat_unused;
  specular_setup_exp2 #(.CBits(CBits), .SetupII(SetupII), .TileBits(TileBits), .Exp2File(Exp2File)) u_exp2 (
    .clk_i (clk_i), .en_i (adv), .e_i (e_q), .scale_i (scale_e), .c_o (c_cc), .sat_o (sat_unused));
  specular_delay #(.Width(CBits), .Depth(TOUT - TCC), .Reset(1'b0), .Ram(RamLines)) u_dly_c (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (c_cc), .q_o (c_out));
  logic a_pos_out;
  specular_delay #(.Width(1), .Depth(TOUT - TA), .Reset(1'b0), .Ram(RamLines)) u_dly_apos (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (a2_q != '0), .q_o (a_pos_out));

  // ---- step 7: gamma, psi0, dpsi (TCOR -> TOUT) ----
  logic flat_cor, opph_cor;
  specular_delay #(.Width(2), .Depth(TCOR - TD), .Reset(1'b0), .Ram(RamLines)) u_dly_flags_cor (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i ({flat_q, opposite_halfway_q}), .q_o ({flat_cor, opph_cor}));
  logic [LenBits-1:0] len_pre, len_cor;
  specular_delay #(.Width(LenBits), .Depth(TCOR - 1), .Reset(1'b0), .Ram(RamLines)) u_dly_len_cor (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (len_q), .q_o (len_pre));
  always_ff @(posedge clk_i) begin
    if (adv) len_cor <= len_pre;
  end
  logic signed [CW-1:0] gamma_q;
  logic [AngleBits-1:0] psi0_q, psi0_out;
  logic [3:0]           lshift_d, lshift_q, lshift_dp;
  always_comb begin
    lshift_d = '0;
    for (int b = 0; b < LenBits; b++) begin
      if (len_cor[b]) lshift_d = 4'(b);
    end
  end
  // gamma's clamp to [0, pi]. Folded, gamma_raw holds for the slot: its compares are registered
  // on every clock (valid from the slot's second), so the advance's clock holds the multiplexer
  // alone (docs/setup_hw.md#the-folded-setup).
  logic g_neg, g_big;
  if (SetupII > 1) begin : gen_gclamp_reg
    always_ff @(posedge clk_i) begin
      g_neg <= gamma_raw < 0;
      g_big <= gamma_raw > Pi;
    end
  end else begin : gen_gclamp_wire
    assign g_neg = gamma_raw < 0;
    assign g_big = gamma_raw > Pi;
  end
  always_ff @(posedge clk_i) begin
    if (adv) begin
      gamma_q  <= opph_cor ? Pi : flat_cor ? '0 : g_neg ? '0 : g_big ? Pi : gamma_raw;
      // rshift_round(-lambda, 1) = (1 - lambda) >> 1 = (~lambda + 2) >> 1.
      psi0_q   <= AngleBits'((~lambda + CW'(2)) >>> (CFrac - AngleFrac));
      lshift_q <= lshift_d;
    end
  end
  // 1/l read a stage early and registered again in the fabric, so the block RAM's
  // clock-to-output (5.61 ns) ends in a flip-flop beside it, not in a shared unit's
  // operand multiplexer (docs/setup_hw.md#the-folded-setup).
  logic [RecipLenFrac:0] recip_rd, recip;
  specular_rom #(.Width(RecipLenFrac + 1), .AddrBits(LenBits), .File(RecipLenFile)) u_recip_len_rom (
    .clk_i (clk_i), .en_i (adv), .addr_i (len_pre), .data_o (recip_rd));
  always_ff @(posedge clk_i) begin
    if (adv) recip <= recip_rd;
  end
  logic signed [GW+RLW-1:0] gr;
  logic signed [GW-1:0]     gamma2;  // rshift_round(gamma, CFrac - GammaFrac): gamma 2^1
  assign gamma2 = GW'(gamma_q) <<< (GammaFrac - CFrac);
  if (SetupII > 1) begin : gen_gr_fold
    assign f44_a[(39)*F44A +: F44A] = F44A'($signed(gamma2));
    assign f44_b[(39)*F44B +: F44B] = F44B'($signed($signed({1'b0, recip})));
    assign gr = (GW + RLW)'(f44_p[(39)*(F44A + F44B) +: F44A + F44B]);
  end else begin : gen_gr_pipe
    specular_setup_smul #(.ABits(GW), .BBits(RLW), .TileBits(TileBits)) u_gr (
      .clk_i (clk_i), .en_i (adv), .a_i (gamma2), .b_i ($signed({1'b0, recip})), .p_o (gr));
  end
  specular_delay #(.Width(4), .Depth(LDP), .Reset(1'b0), .Ram(RamLines)) u_dly_lshift (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (lshift_q), .q_o (lshift_dp));
  logic len_zero_dp, len_zero_q;
  specular_delay #(.Width(1), .Depth(LDP + 1), .Reset(1'b0), .Ram(RamLines)) u_dly_lenz (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (len_cor == '0), .q_o (len_zero_dp));
  // dpsi = rshift_round(2 gamma recip, GammaFrac + RecipLenFrac + s - AngleFrac): a shift by
  // that minus one, then the rounding.
  localparam int DpShift = GammaFrac + RecipLenFrac - AngleFrac - 1;
  logic signed [AngleBits+3:0] dy_q;
  logic [AngleBits-1:0]        dpsi_q;
  always_ff @(posedge clk_i) begin
    if (adv) begin
      dy_q       <= (AngleBits + 4)'(gr >>> (DpShift + 32'(lshift_dp)));
      len_zero_q <= len_zero_dp;
      dpsi_q     <= len_zero_q ? '0 : AngleBits'((dy_q + (AngleBits + 4)'(1)) >>> 1);
    end
  end
  logic [AngleBits-1:0] dpsi_out;
  specular_delay #(.Width(AngleBits), .Depth(TOUT - TDP), .Reset(1'b0), .Ram(RamLines)) u_dly_dpsi (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (dpsi_q), .q_o (dpsi_out));
  specular_delay #(.Width(AngleBits), .Depth(TOUT - TCOR - 1), .Reset(1'b0), .Ram(RamLines)) u_dly_psi0 (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (psi0_q), .q_o (psi0_out));

  // ---- TOUT: the descriptor and the status; then the output buffer ----
  logic               valid_out, invalid_out, undefined_out, oppn_out, opph_out;
  logic [LenBits-1:0] len_out;
  logic [NBits-1:0]   n_out;
  logic [TagBits-1:0] tag_out;
  specular_delay #(.Width(1), .Depth(TOUT), .Reset(1'b1)) u_dly_valid (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (in_valid_q), .q_o (valid_out));
  specular_delay #(.Width(LenBits + NBits + TagBits + 2), .Depth(TOUT), .Reset(1'b0), .Ram(RamLines)) u_dly_side (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv),
    .d_i ({len_q, n_q, tag_q, invalid, undefined}), .q_o ({len_out, n_out, tag_out, invalid_out, undefined_out}));
  specular_delay #(.Width(1), .Depth(TOUT - TON), .Reset(1'b0), .Ram(RamLines)) u_dly_oppn_out (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (opposite_normals_q), .q_o (oppn_out));
  specular_delay #(.Width(1), .Depth(TOUT - TCOR), .Reset(1'b0), .Ram(RamLines)) u_dly_opph_out (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (opph_cor), .q_o (opph_out));
  logic               zero_out;
  logic [2:0]         status_out;
  logic [OutBits-1:0] out_d, out_q;
  always_comb begin
    zero_out   = invalid_out || undefined_out;
    status_out = invalid_out ? 3'd1 : undefined_out ? 3'd2 : opph_out ? 3'd4 : oppn_out ? 3'd3 : 3'd0;
    out_d = {zero_out || !a_pos_out ? CBits'(0) : c_out,
             zero_out ? AngleBits'(0) : psi0_out,
             zero_out ? AngleBits'(0) : dpsi_out,
             n_out, len_out, tag_out, status_out};
  end
  specular_out_buf #(.Width(OutBits)) u_out_buf (
    .clk_i      (clk_i),
    .rst_ni     (rst_ni),
    .adv_o      (buf_adv),
    .adv_d_o    (buf_adv_d),
    .in_valid_i (valid_out & slot_last),
    .in_data_i  (out_d),
    .px_valid_o (span_valid_o),
    .px_ready_i (span_ready_i),
    .px_data_o  (out_q)
  );
  assign {span_c_o, span_psi0_o, span_dpsi_o, span_n_o, span_len_o, span_tag_o, span_status_o} = out_q;

  logic unused;
  assign unused = ^{sat_unused, cc_q[CCW-1:60-KH], cos2[2*VW-1:A2W], nu2[2*VW-1:A2W], gamma_q[CW-1]};

`ifndef SYNTHESIS
  // The windows of the bounded block normalizations hold on every span that entered (a bubble's
  // values are whatever the registers held).
  logic valid_gw, valid_xw;
  specular_delay #(.Width(1), .Depth(TGV + 1), .Reset(1'b1)) u_dly_valid_gw (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (in_valid_q), .q_o (valid_gw));
  specular_delay #(.Width(1), .Depth(TX2 + 1), .Reset(1'b1)) u_dly_valid_xw (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (in_valid_q), .q_o (valid_xw));
  `SPEC_ASSERT(GInWindow_A, !valid_gw || u_blk_g.in_window, clk_i, rst_ni)
  `SPEC_ASSERT(XcInWindow_A, !valid_xw || u_blk_xc.in_window, clk_i, rst_ni)
`endif

  `SPEC_ASSERT_KNOWN(GeoValidKnown_A, geo_valid_i, clk_i, rst_ni)
  // The geometry word as one signal: a macro call inside an assertion's stringified argument
  // is more than Icarus 11 reads.
  logic [`SPECULAR_GEO_DATA_BITS-1:0] geo_data;
  assign geo_data = `SPECULAR_GEO_DATA(geo_, _i);
  `SPEC_ASSERT_KNOWN_IF(GeoDataKnown_A, geo_data, geo_valid_i && geo_ready_o, clk_i, rst_ni)

endmodule
