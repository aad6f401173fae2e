// Copyright (c) the specular_device authors.
//
// Control unit, block 14 of patent UA 71489. The patent builds it from four D flip-flops,
// a pulse generator and AND / inverter / NAND gates, and clocks the flip-flops with the
// generator phases. Here everything is synchronous to clk_i, the generator fires on every
// clock (one pixel per clock) and the four flip-flops survive as named state bits:
//   start_q   start latch: set by an accepted start pulse (26), cleared when the last
//             pixel has left the pipeline; it is the busy / "End" output (28)
//   run_q     run: gates the pulse generator; set by the start, cleared by the
//             counter's borrow (35); every clock with run_q high is one strobe, i.e.
//             one write of register 8 (37)
//   mux_sel_q mux select (36): 0 for the first strobe (register 8 loads psi0), then 1
//   cnt_en_q  count enable: gates the count pulses (34) of counter 5. With one pixel per
//             clock it rises and falls with run_q; it is kept as its own bit so that the
//             patent's four flip-flops can be found in the RTL (synthesis merges it).
// The data-valid strobe (29) is the register-8 strobe delayed by the datapath latency
// PipeDepth (register 8 -> multiplier 11 (2 stages) -> ROM 12 -> multiplier 13 / output
// register).
//
// Timing with start_i high in cycle s while idle (l = value of counter 5):
//   s+1 .. s+1+l           strobes (l + 1 of them); the last one carries the borrow
//   s+1+PipeDepth ..       valid_o, l + 1 consecutive cycles
//   s+1 .. s+1+PipeDepth+l busy_o; a new start is accepted from s+2+PipeDepth+l on.
// Starts while busy are ignored; idle_o qualifies register writes the same way.

module specular_control #(
  parameter int PipeDepth = 5
) (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic start_i,        // start pulse 26
  input  logic borrow_i,       // borrow 35 of counter 5
  output logic idle_o,         // register writes allowed
  output logic strobe_o,       // write 37 of register 8
  output logic sel_o,          // mux select 36
  output logic count_o,        // count pulse 34
  output logic valid_o,        // data valid strobe 29
  output logic valid_next_o,   // a pixel enters the output register at the next edge
  output logic busy_o          // "End" 28
);

  if (PipeDepth < 1) begin : gen_depth_check
    $error("specular_control: PipeDepth must be >= 1");
  end

  logic start_d, start_q;
  logic run_d, run_q;
  logic mux_sel_d, mux_sel_q;
  logic cnt_en_d, cnt_en_q;
  logic accept, last_out;

  // Delay line from strobe to data valid; a parallel one marks the last pixel.
  logic [PipeDepth-1:0] vld_d, vld_q, last_d, last_q;

  assign accept   = start_i & ~start_q;
  assign strobe_o = run_q;
  assign count_o  = run_q & cnt_en_q;
  assign sel_o    = mux_sel_q;
  assign last_out = vld_q[PipeDepth-1] & last_q[PipeDepth-1];

  always_comb begin
    start_d   = start_q;
    run_d     = run_q;
    mux_sel_d = mux_sel_q;
    cnt_en_d  = cnt_en_q;
    if (accept) begin
      start_d   = 1'b1;
      run_d     = 1'b1;
      mux_sel_d = 1'b0;
      cnt_en_d  = 1'b1;
    end else begin
      if (run_q) begin
        mux_sel_d = 1'b1;          // after the first strobe: psi + dpsi
      end
      if (borrow_i) begin          // counter passed 0: the strobe just given was the last
        run_d     = 1'b0;
        cnt_en_d  = 1'b0;
        mux_sel_d = 1'b0;
      end
      if (last_out) begin          // last pixel is on the output in this cycle
        start_d = 1'b0;
      end
    end
  end

  if (PipeDepth > 1) begin : gen_shift
    assign vld_d  = {vld_q[PipeDepth-2:0], strobe_o};
    assign last_d = {last_q[PipeDepth-2:0], borrow_i};
  end else begin : gen_single
    assign vld_d  = strobe_o;
    assign last_d = borrow_i;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      start_q   <= 1'b0;
      run_q     <= 1'b0;
      mux_sel_q <= 1'b0;
      cnt_en_q  <= 1'b0;
      vld_q     <= '0;
      last_q    <= '0;
    end else begin
      start_q   <= start_d;
      run_q     <= run_d;
      mux_sel_q <= mux_sel_d;
      cnt_en_q  <= cnt_en_d;
      vld_q     <= vld_d;
      last_q    <= last_d;
    end
  end

  assign idle_o  = ~start_q;
  assign valid_o = vld_q[PipeDepth-1];
  if (PipeDepth > 1) begin : gen_valid_next
    assign valid_next_o = vld_q[PipeDepth-2];
  end else begin : gen_valid_next_strobe
    assign valid_next_o = strobe_o;
  end
  assign busy_o  = start_q;

endmodule
