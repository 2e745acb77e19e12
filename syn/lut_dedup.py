#!/usr/bin/env python3
"""lut_dedup: gives every iCE40 LUT of a Yosys JSON netlist distinct input nets, so that nextpnr-ice40 can route it.

nextpnr-ice40 (0.4) routes each LUT input to a logic cell's input wire and then through the cell's input
permutation switch. When one net drives two inputs of the same SB_LUT4, both arcs can end on the same input
wire, whose permutation switch cannot feed two LUT pins: router1 then rips the two arcs up in turn forever (the
remaining arc count stops moving) and router2 stops on an assertion. Whether it happens depends on the
placement, so a design routes with some seeds and not with others. Yosys 0.23 leaves such LUTs in the top cell
of spec_add (x = {p, a, cin} + {p, b, cin}: the cell computes p ^ p ^ carry), one per carry chain.

For each SB_LUT4 with the same net on two inputs, and not paired with an SB_CARRY that needs both (an SB_CARRY
takes its I0 and I1 from the LUT's I1 and I2 pins), this pass rewrites LUT_INIT so that the function reads the
first of the two inputs in both places, and ties the second to constant 0. The LUT's output is the same for
every value of its inputs. Used by syn/synth.py after syn/dsp_pack.py on iCE40 netlists; syn/dsp_pack_check.py
simulates the netlist before and after both passes.

Usage: lut_dedup.py NETLIST.json [--out OUT.json]
"""
import argparse
import json
import sys

PINS = ("I0", "I1", "I2", "I3")


def lut_bits(v):
    """LUT_INIT (a binary string, most significant bit first, or an integer) as a list, index = input value."""
    if isinstance(v, str):
        v = int(v.strip() or "0", 2)
    return [(v >> i) & 1 for i in range(16)]


def merged_init(init, keep, drop):
    """The 16-bit LUT_INIT whose output ignores input `drop` and reads input `keep` where it read `drop`."""
    bits = lut_bits(init)
    out = 0
    for i in range(16):
        k = (i >> keep) & 1
        j = (i & ~(1 << drop)) | (k << drop)
        out |= bits[j] << i
    return format(out, "016b")


def dedup(mod):
    """Rewrites the LUTs of one module in place; returns the names of the LUTs changed."""
    carries = set()
    for c in mod.get("cells", {}).values():
        if c["type"] == "SB_CARRY":
            conn = c["connections"]
            carries.add((conn["I0"][0], conn["I1"][0], conn["CI"][0]))
    changed = []
    for name, c in sorted(mod.get("cells", {}).items()):
        if c["type"] != "SB_LUT4":
            continue
        conn = c["connections"]
        if (conn["I1"][0], conn["I2"][0], conn["I3"][0]) in carries:
            continue    # the carry beside it needs its I1 and I2 pins as they are
        for drop in range(1, 4):
            for keep in range(drop):
                a, b = conn[PINS[keep]][0], conn[PINS[drop]][0]
                if not isinstance(a, str) and a == b:
                    c["parameters"]["LUT_INIT"] = merged_init(c["parameters"]["LUT_INIT"], keep, drop)
                    conn[PINS[drop]] = ["0"]
                    changed.append(name)
    return changed


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("netlist")
    ap.add_argument("--out", default="")
    args = ap.parse_args()
    try:
        with open(args.netlist) as f:
            net = json.load(f)
        mods = net["modules"]
    except (OSError, ValueError, KeyError, TypeError) as e:
        print("lut_dedup: cannot read %s as a Yosys JSON netlist: %s" % (args.netlist, e), file=sys.stderr)
        sys.exit(2)
    changed = []
    for mod in mods.values():
        changed += dedup(mod)
    with open(args.out or args.netlist, "w") as f:
        json.dump(net, f)
    print("lut_dedup: %d LUTs with one net on two inputs rewritten" % len(changed))


if __name__ == "__main__":
    main()
