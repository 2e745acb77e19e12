#!/usr/bin/env python3
"""induct.py - the k-induction step of formal.py, one assertion at a time (formal.py's `split` jobs).

The step yosys-smtbmc -i runs asks the solver at once for K + 1 states s0 .. sK, linked by transitions, in
which every assertion holds in s0 .. sK-1 and one fails in sK. This script asks the same question once per
assertion A of the model: K states where every assertion holds, followed by a state where A fails. When no
such trace exists for any A, none exists where some assertion fails: the same proof, in many small queries
(one solver process, incremental). An assertion proved for sK is kept as a fact about sK for the next ones.

usage: induct.py [-s z3|yices] [--unroll] [-t K] [--dump-vcd FILE] [--timeout SECONDS] MODEL.smt2
Prints `PASSED` (all assertions proved) or, for the first assertion that fails, the assertion, `FAILED` and a
counterexample trace of s0 .. sK (VCD). --timeout: seconds for the solver process (0: none); a timeout is a
failure.
"""
import argparse
import sys
import time

sys.path += ["/usr/share/yosys"]
from smtio import SmtIo, SmtOpts, MkVcd  # noqa: E402  (yosys-smtbmc's own solver interface)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-s", dest="solver", default="z3")
    ap.add_argument("--unroll", action="store_true")
    ap.add_argument("-t", dest="k", type=int, default=1)
    ap.add_argument("--dump-vcd")
    ap.add_argument("--timeout", type=int, default=0)
    ap.add_argument("model")
    a = ap.parse_args()

    so = SmtOpts()
    so.solver = a.solver
    so.unroll = a.unroll
    so.timeout = a.timeout
    so.timeinfo = False          # no progress spinner in the log
    smt = SmtIo(opts=so)
    t0 = time.time()

    def msg(text):
        print("%7.1f s  %s" % (time.time() - t0, text), flush=True)

    msg("solver: %s, k = %d" % (a.solver, a.k))
    with open(a.model) as f:
        for line in f:
            smt.write(line)
    top = smt.topmod
    k = a.k
    for i in range(k + 1):
        smt.write("(declare-fun s%d () |%s_s|)" % (i, top))
    for i in range(k + 1):
        smt.write("(assert (|%s_u| s%d))" % (top, i))
        smt.write("(assert (|%s_h| s%d))" % (top, i))
        smt.write("(assert (not (|%s_is| s%d)))" % (top, i))
        if i < k:
            smt.write("(assert (|%s_t| s%d s%d))" % (top, i, i + 1))
            smt.write("(assert (|%s_a| s%d))" % (top, i))
    if smt.modinfo[top].cells:
        msg("the model has submodules: their assertions would not be asked one by one (flatten it)\nFAILED")
        return finish(smt, 1)
    asserts = list(smt.modinfo[top].asserts.items())
    msg("%d assertions" % len(asserts))
    # the hypotheses alone must be satisfiable (else every query below would be unsat for nothing)
    r = smt.check_sat()
    if r != "sat":
        msg("the hypotheses (K states where every assertion holds) are %s: nothing proved\nFAILED" % r)
        return finish(smt, 1)
    for n, (fun, info) in enumerate(asserts):
        t1 = time.time()
        smt.write("(push 1)")
        smt.write("(assert (not (|%s| s%d)))" % (fun, k))
        r = smt.check_sat()
        if r != "unsat":
            msg("assertion %d of %d: %s (%s)" % (n + 1, len(asserts), r, info))
            if r == "sat":
                msg("Assert failed in %s: %s" % (top, info))
                if a.dump_vcd:
                    write_vcd(smt, top, k, a.dump_vcd)
                    msg("Writing trace to VCD file: %s" % a.dump_vcd)
            msg("FAILED")
            return finish(smt, 1)
        smt.write("(pop 1)")
        smt.write("(assert (|%s| s%d))" % (fun, k))
        dt = time.time() - t1
        if dt > 5:
            msg("assertion %d of %d proved in %.1f s: %s" % (n + 1, len(asserts), dt, info))
    # every assertion of the model was one of them: with each a fact about sK, the model's whole assertion holds
    smt.write("(push 1)")
    smt.write("(assert (not (|%s_a| s%d)))" % (top, k))
    r = smt.check_sat()
    if r != "unsat":
        msg("the model's assertion is not the conjunction of those asked (%s)\nFAILED" % r)
        return finish(smt, 1)
    smt.write("(pop 1)")
    msg("Temporal induction successful (every assertion, k = %d).\nPASSED" % k)
    return finish(smt, 0)


def finish(smt, rc):
    smt.write("(exit)")
    smt.wait()
    return rc


def write_vcd(smt, top, k, filename):
    """The counterexample s0 .. sK, every public net (as yosys-smtbmc writes its traces)."""
    with open(filename, "w") as f:
        vcd = MkVcd(f)
        paths = []
        for netpath in sorted(smt.hiernets(top)):
            if any(n.startswith("$") for n in netpath):
                continue
            edge = smt.net_clock(top, netpath)
            if edge is None:
                vcd.add_net([top] + netpath, smt.net_width(top, netpath))
            else:
                vcd.add_clock([top] + netpath, edge)
            paths.append(netpath)
        for i in range(k + 1):
            vcd.set_time(i)
            for path, value in zip(paths, smt.get_net_bin_list(top, paths, "s%d" % i)):
                vcd.set_net([top] + path, value)
        vcd.set_time(k + 1)


if __name__ == "__main__":
    sys.exit(main())
