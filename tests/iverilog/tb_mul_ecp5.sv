// SPDX-License-Identifier: Apache-2.0
//
// The ECP5 form of the DSP tiles (rtl/prim/specular_mul_tile.sv with
// SPECULAR_ECP5_MULT18X18D defined: a MULT18X18D instance with its own registers) under
// Icarus, on the model of tests/iverilog/ecp5_mult18x18d_model.v: every product of random
// operands, with random clock-enable stalls, against the exact product at the block's
// latency. The configurations are the multipliers' shapes in the design: signed tiles (the
// setup's products, one to six tiles), unsigned tiles (the stream core's), a tile with a
// one-bit operand (left to the fabric), and the tile alone below 18 bits.
// Prints "tb_mul_ecp5: PASS" after Products enabled products per configuration, or a FAIL
// line naming the configuration and the first products that differ.
`timescale 1ns / 1ps

module mul_ecp5_check #(
  parameter        Name   = "",
  parameter int    ABits  = 18,
  parameter int    BBits  = 18,
  parameter bit    Signed = 1'b1,
  parameter bit    Tile   = 1'b0,   // the tile alone (latency 2) instead of specular_pipe_mul
  parameter int    Seed   = 1
) (
  input  logic clk,
  input  logic run,
  output int   compared,
  output int   errors
);
  localparam int PBits = ABits + BBits;
  localparam int L     = Tile ? 2 : specular_pkg::pipe_mul_stages(BBits);

  logic [ABits-1:0] a;
  logic [BBits-1:0] b;
  logic             en;
  logic [PBits-1:0] p;
  logic [PBits-1:0] exact;
  logic [PBits-1:0] exp_q [L];
  int               n_en;
  int               seed;

  if (Tile) begin : gen_tile
    specular_mul_tile #(.Bits (ABits), .Signed (Signed)) dut (
      .clk_i (clk), .en_i (en), .a_i (a), .b_i (b), .p_o (p));
  end else begin : gen_pipe
    logic [ABits+1:0] a3;
    assign a3 = '0;  // the DSP style reads no 3a
    specular_pipe_mul #(.ABits (ABits), .BBits (BBits), .TileBits (18), .Signed (Signed)) dut (
      .clk_i (clk), .en_i (en), .a_i (a), .a3_i (a3), .b_i (b), .p_o (p));
  end

  assign exact = Signed ? PBits'($signed(a) * $signed(b)) : PBits'(a) * PBits'(b);

  // Random operands: mostly uniform, one in eight an extreme (all ones, the sign alone, 0).
  function automatic logic [127:0] operand(input int width);
    logic [127:0] v;
    int           kind;
    v    = {$unsigned($random(seed)), $unsigned($random(seed)), $unsigned($random(seed)), $unsigned($random(seed))};
    kind = $unsigned($random(seed)) % 32;
    if (kind == 0) v = '1;
    if (kind == 1) v = 128'd1 << (width - 1);
    if (kind == 2) v = '0;
    if (kind == 3) v = (128'd1 << (width - 1)) - 1;
    operand = v & ((128'd1 << width) - 1);
  endfunction

  initial begin
    seed     = Seed;
    compared = 0;
    errors   = 0;
    n_en     = 0;
    en       = 1'b0;
    a        = '0;
    b        = '0;
  end

  // New operands and enable after every edge; the expected line advances with the enable.
  always @(posedge clk) begin
    if (en) begin
      for (int i = L - 1; i > 0; i--) exp_q[i] <= exp_q[i-1];
      exp_q[0] <= exact;
      n_en <= n_en + 1;
    end
    a  <= ABits'(operand(ABits));
    b  <= BBits'(operand(BBits));
    en <= run && ($unsigned($random(seed)) % 4 != 0);
  end

  always @(negedge clk) begin
    if (n_en >= L) begin
      compared <= compared + 1;
      if (p !== exp_q[L-1]) begin
        errors <= errors + 1;
        if (errors < 5)
          $display("FAIL %s: after %0d enabled clocks p = %h, expected %h", Name, n_en, p, exp_q[L-1]);
      end
    end
  end
endmodule

module tb_mul_ecp5;
  localparam int Products = 4000;
  localparam int NCfg     = 7;

  logic clk = 1'b0;
  logic run = 1'b1;
  always #5 clk = ~clk;

  int compared [NCfg];
  int errors   [NCfg];

  mul_ecp5_check #(.Name ("signed 18x18 (one tile)"), .ABits (18), .BBits (18), .Signed (1'b1), .Seed (11))
    u_c0 (.clk (clk), .run (run), .compared (compared[0]), .errors (errors[0]));
  mul_ecp5_check #(.Name ("signed 28x28 (2x2 tiles)"), .ABits (28), .BBits (28), .Signed (1'b1), .Seed (12))
    u_c1 (.clk (clk), .run (run), .compared (compared[1]), .errors (errors[1]));
  mul_ecp5_check #(.Name ("signed 35x52 (2x3 tiles)"), .ABits (35), .BBits (52), .Signed (1'b1), .Seed (13))
    u_c2 (.clk (clk), .run (run), .compared (compared[2]), .errors (errors[2]));
  mul_ecp5_check #(.Name ("unsigned 21x21 (2x2 tiles)"), .ABits (21), .BBits (21), .Signed (1'b0), .Seed (14))
    u_c3 (.clk (clk), .run (run), .compared (compared[3]), .errors (errors[3]));
  mul_ecp5_check #(.Name ("unsigned 18x19 (a one-bit tile in the fabric)"), .ABits (18), .BBits (19),
                   .Signed (1'b0), .Seed (15))
    u_c4 (.clk (clk), .run (run), .compared (compared[4]), .errors (errors[4]));
  mul_ecp5_check #(.Name ("tile alone, signed 10 bits"), .ABits (10), .BBits (10), .Signed (1'b1), .Tile (1'b1),
                   .Seed (16))
    u_c5 (.clk (clk), .run (run), .compared (compared[5]), .errors (errors[5]));
  mul_ecp5_check #(.Name ("tile alone, unsigned 17 bits"), .ABits (17), .BBits (17), .Signed (1'b0), .Tile (1'b1),
                   .Seed (17))
    u_c6 (.clk (clk), .run (run), .compared (compared[6]), .errors (errors[6]));

  initial begin
    int total_errors;
    int done;
    done = 0;
    while (!done) begin
      @(posedge clk);
      done = 1;
      for (int i = 0; i < NCfg; i++) if (compared[i] < Products) done = 0;
    end
    total_errors = 0;
    for (int i = 0; i < NCfg; i++) total_errors += errors[i];
    if (total_errors != 0) begin
      $display("tb_mul_ecp5: FAIL (%0d products differ)", total_errors);
      $fatal(1);
    end
    $display("tb_mul_ecp5: PASS (%0d products in each of %0d configurations)", Products, NCfg);
    $finish;
  end
endmodule
