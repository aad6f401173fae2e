// Copyright (c) the specular_device authors.
//
// specular_unit: specular (Blinn) intensity of every pixel of a scanline, after patent
// UA 71489 ("device for determining the intensity of the specular colour component").
// Pixel i = 0..l of a line gets
//   I_i = C * cos^k(a(n) * psi_i),  psi_i = psi0 + i * dpsi,   0 where a*|psi_i| >= pi/2,
// with k and a(n) chosen per exponent n so that cos^k(a x) approximates cos^n(x).
// Bit-exact datapath contract: model/device_model.hpp (the golden model follows it too).
//
// Interface (SPEC section 6; default widths):
//   clk_i                 clock; everything is synchronous to its rising edge
//   rst_ni                asynchronous reset, active low (patent input 25): all registers
//                         0, idle
//   c_we_i,    c_i[16]    write reg 1: C, unsigned, 15 fraction bits (0 <= C < 2)
//   dpsi_we_i, dpsi_i[32] write reg 2: dpsi, radians, signed, 28 fraction bits
//   psi0_we_i, psi0_i[32] write reg 3: psi0, same format
//   n_we_i,    n_i[10]    write reg 4: n, unsigned 1..1000 (0 or > 1000: all pixels 0)
//   len_we_i,  len_i[11]  write counter 5: l; the line has l + 1 pixels
//   start_i               one-cycle pulse: start the line
//   intensity_o[16]       pixel intensity, format of C (output 27); 0 while valid_o is low
//   valid_o               intensity_o holds the next pixel (data valid strobe 29)
//   busy_o                line in progress ("End", 28)
// Register values persist until rewritten (l included, see specular_down_counter).
//
// Protocol, start_i high in cycle s while idle (writes in cycle s apply to this line):
//   busy_o   high in cycles s+1 .. s+6+l, low in s+7+l, when a new start is accepted
//   valid_o  high in cycles s+6 .. s+6+l, pixel i in cycle s+6+i
// i.e. latency 6 clocks to the first pixel, one pixel per clock, a line occupies l + 7
// clocks from start to the next accepted start. Writes and starts while busy are ignored.
//
// Pipeline (patent block numbers): control 14 strobes register 8 (accumulator 6/7/8)
// once per clock -> multiplier 11 (|psi|; then zeta and the ROM address: 2 stages) -> ROM 12
// (synchronous read) -> multiplier 13 (output register). ROM 9 is read from register 4
// and settles while idle; decoder 10 is combinational on register 4.
//
// Patent errata resolved here (SPEC 5): n has 10 bits (the patent's decoder has 9 inputs);
// register 3 holds the unscaled -lambda and register 2 gamma/l (multiplier 11 applies
// a(n)); ROM 12 covers only [0, pi/2), so the magnitude |zeta| addresses it and
// zeta >= pi/2 outputs 0.
//
// ROM contents are read with $readmemh when the design is elaborated; the file paths are
// parameters relative to the working directory (the repository root for simulation and
// for the Yosys checks). Formats (roms/README.md): one hex word per line, no comments,
// no @ addresses.
//   CoefRomFile  2^NBits words of CoefBits bits: word n = round(a(n, k(n)) * 2/pi *
//                2^CoefFrac), 0 for n = 0 and n > 1000
//   CosRomFile   NumBanks * 2^CosAddrBits words of CosDataBits bits: word
//                bank * 2^CosAddrBits + i = min(round(cos^k_bank(i * pi/2 / 2^CosAddrBits)
//                * 2^CosDataBits), 2^CosDataBits - 1)
// The numeric parameter defaults equal struct specular::device::Format; the k of each ROM 12
// bank (default 1, 2, 4, 16) lives only in CosRomFile, the hardware does not need it.
// The numeric parameters are /*verilator public*/: a Verilator testbench reads them as
// static constants V<prefix>_specular_unit::CBits, ... (header V<prefix>_specular_unit.h),
// e.g. to refuse to run when they differ from Format.

module specular_unit #(
  parameter int CBits       /*verilator public*/ = 16,  // Format::c_bits
  parameter int CFrac       /*verilator public*/ = 15,  // Format::c_frac (documentary)
  parameter int AngleBits   /*verilator public*/ = 32,  // Format::angle_bits
  parameter int AngleFrac   /*verilator public*/ = 28,  // Format::angle_frac
  parameter int AccBits     /*verilator public*/ = 44,  // Format::acc_bits
  parameter int NBits       /*verilator public*/ = 10,  // Format::n_bits
  parameter int LenBits     /*verilator public*/ = 11,  // Format::len_bits
  parameter int CoefBits    /*verilator public*/ = 18,  // Format::coef_bits
  parameter int CoefFrac    /*verilator public*/ = 15,  // Format::coef_frac
  parameter int PsiMulFrac  /*verilator public*/ = 20,  // Format::psi_mul_frac
  parameter int CosAddrBits /*verilator public*/ = 12,  // Format::cos_addr_bits
  parameter int CosDataBits /*verilator public*/ = 16,  // Format::cos_data_bits
  parameter int NumBanks    /*verilator public*/ = 4,   // Format::banks.size()
  // Format::bank_max_n, NBits bits per bank, bank 0 in the least significant bits.
  parameter logic [NumBanks*NBits-1:0] BankMaxN /*verilator public*/ =
      {10'd1000, 10'd6, 10'd2, 10'd1},
  parameter     CoefRomFile  = "roms/coef_minimax.hex",
  parameter     CosRomFile   = "roms/cos_k_1_2_4_16.hex"
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  input  logic                 c_we_i,
  input  logic [CBits-1:0]     c_i,
  input  logic                 dpsi_we_i,
  input  logic [AngleBits-1:0] dpsi_i,
  input  logic                 psi0_we_i,
  input  logic [AngleBits-1:0] psi0_i,
  input  logic                 n_we_i,
  input  logic [NBits-1:0]     n_i,
  input  logic                 len_we_i,
  input  logic [LenBits-1:0]   len_i,
  input  logic                 start_i,
  output logic [CBits-1:0]     intensity_o,
  output logic                 valid_o,
  output logic                 busy_o
);

  // Strobe of register 8 to the output register: register 8 itself, the two stages of
  // multiplier 11, the ROM 12 read, multiplier 13 / output register.
  localparam int PipeDepth = 5;

  if (CFrac > CBits) begin : gen_c_check
    $error("specular_unit: CFrac must not exceed CBits");
  end
  if (AccBits < AngleBits + LenBits + 1) begin : gen_acc_check
    $error("specular_unit: AccBits too small for 2^LenBits additions of dpsi");
  end

  // ---------------------------------------------------------------------------------
  // Control unit 14
  // ---------------------------------------------------------------------------------
  logic idle, strobe, mux_sel, count, borrow, valid_next;

  specular_control #(
    .PipeDepth (PipeDepth)
  ) u_control (
    .clk_i        (clk_i),
    .rst_ni       (rst_ni),
    .start_i      (start_i),
    .borrow_i     (borrow),
    .idle_o       (idle),
    .strobe_o     (strobe),
    .sel_o        (mux_sel),
    .count_o      (count),
    .valid_o      (valid_o),
    .valid_next_o (valid_next),
    .busy_o       (busy_o)
  );

  // ---------------------------------------------------------------------------------
  // Registers 1-4 and counter 5 (writes only while idle)
  // ---------------------------------------------------------------------------------
  logic [CBits-1:0]     c_q;
  logic [AngleBits-1:0] dpsi_q, psi0_q;
  logic [NBits-1:0]     n_q;
  logic [LenBits-1:0]   unused_count;

  specular_reg #(.Width (CBits)) u_reg1_c (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .we_i   (c_we_i & idle),
    .d_i    (c_i),
    .q_o    (c_q)
  );

  specular_reg #(.Width (AngleBits)) u_reg2_dpsi (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .we_i   (dpsi_we_i & idle),
    .d_i    (dpsi_i),
    .q_o    (dpsi_q)
  );

  specular_reg #(.Width (AngleBits)) u_reg3_psi0 (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .we_i   (psi0_we_i & idle),
    .d_i    (psi0_i),
    .q_o    (psi0_q)
  );

  specular_reg #(.Width (NBits)) u_reg4_n (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .we_i   (n_we_i & idle),
    .d_i    (n_i),
    .q_o    (n_q)
  );

  specular_down_counter #(.LenBits (LenBits)) u_counter5 (
    .clk_i    (clk_i),
    .rst_ni   (rst_ni),
    .len_we_i (len_we_i & idle),
    .len_i    (len_i),
    .count_i  (count),
    .borrow_o (borrow),
    .count_o  (unused_count)
  );

  // ---------------------------------------------------------------------------------
  // Accumulator: adder 6, mux 7, register 8
  // ---------------------------------------------------------------------------------
  logic signed [AccBits-1:0] psi;

  specular_accumulator #(
    .AngleBits (AngleBits),
    .AccBits   (AccBits)
  ) u_accumulator (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .we_i   (strobe),
    .sel_i  (mux_sel),
    .psi0_i (psi0_q),
    .dpsi_i (dpsi_q),
    .psi_o  (psi)
  );

  // ---------------------------------------------------------------------------------
  // Decoder 10 and coefficient ROM 9
  // ---------------------------------------------------------------------------------
  logic [NumBanks-1:0] bank;
  logic                n_valid;
  logic [CoefBits-1:0] coef;

  specular_decoder #(
    .NBits    (NBits),
    .NumBanks (NumBanks),
    .BankMaxN (BankMaxN)
  ) u_decoder10 (
    .n_i       (n_q),
    .bank_o    (bank),
    .n_valid_o (n_valid)
  );

  specular_coef_rom #(
    .NBits       (NBits),
    .CoefBits    (CoefBits),
    .CoefRomFile (CoefRomFile)
  ) u_coef_rom9 (
    .clk_i  (clk_i),
    .n_i    (n_q),
    .coef_o (coef)
  );

  // ---------------------------------------------------------------------------------
  // Multiplier 11, ROM 12, multiplier 13
  // ---------------------------------------------------------------------------------
  logic [CosAddrBits-1:0] cos_addr;
  logic                   zero_addr;
  logic [CosDataBits-1:0] cosk;
  logic                   zero_rom_q;

  specular_angle_mul #(
    .AccBits     (AccBits),
    .AngleFrac   (AngleFrac),
    .CoefBits    (CoefBits),
    .CoefFrac    (CoefFrac),
    .PsiMulFrac  (PsiMulFrac),
    .CosAddrBits (CosAddrBits)
  ) u_mul11 (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .psi_i     (psi),
    .coef_i    (coef),
    .n_valid_i (n_valid),
    .addr_o    (cos_addr),
    .zero_o    (zero_addr)
  );

  specular_cos_k_rom #(
    .NumBanks    (NumBanks),
    .CosAddrBits (CosAddrBits),
    .CosDataBits (CosDataBits),
    .CosRomFile  (CosRomFile)
  ) u_cos_k_rom12 (
    .clk_i  (clk_i),
    .bank_i (bank),
    .addr_i (cos_addr),
    .cosk_o (cosk)
  );

  // The zero flag travels alongside the ROM 12 read.
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      zero_rom_q <= 1'b0;
    end else begin
      zero_rom_q <= zero_addr;
    end
  end

  specular_intensity_mul #(
    .CBits       (CBits),
    .CosDataBits (CosDataBits)
  ) u_mul13 (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .c_i         (c_q),
    .cosk_i      (cosk),
    .zero_i      (zero_rom_q | ~valid_next),   // 0 on the output whenever valid_o is low
    .intensity_o (intensity_o)
  );

endmodule
