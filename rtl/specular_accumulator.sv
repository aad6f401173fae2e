// Copyright (c) the specular_device authors.
//
// Angle accumulator of patent UA 71489: adder 6, 2:1 multiplexer 7 and register 8.
// On the first strobe (mux select 36 low) register 8 loads psi0 from register 3; on
// every further strobe it loads psi + dpsi (register 2). Write strobe of reg 8 is 37.
//
// Erratum (SPEC 5): the patent loads register 3 with -sqrt(n/k)*lambda, but multiplier 11
// scales the accumulator output afterwards, so registers 3 and 2 hold the unscaled angles
// psi0 = -lambda and dpsi = gamma / l, in radians.
//
// Width: AccBits = AngleBits + 12 so that 2047 additions of the most negative dpsi to
// the most negative psi0 cannot overflow (2^31 * 2049 < 2^43).

module specular_accumulator #(
  parameter int AngleBits = 32,   // registers 2 and 3, signed, radians
  parameter int AccBits   = 44    // register 8, signed, same fraction bits
) (
  input  logic                        clk_i,
  input  logic                        rst_ni,
  input  logic                        we_i,      // write 37 of register 8 (strobe)
  input  logic                        sel_i,     // mux 7 select 36: 0 = psi0, 1 = psi + dpsi
  input  logic signed [AngleBits-1:0] psi0_i,    // register 3
  input  logic signed [AngleBits-1:0] dpsi_i,    // register 2
  output logic signed [AccBits-1:0]   psi_o      // register 8
);

  if (AccBits < AngleBits + 1) begin : gen_width_check
    $error("specular_accumulator: AccBits must exceed AngleBits");
  end

  logic signed [AccBits-1:0] psi0_ext, dpsi_ext, sum, psi_d, psi_q;

  // Sign extension to the accumulator width.
  assign psi0_ext = {{(AccBits-AngleBits){psi0_i[AngleBits-1]}}, psi0_i};
  assign dpsi_ext = {{(AccBits-AngleBits){dpsi_i[AngleBits-1]}}, dpsi_i};

  assign sum   = psi_q + dpsi_ext;          // adder 6
  assign psi_d = sel_i ? sum : psi0_ext;    // multiplexer 7

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      psi_q <= '0;
    end else if (we_i) begin
      psi_q <= psi_d;                       // register 8
    end
  end

  assign psi_o = psi_q;

endmodule
