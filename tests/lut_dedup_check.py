#!/usr/bin/env python3
"""lut_dedup_check: syn/lut_dedup.py keeps every cell's function and leaves no logic cell with one net on two inputs.

Builds small Yosys-style JSON netlists (random LUT functions with one, two or three inputs on a shared net; the
bottom carries of spec_add with a constant carry in; a carry whose carry in is a net; a LUT paired with a carry
that needs both its pins), runs the pass as a program on them, and evaluates every cell before and after it
for every value of its nets. Also: an unreadable netlist gets one line and exit 2.

Usage: lut_dedup_check.py SOURCE_DIR
Exit 0 when every check holds, 1 otherwise.
"""
import itertools
import json
import os
import random
import subprocess
import sys
import tempfile

PINS = ("I0", "I1", "I2", "I3")


def lut(init_bits, conn):
    return {"type": "SB_LUT4", "parameters": {"LUT_INIT": init_bits},
            "port_directions": {p: "input" for p in PINS} | {"O": "output"},
            "connections": {**{p: [conn[i]] for i, p in enumerate(PINS)}, "O": [1000 + random.getrandbits(20)]}}


def carry(i0, i1, ci):
    return {"type": "SB_CARRY", "parameters": {},
            "port_directions": {"I0": "input", "I1": "input", "CI": "input", "CO": "output"},
            "connections": {"I0": [i0], "I1": [i1], "CI": [ci], "CO": [2000 + random.getrandbits(20)]}}


def value(bit, env):
    return int(bit) if isinstance(bit, str) else env[bit]


def evaluate(c, env):
    conn = c["connections"]
    if c["type"] == "SB_LUT4":
        idx = sum(value(conn[p][0], env) << i for i, p in enumerate(PINS))
        return (int(c["parameters"]["LUT_INIT"], 2) >> idx) & 1
    a, b, ci = (value(conn[p][0], env) for p in ("I0", "I1", "CI"))
    return int(a + b + ci >= 2)


def nets_of(c):
    return sorted({b for p, bits in c["connections"].items() if c["port_directions"][p] == "input"
                   for b in bits if not isinstance(b, str)})


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else "."
    tool = os.path.join(src, "syn", "lut_dedup.py")
    random.seed(71489)
    cells = {}
    for i in range(300):   # LUTs: 4 inputs drawn from 3 nets and a constant, so duplicates of every kind
        conn = [random.choice([1, 2, 3, "0", "1"]) for _ in range(4)]
        cells["lut%d" % i] = lut(format(random.getrandbits(16), "016b"), conn)
    cells["bottom0"] = carry(5, 5, "0")          # spec_add's bottom: cin + cin, chain start
    cells["bottom1"] = carry(6, 6, "1")
    cells["mid"] = carry(7, 7, 8)                # carry in from the chain: cannot be rewritten
    cells["paired_carry"] = carry(9, 9, 10)      # and the LUT beside it needs both pins
    cells["paired_lut"] = lut("0110100110010110", ["0", 9, 9, 10])
    net = {"modules": {"top": {"attributes": {"top": 1}, "ports": {}, "cells": cells}}}
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        pre, post = os.path.join(tmp, "pre.json"), os.path.join(tmp, "post.json")
        json.dump(net, open(pre, "w"))
        r = subprocess.run([sys.executable, tool, pre, "--out", post], capture_output=True, text=True)
        if r.returncode != 0:
            print("lut_dedup_check: the pass failed: " + r.stderr.strip())
            return 1
        after = json.load(open(post))["modules"]["top"]["cells"]
        for name, c in cells.items():
            d = after[name]
            ns = nets_of(c)
            for vals in itertools.product((0, 1), repeat=len(ns)):
                env = dict(zip(ns, vals))
                if evaluate(c, env) != evaluate(d, env):
                    failures.append("%s: function changed for %s" % (name, env))
                    break
            pins = [d["connections"][p][0] for p in (PINS if d["type"] == "SB_LUT4" else ("I0", "I1"))]
            live = [b for b in pins if not isinstance(b, str)]
            kept = name in ("mid", "paired_carry", "paired_lut")
            if len(live) != len(set(live)) and not kept:
                failures.append("%s: still one net on two inputs: %s" % (name, pins))
            if kept and d["connections"] != c["connections"]:
                failures.append("%s: changed, but it must stay as it is" % name)
        if "2 SB_CARRY with one net on I0 and I1 and a carry in from the chain left" not in r.stdout:
            failures.append("the carries left as they are are not reported: " + r.stdout.strip())
        bad = os.path.join(tmp, "bad.json")
        open(bad, "w").write("{not json")
        r = subprocess.run([sys.executable, tool, bad], capture_output=True, text=True)
        if r.returncode != 2 or len(r.stderr.strip().splitlines()) != 1 or "Traceback" in r.stderr:
            failures.append("bad netlist: exit %d, stderr %r (want one line, exit 2)" % (r.returncode, r.stderr))
    for f in failures[:20]:
        print("lut_dedup_check: " + f)
    print("lut_dedup_check: %d cells, %s" % (len(cells), "every function kept" if not failures else
                                             "%d failure(s)" % len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
