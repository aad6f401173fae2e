// Copyright (c) the specular_device authors.
//
// Multiplier 11 of patent UA 71489: zeta = a(n) * psi, turned into the ROM 12 address.
// Two pipeline stages (latency 2): |psi| and its truncation are registered before the
// multiplier, the rounded address and the zero flag after it. The split lifts the
// iCE40-HX8K Fmax from 39 to about 55 MHz (scripts/synth_pnr.sh).
// Bit-exact contract (model/device_model.hpp):
//   |psi|            cos is even, so only the magnitude of register 8 matters
//   far              |psi| >= 8 rad: the pixel is 0 (and |psi| fits 3 integer bits below)
//   psi_t            |psi| truncated to 3 integer and PsiMulFrac fraction bits
//   zeta             coef * psi_t, coef = a(n) * 2/pi from ROM 9 (CoefFrac fraction bits),
//                    so zeta is in quarter turns (zeta >= 1 means a*|psi| >= pi/2)
//   addr             round-half-up(zeta * 2^CosAddrBits)
//   zero             far, or addr >= 2^CosAddrBits (zeta at or past pi/2, where ROM 12
//                    has no entry: erratum of SPEC 5), or n invalid (decoder 10)

module specular_angle_mul #(
  parameter int AccBits     = 44,
  parameter int AngleFrac   = 28,
  parameter int CoefBits    = 18,
  parameter int CoefFrac    = 15,
  parameter int PsiMulFrac  = 20,
  parameter int CosAddrBits = 12
) (
  input  logic                          clk_i,
  input  logic                          rst_ni,
  input  logic                          en_i,      // pipeline advance (clock enable)
  input  logic signed [AccBits-1:0]     psi_i,     // register 8
  input  logic        [CoefBits-1:0]    coef_i,    // ROM 9
  input  logic                          n_valid_i, // decoder 10, for the pixel in stage 1
  output logic        [CosAddrBits-1:0] addr_o,    // ROM 12 address within the bank
  output logic                          zero_o     // this pixel is 0
);

  localparam int PsiTBits  = 3 + PsiMulFrac;            // |psi| < 8 rad
  localparam int ZetaBits  = CoefBits + PsiTBits;
  localparam int ZetaFrac  = CoefFrac + PsiMulFrac;
  localparam int DropBits  = ZetaFrac - CosAddrBits;    // bits below the ROM address
  localparam int AddrWBits = ZetaBits - DropBits + 1;   // rounded address, with carry

  if (PsiMulFrac > AngleFrac) begin : gen_frac_check
    $error("specular_angle_mul: PsiMulFrac must not exceed AngleFrac");
  end
  if (AccBits < AngleFrac + 4) begin : gen_acc_check
    $error("specular_angle_mul: AccBits must hold the sign and 3 integer bits");
  end
  if (DropBits < 1) begin : gen_drop_check
    $error("specular_angle_mul: CoefFrac + PsiMulFrac must exceed CosAddrBits");
  end
  if (AddrWBits <= CosAddrBits) begin : gen_addr_check
    $error("specular_angle_mul: zeta too narrow for the ROM address");
  end

  // |psi|: two's complement negate when negative. Register 8 never holds the most
  // negative code (see the accumulator's width), so the magnitude fits AccBits - 1 bits.
  logic [AccBits-1:0] psi_abs;
  assign psi_abs = psi_i[AccBits-1] ? AccBits'(-psi_i) : AccBits'(psi_i);

  logic far;
  assign far = |psi_abs[AccBits-1:AngleFrac+3];

  logic [PsiTBits-1:0] psi_t;
  assign psi_t = psi_abs[AngleFrac+2 -: PsiTBits];      // truncation of low fraction bits

  // Stage 1 registers: |psi|_t, the far flag, and the coefficient of this pixel's span
  // (the copy also takes the block-RAM output delay of ROM 9 off the multiplier path).
  logic [PsiTBits-1:0] psi_t_q;
  logic                far_q;
  logic [CoefBits-1:0] coef_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      psi_t_q <= '0;
      far_q   <= 1'b0;
      coef_q  <= '0;
    end else if (en_i) begin
      psi_t_q <= psi_t;
      far_q   <= far;
      coef_q  <= coef_i;
    end
  end

  // Stage 2: the multiplier proper.
  logic [ZetaBits-1:0] zeta;
  assign zeta = ZetaBits'(coef_q) * ZetaBits'(psi_t_q);

  // Round half up: add half an address step, keep the bits from the address LSB up.
  logic [ZetaBits:0] zeta_rnd;
  assign zeta_rnd = {1'b0, zeta} + ((ZetaBits + 1)'(1) << (DropBits - 1));

  logic [AddrWBits-1:0] addr_w;
  assign addr_w = zeta_rnd[ZetaBits:DropBits];

  logic past_quarter;
  assign past_quarter = |addr_w[AddrWBits-1:CosAddrBits];

  logic [CosAddrBits-1:0] addr_d, addr_q;
  logic                   zero_d, zero_q;

  assign addr_d = addr_w[CosAddrBits-1:0];
  assign zero_d = far_q | past_quarter | ~n_valid_i;   // n_valid_i is aligned with stage 1

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      addr_q <= '0;
      zero_q <= 1'b0;
    end else if (en_i) begin
      addr_q <= addr_d;
      zero_q <= zero_d;
    end
  end

  assign addr_o = addr_q;
  assign zero_o = zero_q;

  // The rounding remainder below the address LSB is discarded.
  logic unused_zeta_lsbs;
  assign unused_zeta_lsbs = ^zeta_rnd[DropBits-1:0];

  // Bits of |psi| below the multiplier's precision are deliberately dropped.
  if (AngleFrac > PsiMulFrac) begin : gen_unused
    logic unused_psi_lsbs;
    assign unused_psi_lsbs = ^psi_abs[AngleFrac-PsiMulFrac-1:0];
  end

endmodule
