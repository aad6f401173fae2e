// SPDX-License-Identifier: Apache-2.0
//
// specular_axil_fv: formal property harness of specular_axil's AXI4-Lite slave
// (rtl/axi/specular_axil.sv; the rules in docs/interfaces.md). Run by scripts/formal.sh axil
// (ctests rtl_formal_axil and rtl_formal_axil_mutant): Yosys read_verilog -formal, the
// stream core cut out (its outputs become free values every clock, so the proof holds
// whatever the core does), the unbounded proof (base case from reset and induction). Overview and figures: docs/formal.md.
//
// Reduced parameters: the stream core's and TagBits are those of specular_stream_fv.sv
// (rtl/prim/formal/specular_fv.svh; the core is cut out anyway, they only keep
// elaboration small), AddrWidth 9 (so that addresses at
// and above 0x100 exist and must answer SLVERR), FifoDepth 2. The AXI4-Lite side keeps
// its 32-bit data path.
//
// Assumptions: the design starts in reset (rst_ni low in the first cycle; resets may come
// again at any clock), and the master follows AXI4-Lite: AWVALID, WVALID and ARVALID,
// once high, stay high with AWADDR/AWPROT, WDATA/WSTRB, ARADDR/ARPROT stable until their
// handshake; a reset releases them. BREADY, RREADY and the pixel side are free.
//
// Properties (asserted whenever rst_ni is high):
//   P1 B after AW and W  bvalid only while an accepted AW and an accepted W are unanswered
//   P2 one response per request  at most one write and one read outstanding (accepted
//                        AW, W or AR not yet answered: awready / wready / arready stay low
//                        until the response has been taken), so no request gets two
//                        responses and none is answered twice
//   P3 B held            after bvalid && !bready, bvalid is still high and bresp unchanged
//   P4 R held            after rvalid && !rready, rvalid is still high, rdata and rresp
//                        unchanged
//   P5 R after AR        rvalid only while an accepted AR is unanswered
//   P6 progress          B is valid at most 2 clocks after the later of the AW and W
//                        handshakes; R is valid in the clock after the AR handshake
//   P7 responses         bresp is SLVERR exactly for an unmapped or read-only address
//                        (the AW's), rresp is SLVERR exactly for an unmapped one (the AR's);
//                        a read of ID returns 0x5350_4543
//   P8 reset             after a reset, bvalid and rvalid are low (P1, P5 with counters
//                        cleared by the reset)
// Strengthening invariants (for induction, proven like the properties) tie the harness's
// counters and recorded addresses to the slave's holding registers, read through the probe
// wires p_* of the probe table of its target in scripts/formal.sh (connect after flatten; Yosys reads
// no hierarchical references).
// With FV_PROPERTIES_ONLY defined (the mutant runs) the invariants and probes are left out.

`include "specular_params.svh"
`include "formal/specular_fv.svh"
`include "specular_axil_ports.svh"

module specular_axil_fv #(
  `SPECULAR_FV_PARAMS,
  parameter int AddrWidth    = 9,
  parameter int FifoDepth    = 2
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  `SPECULAR_AXIL_PORTS,
  `SPECULAR_AXIS_PX_PORTS,
  output logic                 irq_o
);

  specular_axil #(
    `SPECULAR_CORE_PARAM_MAP,
    .TagBits      (TagBits),
    .AddrWidth    (AddrWidth),
    .FifoDepth    (FifoDepth)
  ) u_dut (
    .clk_i            (clk_i),
    .rst_ni           (rst_ni),
    `SPECULAR_AXIL_MAP(s_axil_),
    `SPECULAR_AXIS_PX_MAP(m_axis_px_),
    .irq_o            (irq_o)
  );

`ifdef FORMAL
  localparam logic [1:0]  Okay    = 2'b00;
  localparam logic [1:0]  Slverr  = 2'b10;
  localparam logic [31:0] IdValue = specular_axil_reg_pkg::IdReset;
  localparam int          MapAw   = specular_axil_reg_pkg::BlockAw;

  // The map's access types (rtl/axi/data/specular_axil.rdl, docs/interfaces.md#register-map,
  // through the generated specular_axil_reg_pkg): which byte addresses are writable (RW, W1C,
  // WO) and which are readable. The proof checks the slave's decode of the address against
  // them, above the map's window included.
  function automatic logic f_writable(input logic [AddrWidth-1:0] a);
    f_writable = (a >> MapAw) == '0 && specular_axil_reg_pkg::WritableWords[a[MapAw-1:2]];
  endfunction
  function automatic logic f_readable(input logic [AddrWidth-1:0] a);
    f_readable = (a >> MapAw) == '0 && specular_axil_reg_pkg::ReadableWords[a[MapAw-1:2]];
  endfunction

  logic aw_fire, w_fire, b_fire, ar_fire, r_fire;
  assign aw_fire = s_axil_awvalid && s_axil_awready;
  assign w_fire  = s_axil_wvalid && s_axil_wready;
  assign b_fire  = s_axil_bvalid && s_axil_bready;
  assign ar_fire = s_axil_arvalid && s_axil_arready;
  assign r_fire  = s_axil_rvalid && s_axil_rready;

  // ---------------------------------------------------------------------------------
  // Assumptions: start in reset; an AXI4-Lite master
  // ---------------------------------------------------------------------------------
  `SPECULAR_FV_START_IN_RESET(clk_i, rst_ni)

  `SPECULAR_FV_AXIS_RULES(u_aw_rules, 1'b1, AddrWidth + 3, s_axil_awvalid, s_axil_awready,
                          {s_axil_awprot, s_axil_awaddr});
  `SPECULAR_FV_AXIS_RULES(u_w_rules, 1'b1, 36, s_axil_wvalid, s_axil_wready,
                          {s_axil_wstrb, s_axil_wdata});
  `SPECULAR_FV_AXIS_RULES(u_ar_rules, 1'b1, AddrWidth + 3, s_axil_arvalid, s_axil_arready,
                          {s_axil_arprot, s_axil_araddr});
  // P3 / P4: the responses held under backpressure (the slave drives B and R)
  `SPECULAR_FV_AXIS_RULES(u_b_rules, 1'b0, 2, s_axil_bvalid, s_axil_bready,
                          s_axil_bresp);
  `SPECULAR_FV_AXIS_RULES(u_r_rules, 1'b0, 34, s_axil_rvalid, s_axil_rready,
                          {s_axil_rresp, s_axil_rdata});

  // ---------------------------------------------------------------------------------
  // Requests and responses: outstanding counts, the addresses of the open requests
  // ---------------------------------------------------------------------------------
  logic [1:0]           aw_out_q, w_out_q, ar_out_q;
  logic [AddrWidth-1:0] f_awaddr_q, f_araddr_q;
  logic [1:0]           b_wait_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      aw_out_q     <= '0;
      w_out_q      <= '0;
      ar_out_q     <= '0;
      f_awaddr_q   <= '0;
      f_araddr_q   <= '0;
      b_wait_q     <= '0;
    end else begin
      aw_out_q     <= aw_out_q + 2'(aw_fire) - 2'(b_fire);
      w_out_q      <= w_out_q + 2'(w_fire) - 2'(b_fire);
      ar_out_q     <= ar_out_q + 2'(ar_fire) - 2'(r_fire);
      if (aw_fire) f_awaddr_q <= s_axil_awaddr;
      if (ar_fire) f_araddr_q <= s_axil_araddr;
      // clocks with both AW and W accepted and no B yet
      b_wait_q     <= (aw_out_q != '0 && w_out_q != '0 && !s_axil_bvalid) ? b_wait_q + 2'd1 : 2'd0;
    end
  end

  always_comb begin
    if (rst_ni) begin
      // P1 / P5: no response without its request(s)
      if (s_axil_bvalid) begin
        assert (aw_out_q != '0);
        assert (w_out_q != '0);
      end
      if (s_axil_rvalid) begin
        assert (ar_out_q != '0);
      end
      // P2: one outstanding write and one outstanding read
      assert (aw_out_q <= 2'd1);
      assert (w_out_q <= 2'd1);
      assert (ar_out_q <= 2'd1);
      // P3 / P4: u_b_rules, u_r_rules (above)
      // P6: progress
      assert (b_wait_q <= 2'd1);
      if (ar_out_q != '0) begin
        assert (s_axil_rvalid);
      end
      // P7: the responses
      if (s_axil_bvalid) begin
        assert (s_axil_bresp == (f_writable(f_awaddr_q) ? Okay : Slverr));
      end
      if (s_axil_rvalid) begin
        assert (s_axil_rresp == (f_readable(f_araddr_q) ? Okay : Slverr));
        if ((f_araddr_q >> 2) == '0) begin
          assert (s_axil_rdata == IdValue);
        end
      end
    end
  end

`ifndef FV_PROPERTIES_ONLY
  // ---------------------------------------------------------------------------------
  // Strengthening invariants on the slave's holding registers (probes, see the header)
  // ---------------------------------------------------------------------------------
  logic                 p_aw_full;
  logic                 p_w_full;
  logic [AddrWidth-1:0] p_awaddr;

  always_comb begin
    if (rst_ni) begin
      assert (aw_out_q == 2'(p_aw_full) + 2'(s_axil_bvalid));
      assert (w_out_q == 2'(p_w_full) + 2'(s_axil_bvalid));
      if (p_aw_full) begin
        assert (p_awaddr == f_awaddr_q);
      end
      assert (ar_out_q == 2'(s_axil_rvalid));
      if (b_wait_q != '0) begin
        assert (s_axil_bvalid);
      end
      assert (s_axil_awready == !(p_aw_full || s_axil_bvalid));
      assert (s_axil_wready == !(p_w_full || s_axil_bvalid));
    end
  end
`endif  // FV_PROPERTIES_ONLY
`endif  // FORMAL

endmodule
