#!/usr/bin/env python3
"""dsp_pack: moves flip-flops into the DSP blocks' and block RAMs' own registers in a Yosys JSON netlist.

Yosys (0.70) has no pass that does this for the ECP5: synth_ecp5 maps every multiplier to a MULT18X18D without
its input and output registers and every block RAM read to a DP16KD without its output register (REGMODE NOREG),
even when the RTL puts registers right at the multiplier's operands and product and at the memory's output. The
fabric path through the multiplier (3.9 ns at speed 6) and the block RAM's clock-to-output without its register
(5.6 ns) then limit the clock. Yosys 0.23's ice40_dsp takes an SB_MAC16's input registers only for 16-bit
operands. This pass does what those passes would: for each block, it takes

  * MULT18X18D (ECP5): the registers on A (and on B) when every non-constant A bit comes from a TRELLIS_FF
    that feeds nothing else; the output register when every used P bit feeds one TRELLIS_FF and nothing else.
    The block's CLK0 is the flip-flops' clock, CE0..CE3 their enables (one per distinct enable);
  * DP16KD (ECP5): the output register of a read port (REGMODE_A/B = OUTREG, OCEA/OCEB = the flip-flops'
    enable) when every used data output feeds one TRELLIS_FF and nothing else, on the port's own clock;
  * SB_MAC16 (iCE40): the A and B input registers (A_REG, B_REG; AHOLD/BHOLD = the enable inverted) when
    every non-constant A (B) bit comes from an SB_DFF/SB_DFFE that feeds nothing else.

Only plain flip-flops move: rising edge, no set or reset, initial value 0 (what the blocks' registers hold after
configuration), all on the block's clock. The flip-flops' D nets then drive the block's inputs, or the block's
outputs drive the flip-flops' Q nets. Cycle for cycle the same logic: a register loads under its enable either
way. Used by syn/synth.py after synthesis; prints what it moved.

Usage: dsp_pack.py NETLIST.json [--out OUT.json] [--family ecp5|ice40]
"""
import argparse
import json
import sys


def is_const(b):
    return isinstance(b, str)


def pbool(v):
    """A Yosys JSON parameter (a binary string or an integer) as a truth value."""
    if isinstance(v, str):
        return bool(v.strip()) and set(v.strip()) <= set("01") and int(v.strip(), 2) != 0
    return bool(v)


class Netlist:
    def __init__(self, mod):
        self.mod = mod
        self.cells = mod["cells"]
        self.users = {}
        self.driver = {}
        for name, c in self.cells.items():
            dirs = c.get("port_directions", {})
            for port, bits in c["connections"].items():
                for i, b in enumerate(bits):
                    if is_const(b):
                        continue
                    if dirs.get(port) == "output":
                        self.driver[b] = (name, port, i)
                    else:
                        self.users.setdefault(b, []).append((name, port, i))
        for pname, p in mod.get("ports", {}).items():
            for b in p["bits"]:
                if is_const(b):
                    continue
                if p["direction"] == "output":
                    self.users.setdefault(b, []).append(("$port", pname, 0))
        # nets that a netname keeps (kept wires count as users: never move their flip-flops)
        self.kept = set()
        for nn, nd in mod.get("netnames", {}).items():
            if nd.get("attributes", {}).get("keep"):
                self.kept.update(b for b in nd["bits"] if not is_const(b))

    def fanout(self, b):
        return self.users.get(b, [])


def ff_info_ecp5(c):
    """(clk, ce) of a plain rising-edge TRELLIS_FF without set/reset and with initial value 0, else None."""
    p = c["parameters"]
    con = c["connections"]
    if p.get("CLKMUX", "CLK").strip() != "CLK" or p.get("REGSET", "RESET").strip() != "RESET":
        return None
    if p.get("LSRMUX", "LSR").strip() != "LSR" or con.get("LSR", ["0"])[0] not in ("0",):
        return None
    if "M" in con and con["M"][0] not in ("0", "x"):
        return None
    cemux = p.get("CEMUX", "1").strip()
    if cemux == "1":
        ce = "1"
    elif cemux == "CE":
        ce = con["CE"][0]
    else:
        return None
    return con["CLK"][0], ce


def ff_info_ice40(c):
    """(clk, enable) of an SB_DFF / SB_DFFE (rising edge, no set/reset), else None."""
    con = c["connections"]
    if c["type"] == "SB_DFF":
        return con["C"][0], "1"
    if c["type"] == "SB_DFFE":
        return con["C"][0], con["E"][0]
    return None


class Packer:
    def __init__(self, mod, family):
        self.nl = Netlist(mod)
        self.family = family
        self.ff_types = ("TRELLIS_FF",) if family == "ecp5" else ("SB_DFF", "SB_DFFE")
        self.ff_info = ff_info_ecp5 if family == "ecp5" else ff_info_ice40
        self.d_port = "DI" if family == "ecp5" else "D"
        self.removed = set()   # flip-flops now inside a block (their outputs drive nothing else)
        self.copied = set()    # flip-flops copied into blocks' input registers (removed if nothing else uses them)
        self.private = {}      # (DSP block, net) -> that block's own inverter of the net (iCE40 holds)
        self.log = []

    def input_ffs(self, bits):
        """The flip-flops driving a block's input bits, when each non-constant bit is the Q of a plain
        flip-flop: [(bit index, ff name)], or None. A flip-flop that also feeds other logic stays (the block's
        register becomes a copy of it; Yosys merges the RTL's copies of a register into one)."""
        out = []
        for i, b in enumerate(bits):
            if is_const(b):
                continue
            drv = self.nl.driver.get(b)
            if drv is None or drv[1] != "Q" or b in self.nl.kept:
                return None
            ff = self.nl.cells[drv[0]]
            if ff["type"] not in self.ff_types or drv[0] in self.removed or self.ff_info(ff) is None:
                return None
            out.append((i, drv[0]))
        return out if out else None

    def output_ffs(self, bits):
        """The flip-flops a block's output bits feed, when each used bit feeds exactly one plain flip-flop's D
        and nothing else: [(bit index, ff name)], or None (also when no bit is used)."""
        out = []
        for i, b in enumerate(bits):
            if is_const(b):
                continue
            us = self.nl.fanout(b)
            if not us:
                continue
            if len(us) != 1 or b in self.nl.kept:
                return None
            name, port, _ = us[0]
            if name == "$port" or port != self.d_port:
                return None
            ff = self.nl.cells[name]
            if ff["type"] not in self.ff_types or name in self.removed or name in self.copied or \
                    self.ff_info(ff) is None:
                return None
            out.append((i, name))
        return out if out else None

    def common(self, ffs, clk):
        """The one enable of these flip-flops on clock clk, or None."""
        infos = {self.ff_info(self.nl.cells[f]) for _, f in ffs}
        if len(infos) != 1:
            return None
        c, ce = infos.pop()
        return ce if c == clk else None

    def take_inputs(self, cell, bits, ffs):
        for i, f in ffs:
            bits[i] = self.nl.cells[f]["connections"][self.d_port][0]
            self.copied.add(f)

    def take_outputs(self, bits, ffs):
        for i, f in ffs:
            bits[i] = self.nl.cells[f]["connections"]["Q"][0]
            self.removed.add(f)

    # ---- ECP5 ------------------------------------------------------------------------------------------------
    def mult18(self, name, c):
        con, par = c["connections"], c["parameters"]
        clk = None
        ces = []        # distinct enables -> CE0..CE3

        def ce_port(ce):
            if ce not in ces:
                ces.append(ce)
            return "CE%d" % ces.index(ce)
        plan = []
        for grp in ("A", "B"):
            bits = [con.get("%s%d" % (grp, k), ["0"])[0] for k in range(18)]
            ffs = self.input_ffs(bits)
            if not ffs:
                continue
            fclk = self.ff_info(self.nl.cells[ffs[0][1]])[0]
            clk = clk or fclk
            ce = self.common(ffs, clk)
            if ce is None or len(set(ces + [ce])) > 4:
                continue
            plan.append(("in", grp, bits, ffs, ce_port(ce)))
        pbits = [con.get("P%d" % k, ["x"])[0] for k in range(36)]
        offs = self.output_ffs(pbits)
        if offs:
            fclk = self.ff_info(self.nl.cells[offs[0][1]])[0]
            if clk is None or fclk == clk:
                clk = fclk
                ce = self.common(offs, clk)
                if ce is not None and len(set(ces + [ce])) <= 4:
                    plan.append(("out", "P", pbits, offs, ce_port(ce)))
        if not plan:
            return
        for kind, grp, bits, ffs, cep in plan:
            if kind == "in":
                self.take_inputs(c, bits, ffs)
                for k in range(18):
                    con["%s%d" % (grp, k)] = [bits[k]]
                par["REG_INPUT%s_CLK" % grp] = "CLK0"
                par["REG_INPUT%s_CE" % grp] = cep
                par["REG_INPUT%s_RST" % grp] = "RST0"
            else:
                self.take_outputs(bits, ffs)
                for k in range(36):
                    if not is_const(bits[k]):
                        con["P%d" % k] = [bits[k]]
                par["REG_OUTPUT_CLK"] = "CLK0"
                par["REG_OUTPUT_CE"] = cep
                par["REG_OUTPUT_RST"] = "RST0"
            self.log.append("%s: %s register (%d flip-flops, %s)" % (name, "input " + grp if kind == "in" else
                                                                     "output", len(ffs), cep))
        self.port(c, "CLK0", clk)
        for k, ce in enumerate(ces):
            self.port(c, "CE%d" % k, ce)
        self.port(c, "RST0", "0")
        par.setdefault("GSR", "DISABLED")

    def dp16kd(self, name, c):
        con, par = c["connections"], c["parameters"]
        for side in ("A", "B"):
            if par.get("REGMODE_%s" % side, "NOREG") != "NOREG":
                continue
            outs = [k for k in range(18) if "DO%s%d" % (side, k) in con]
            bits = [con["DO%s%d" % (side, k)][0] for k in outs]
            ffs = self.output_ffs(bits)
            if not ffs:
                continue
            clk = con.get("CLK%s" % side, ["0"])[0]
            if is_const(clk) or par.get("CLK%sMUX" % side, "CLK" + side) != "CLK" + side:
                continue
            if con.get("RST%s" % side, ["0"])[0] != "0":
                continue
            ce = self.common(ffs, clk)
            if ce is None:
                continue
            self.take_outputs(bits, ffs)
            for k, b in zip(outs, bits):
                con["DO%s%d" % (side, k)] = [b]
            par["REGMODE_%s" % side] = "OUTREG"
            self.port(c, "OCE%s" % side, ce)
            self.log.append("%s: port %s output register (%d flip-flops)" % (name, side, len(ffs)))

    # ---- iCE40 -----------------------------------------------------------------------------------------------
    def mac16(self, name, c):
        con, par = c["connections"], c["parameters"]
        clk = con["CLK"][0]
        if con.get("CE", ["1"])[0] != "1" or any(con.get(p, ["0"])[0] != "0" for p in ("IRSTTOP", "IRSTBOT")):
            return
        for grp in ("A", "B"):
            if pbool(par.get("%s_REG" % grp, 0)):
                continue
            if con.get("%sHOLD" % grp, ["0"])[0] != "0":
                continue
            bits = list(con[grp])
            ffs = self.input_ffs(bits)
            if not ffs:
                continue
            en = self.common(ffs, clk)
            if en is None:
                continue
            self.take_inputs(c, bits, ffs)
            con[grp] = bits
            par["%s_REG" % grp] = "1"
            if en != "1":
                self.port(c, "%sHOLD" % grp, self.inverter(name, en))
            self.log.append("%s: input %s register (%d flip-flops)" % (name, grp, len(ffs)))

    def inverted(self, b):
        """x when net b comes from an SB_LUT4 that computes ~x of one net x (its other inputs constant)."""
        drv = self.nl.driver.get(b)
        if drv is None or drv[1] != "O" or self.nl.cells[drv[0]]["type"] != "SB_LUT4":
            return None
        c = self.nl.cells[drv[0]]
        ins = [c["connections"].get("I%d" % k, ["0"])[0] for k in range(4)]
        nets = [k for k, x in enumerate(ins) if not is_const(x)]
        if len(nets) != 1 or any(x not in ("0", "1") for k, x in enumerate(ins) if k != nets[0]):
            return None
        init = str(c["parameters"].get("LUT_INIT", "0"))
        init = int(init, 2) if set(init) <= set("01") else int(init)
        idx = [sum((1 << k) for k, x in enumerate(ins) if x == "1"), 0]
        idx[1] = idx[0] | (1 << nets[0])
        return ins[nets[0]] if ((init >> idx[0]) & 1, (init >> idx[1]) & 1) == (1, 0) else None

    def inverter(self, mac, net):
        """A net carrying ~net for this DSP block alone: each block gets its own inverter LUT (Yosys shares one
        between the blocks, which sit at both edges of the chip, so the shared one ends up far from all)."""
        key = (mac, net)
        if key in self.private:
            return self.private[key]
        new = max(b for cc in self.nl.cells.values() for bb in cc["connections"].values() for b in bb
                  if not is_const(b)) + 1
        name = "$dsp_pack$inv%d" % new
        self.nl.cells[name] = {
            "hide_name": 1, "type": "SB_LUT4", "parameters": {"LUT_INIT": "0000000000000001"}, "attributes": {},
            "port_directions": {"I0": "input", "I1": "input", "I2": "input", "I3": "input", "O": "output"},
            "connections": {"I0": [net], "I1": ["0"], "I2": ["0"], "I3": ["0"], "O": [new]}}
        self.nl.driver[new] = (name, "O", 0)
        self.private[key] = new
        return new

    def private_holds(self, name, c):
        """The block's hold inputs from inverter LUTs of its own."""
        for p in ("AHOLD", "BHOLD", "CHOLD", "DHOLD", "OHOLDTOP", "OHOLDBOT"):
            b = c["connections"].get(p, ["0"])[0]
            if is_const(b):
                continue
            x = self.inverted(b)
            if x is not None:
                c["connections"][p] = [self.inverter(name, x)]

    @staticmethod
    def port(c, p, b):
        c["connections"][p] = [b]
        c.setdefault("port_directions", {})[p] = "input"

    def run(self):
        # block RAMs first: a flip-flop between a block RAM and a multiplier becomes the RAM's output register
        # (the multiplier's input register then needs a second one, as the RTL has it)
        for name, c in sorted(self.nl.cells.items()):
            if self.family == "ecp5" and c["type"] == "DP16KD":
                self.dp16kd(name, c)
        for name, c in sorted(self.nl.cells.items()):
            if self.family == "ecp5" and c["type"] == "MULT18X18D":
                self.mult18(name, c)
            elif self.family == "ice40" and c["type"] == "SB_MAC16":
                self.mac16(name, c)
                self.private_holds(name, c)
        for f in self.removed:
            del self.nl.cells[f]
        # copied flip-flops that feed nothing now
        used = set()
        for c in self.nl.cells.values():
            dirs = c.get("port_directions", {})
            for p, bits in c["connections"].items():
                if dirs.get(p) != "output":
                    used.update(b for b in bits if not is_const(b))
        for p in self.nl.mod.get("ports", {}).values():
            used.update(b for b in p["bits"] if not is_const(b))
        for f in sorted(self.copied - self.removed):
            q = self.nl.cells[f]["connections"]["Q"][0]
            if q not in used and q not in self.nl.kept:
                del self.nl.cells[f]
        # inverters that the blocks' private ones replaced and that now drive nothing
        for name in [n for n, c in self.nl.cells.items() if c["type"] == "SB_LUT4"]:
            o = self.nl.cells[name]["connections"]["O"][0]
            if not is_const(o) and o not in used and o not in self.nl.kept:
                del self.nl.cells[name]
        return self.log


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("netlist")
    ap.add_argument("--out", default="")
    ap.add_argument("--family", choices=("ecp5", "ice40"), required=True)
    args = ap.parse_args()
    try:
        with open(args.netlist) as f:
            net = json.load(f)
    except (OSError, ValueError) as e:
        print("dsp_pack: cannot read %s: %s" % (args.netlist, e), file=sys.stderr)
        sys.exit(2)
    log = []
    for mod in net.get("modules", {}).values():
        if mod.get("attributes", {}).get("top") or len(net["modules"]) == 1:
            log += Packer(mod, args.family).run()
    with open(args.out or args.netlist, "w") as f:
        json.dump(net, f)
    for line in log:
        print("dsp_pack: " + line)
    print("dsp_pack: %d registers moved into blocks" % len(log))


if __name__ == "__main__":
    main()
