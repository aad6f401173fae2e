// SPDX-License-Identifier: Apache-2.0
//
// Self-checking Icarus Verilog testbench of specular_stream (default parameters, TagBits =
// 16). Spans and the expected pixels come from the bit-exact C++ model
// (tests/iverilog/gen_stream_vectors.cpp writes them; file formats in its header). Every
// pixel transferred is compared with the next expected one: intensity, tag and last flag.
//
//   vvp -n tb.vvp +spans=FILE +pixels=FILE [+seed=N] [+corrupt=K] [+max_cycles=N]
//
// Run from the repository root (the ROM files are read relative to it). The span side
// offers spans with random gaps and holds each, data stable, until it is taken (AXI4-Stream
// rules); its data are X whenever span_valid_i is low, so a core that used them would
// put X into a pixel. px_ready_i is random, in segments of different character: always
// high, 1 in 2, 1 in 8, long stalls, and span gaps with ready high (see `mode`).
// +corrupt=K alters expected pixel K (its intensity's bit 0) before the run: the run must
// then fail (ctest rtl_iverilog_stream_corrupt).
// Exit: $finish (status 0) when every expected pixel came, in order and equal, and nothing
// else did; $fatal (status 1) after a mismatch (up to 10 reported, within the next 200
// pixels), on an unexpected pixel, or when max_cycles pass first. The RTL's own assertions
// (rtl/prim/specular_assert.svh) end the run with $fatal too.

`timescale 1ns / 1ps

module tb_specular_stream;

  localparam int MaxSpans  = 1 << 15;
  localparam int MaxPixels = 1 << 20;
  localparam int TagBits   = 16;
  localparam int MaxReport = 10;

  logic clk_i = 1'b0;
  logic rst_ni = 1'b0;
  always #5 clk_i = ~clk_i;

  logic        span_valid_i, span_ready_o;
  logic [15:0] span_c_i;
  logic [31:0] span_psi0_i, span_dpsi_i;
  logic [9:0]  span_n_i;
  logic [10:0] span_len_i;
  logic [TagBits-1:0] span_tag_i;
  logic        px_valid_o, px_ready_i, px_last_o;
  logic [15:0] px_intensity_o;
  logic [TagBits-1:0] px_tag_o;

  specular_stream #(
    .TagBits (TagBits)
  ) u_dut (
    .clk_i          (clk_i),
    .rst_ni         (rst_ni),
    .span_valid_i   (span_valid_i),
    .span_ready_o   (span_ready_o),
    .span_c_i       (span_c_i),
    .span_psi0_i    (span_psi0_i),
    .span_dpsi_i    (span_dpsi_i),
    .span_n_i       (span_n_i),
    .span_len_i     (span_len_i),
    .span_tag_i     (span_tag_i),
    .px_valid_o     (px_valid_o),
    .px_ready_i     (px_ready_i),
    .px_intensity_o (px_intensity_o),
    .px_last_o      (px_last_o),
    .px_tag_o       (px_tag_o)
  );

  // ---- Vectors
  logic [127:0] spans  [MaxSpans];
  logic [35:0]  pixels [MaxPixels];
  int n_spans, n_pixels;
  string spans_file, pixels_file;
  int seed, corrupt, max_cycles;

  // Reads one hex word per line into spans (which = 0) or pixels (1); returns the count.
  function automatic int read_hex(string file, int which, int max);
    int fd, n;
    logic [127:0] w;
    fd = $fopen(file, "r");
    if (fd == 0) $fatal(1, "tb_specular_stream: cannot open %s", file);
    n = 0;
    while (n < max && $fscanf(fd, "%h\n", w) == 1) begin
      if (which == 0) spans[n] = w;
      else pixels[n] = w[35:0];
      n++;
    end
    $fclose(fd);
    return n;
  endfunction

  initial begin
    if (!$value$plusargs("spans=%s", spans_file) || !$value$plusargs("pixels=%s", pixels_file)) begin
      $fatal(1, "tb_specular_stream: +spans=FILE and +pixels=FILE are required");
    end
    if (!$value$plusargs("seed=%d", seed)) seed = 1;
    if (!$value$plusargs("corrupt=%d", corrupt)) corrupt = -1;
    if (!$value$plusargs("max_cycles=%d", max_cycles)) max_cycles = 2_000_000;
    n_spans  = read_hex(spans_file, 0, MaxSpans);
    n_pixels = read_hex(pixels_file, 1, MaxPixels);
    if (n_spans == 0 || n_pixels == 0) begin
      $fatal(1, "tb_specular_stream: no vectors in %s / %s", spans_file, pixels_file);
    end
    if (corrupt >= 0 && corrupt < n_pixels) begin
      pixels[corrupt][0] = ~pixels[corrupt][0];
      $display("tb_specular_stream: expected pixel %0d altered on purpose (+corrupt)", corrupt);
    end
    $display("tb_specular_stream: %0d spans, %0d pixels, seed %0d", n_spans, n_pixels, seed);
  end

  // ---- Stimulus, driven at the falling edge
  // mode (changes every 200 .. 1200 cycles): 0 ready high, spans back to back; 1 ready 1 in
  // 2; 2 ready 1 in 8; 3 long stalls (ready low for up to 60 cycles); 4 ready high, spans
  // offered 1 in 3.
  int   mode, mode_left, stall_left, next_span, cycle;
  logic taken;   // the span on the bus was accepted at the last rising edge

  function automatic int rnd(int n);  // 0 .. n - 1
    return int'({$random(seed)} % n);
  endfunction

  task automatic drive_span_bus(logic valid, logic [127:0] w);
    span_valid_i = valid;
    if (valid) begin
      span_tag_i  = w[127:112];
      span_len_i  = w[106:96];
      span_n_i    = w[89:80];
      span_dpsi_i = w[79:48];
      span_psi0_i = w[47:16];
      span_c_i    = w[15:0];
    end else begin
      {span_tag_i, span_len_i, span_n_i, span_dpsi_i, span_psi0_i, span_c_i} = 'x;
    end
  endtask

  initial begin
    mode = 0;
    mode_left = 300;
    stall_left = 0;
    next_span = 0;
    cycle = 0;
    px_ready_i = 1'b0;
    drive_span_bus(1'b0, '0);
    repeat (4) @(negedge clk_i);
    rst_ni = 1'b1;
    forever begin
      @(negedge clk_i);
      cycle++;
      if (mode_left == 0) begin
        mode = rnd(5);
        mode_left = 200 + rnd(1000);
      end else begin
        mode_left--;
      end
      // Span side: a span stays on the bus until taken; a new one after a random gap.
      if (taken || !span_valid_i) begin
        if (taken) next_span++;
        if (next_span < n_spans && (mode == 0 || rnd(mode == 4 ? 3 : 2) == 0)) begin
          drive_span_bus(1'b1, spans[next_span]);
        end else begin
          drive_span_bus(1'b0, '0);
        end
      end
      // Pixel side.
      unique case (mode)
        0, 4: px_ready_i = 1'b1;
        1: px_ready_i = rnd(2) == 0;
        2: px_ready_i = rnd(8) == 0;
        default: begin
          if (stall_left > 0) begin
            stall_left--;
            px_ready_i = 1'b0;
          end else begin
            px_ready_i = 1'b1;
            if (rnd(20) == 0) stall_left = 1 + rnd(60);
          end
        end
      endcase
    end
  end

  // ---- Checks, at the rising edge (values before the edge)
  int got, errors, first_error, quiet_cycles, stall_cycles;

  initial begin
    got = 0;
    errors = 0;
    quiet_cycles = 0;
    stall_cycles = 0;
    taken = 1'b0;
  end

  always @(posedge clk_i) begin
    if (rst_ni) begin
      taken <= span_valid_i && span_ready_o;
      if (px_valid_o && !px_ready_i) stall_cycles++;
      if (px_valid_o && got >= n_pixels) begin
        $fatal(1, "tb_specular_stream: FAIL: a pixel after the last expected one (tag %h, intensity %h)",
               px_tag_o, px_intensity_o);
      end
      if (px_valid_o && px_ready_i) begin
        if ({3'b000, px_last_o, px_tag_o, px_intensity_o} !== pixels[got]) begin
          if (errors == 0) first_error = got;
          errors++;
          if (errors <= MaxReport) begin
            $display("tb_specular_stream: mismatch at pixel %0d (cycle %0d): got last %b tag %h intensity %h, expected last %b tag %h intensity %h",
                     got, cycle, px_last_o, px_tag_o, px_intensity_o, pixels[got][32],
                     pixels[got][31:16], pixels[got][15:0]);
          end
        end
        got++;
      end
      if (got == n_pixels && next_span >= n_spans) quiet_cycles++;
      // After a mismatch: up to MaxReport of them, or 200 more pixels, then stop.
      if (errors > 0 && (errors >= MaxReport || got == n_pixels || got >= first_error + 200)) begin
        $fatal(1, "tb_specular_stream: FAIL: %0d mismatching pixels among the first %0d", errors, got);
      end
      // After the last pixel: 100 more cycles with nothing out (ready as the mode has it).
      if (quiet_cycles == 100) begin
        $display("tb_specular_stream: PASS: %0d spans, %0d pixels equal (intensity, tag, last) in %0d cycles, %0d stall cycles",
                 n_spans, got, cycle, stall_cycles);
        $finish(0);
      end
      if (cycle >= max_cycles) begin
        $fatal(1, "tb_specular_stream: FAIL: timeout after %0d cycles, %0d of %0d pixels, %0d of %0d spans taken",
               cycle, got, n_pixels, next_span, n_spans);
      end
    end
  end

endmodule
