// Copyright (c) the specular_device authors.
//
// Multiplier 13 of patent UA 71489 and the output register (output 27):
//   I = (C * cosk + 2^(CosDataBits-1)) >> CosDataBits
// C from register 1 (unsigned, CBits bits), cosk from ROM 12 (all CosDataBits bits are
// fraction, cosk < 1), so I has the format of C and cannot overflow. zero_i forces 0: a
// pixel flagged zero (far angle, zeta >= pi/2, invalid n), or no pixel at all (the
// output reads 0 whenever no pixel is valid). en_i holds the register while the pixel
// stream is stalled.

module specular_intensity_mul #(
  parameter int CBits       = 16,
  parameter int CosDataBits = 16
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  input  logic                   en_i,      // pipeline advance (clock enable)
  input  logic [CBits-1:0]       c_i,       // register 1 (this pixel's span)
  input  logic [CosDataBits-1:0] cosk_i,    // ROM 12
  input  logic                   zero_i,
  output logic [CBits-1:0]       intensity_o
);

  if (CosDataBits < 1 || CBits < 1) begin : gen_width_check
    $error("specular_intensity_mul: widths must be >= 1");
  end

  localparam int ProdBits = CBits + CosDataBits;

  logic [ProdBits-1:0] prod, prod_rnd;
  assign prod     = ProdBits'(c_i) * ProdBits'(cosk_i);
  assign prod_rnd = prod + (ProdBits'(1) << (CosDataBits - 1));   // round half up

  logic [CBits-1:0] intensity_d, intensity_q;
  assign intensity_d = zero_i ? '0 : prod_rnd[ProdBits-1:CosDataBits];

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      intensity_q <= '0;
    end else if (en_i) begin
      intensity_q <= intensity_d;
    end
  end

  assign intensity_o = intensity_q;

  // The discarded low product bits are the rounding remainder.
  logic unused_prod_lsbs;
  assign unused_prod_lsbs = ^prod_rnd[CosDataBits-1:0];

endmodule
