#!/usr/bin/env python3
"""lut_dedup: gives every iCE40 logic cell of a Yosys JSON netlist distinct input nets, so that nextpnr-ice40 can
route it.

nextpnr-ice40 (0.4) routes each input of a logic cell (its LUT's, and an SB_CARRY's I0 and I1, which are the
cell's LUT inputs 1 and 2) to one of the cell's input wires and then through the cell's input permutation
switch. When one net drives two of those inputs, both arcs can end on the same input wire, whose permutation
switch cannot feed two pins: router1 then rips the two arcs up in turn forever (the remaining arc count stops
moving) and router2 stops on an assertion. Whether it happens depends on the placement, so a design routes with
some seeds and not with others. Yosys 0.23 leaves two such cells in every spec_add
(x = {p, a, cin} + {p, b, cin}): the bottom SB_CARRY adds cin + cin (carry out = cin) and the top LUT computes
p ^ p ^ carry. This pass rewrites them with the same function:

  * an SB_CARRY with one net on I0 and I1 and a constant carry in CI: its carry out is maj(x, x, CI) = x, and
    maj(x, 1, 0) = maj(x, 0, 1) = x, so I1 becomes the constant NOT CI (carries whose CI is a net are counted
    and left as they are);
  * an SB_LUT4 with the same net on two inputs, and not paired with an SB_CARRY that needs both (the carry takes
    its I0 and I1 from the LUT's I1 and I2 pins): LUT_INIT is rewritten so that the function reads the first of
    the two inputs in both places, and the second is tied to constant 0.

Every output is the same for every value of the inputs. Used by syn/synth.py after syn/dsp_pack.py on iCE40
netlists, and by the iCEBreaker flow; syn/dsp_pack_check.py simulates the netlist before and after both passes.

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
    """Rewrites the cells of one module in place; returns (carries changed, LUTs changed, carries left)."""
    carries = set()
    carries_changed, left = [], []
    for name, c in sorted(mod.get("cells", {}).items()):
        if c["type"] != "SB_CARRY":
            continue
        conn = c["connections"]
        i0, i1, ci = conn["I0"][0], conn["I1"][0], conn["CI"][0]
        if not isinstance(i0, str) and i0 == i1:
            if ci in ("0", "1"):
                conn["I1"] = ["1" if ci == "0" else "0"]
                carries_changed.append(name)
            else:
                left.append(name)
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
    return carries_changed, changed, left


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
    carries, luts, left = [], [], []
    for mod in mods.values():
        c, l, k = dedup(mod)
        carries, luts, left = carries + c, luts + l, left + k
    with open(args.out or args.netlist, "w") as f:
        json.dump(net, f)
    print("lut_dedup: %d SB_CARRY and %d SB_LUT4 with one net on two inputs rewritten" % (len(carries), len(luts)))
    if left:
        print("lut_dedup: %d SB_CARRY with one net on I0 and I1 and a carry in from the chain left as they are "
              "(nextpnr's router may stall on them): %s" % (len(left), ", ".join(left[:5])))


if __name__ == "__main__":
    main()
