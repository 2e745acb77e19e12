#!/usr/bin/env python3
"""formal.py - proves the formal properties of formal/*.v (make formal).

For each job: the generator writes ROM images and a parameter header for the reduced widths below; Yosys
reads rtl/ at those widths, flattens the core, makes the internal signals the properties name into ports
(`expose`) and renames it, reads the property wrapper on top and writes an SMT-LIB2 model; yosys-smtbmc
with z3 then runs
  - the base case: every assertion holds in every cycle of every trace from reset up to DEPTH cycles (BMC),
  - the induction step: DEPTH cycles in which the assertions hold are always followed by one in which
    they hold too; with the base case this proves them for traces of any length (unbounded). A job with
    split=True runs it through formal/induct.py, which asks the same question once per assertion (DEPTH
    cycles in which all hold, then one in which that one fails) in one incremental solver session: the
    one query over all assertions at once (yosys-smtbmc -i) did not finish for spec_stream in 16 minutes
    (z3, and 10 minutes with yices); the split queries take about a minute with z3,
  - the covers: a trace reaches each `cover` within COVER cycles.
It is what SymbiYosys does for `mode prove` and `mode cover`, without needing SymbiYosys.
Exit code 0 only when every proof and every cover passed; a failing proof leaves a counterexample trace
(VCD) in the work directory and says where.

usage: formal.py [--specrom PATH] [--work DIR] [--jobs NAME,...] [--yosys yosys] [--smtbmc yosys-smtbmc]
                 [--solver z3|yices] [--steps bmc,induction,cover] [--rtl DIR] [--step-timeout S]
                 [--mutants] [--data FILE.json]
--data: also write the results (every step, its time, the covers reached; or every mutant) as JSON, which
`make formal` / `make formal-mutants` put into docs/data/ for docs/verification.md (scripts/docgen.py). A proof
run replaces the rows of the jobs it ran and keeps the other jobs' rows (each row has its date).
"""
import json
import argparse
import os
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# The reduced widths (rom/gen Format::validate limits): 4-bit C and output, 14-bit angles (11 fraction
# bits; spec_stream's accumulator needs ANG_W + L_W > 16 for its two segments), n 0..15 (N_W = 4: decoder
# 10's gates assume at least four bits), l 0..7, ROM 9 5-bit words, ROM 12 4 tables x 16 positions of 5 bits.
WIDTHS = ["--c-w", "4", "--ang-w", "14", "--ang-frac", "11", "--n-w", "4", "--l-w", "3",
          "--scale-w", "5", "--scale-frac", "4", "--tbl-aw", "4", "--tbl-frac", "4"]


def with_args(args, changes):
    """args (a specrom argument list of --option value pairs) with the values of the options in changes replaced."""
    return [changes.get(args[i - 1], v) if i % 2 else v for i, v in enumerate(args)]


# The small setup's job (setup_engine): the same descriptor widths but n 10 bits (spec_setup_backend's program has
# ten multiplication steps; ROM 9 then needs a wider scale) and the smallest small-setup format the generator
# accepts (setuprom --config up5k: 8 micro-rotations, 22-bit coordinates, 20-bit angle fractions, 4 + 4-bit table
# addresses).
WIDTHS_N10 = with_args(WIDTHS, {"--n-w": "10", "--scale-w": "9"})
SETUP_SMALL = ["--f", "22", "--iters", "8", "--zf", "20", "--lf", "12", "--ef", "12", "--tb", "4", "--rb", "4",
               "--gain-frac", "8", "--flat-log2", "-10"]

# The schedule of the jobs that leave the multiplier setup's arithmetic out (spec_setup, spec_shader: `sched`):
# setuprom's header for the ecp5 configuration with these values in place of its own (II = 41, LATENCY = 549),
# written to <rom>_fv/setup_params.vh, which Yosys finds before the generated one. spec_setup sizes its FIFO from
# them as always (FLY = LATENCY / II + 3 = 4: FIFO_AW = 2, 6 credits); the stubs (formal/fv_setup_stub.v) start a
# span every II clocks and give its descriptor LATENCY clocks later, so two spans are in flight between them.
FV_SCHED = {"SETUP_II": 2, "SETUP_LATENCY": 3}


def core_files(rtl_dir):
    """The core's RTL: the one file list rtl/spec_core.f (names relative to rtl/)."""
    with open(os.path.join(ROOT, "rtl", "spec_core.f")) as f:
        return [os.path.join(rtl_dir, line.strip()) for line in f if line.strip()]


def shader_files(rtl_dir, exclude=()):
    """spec_setup's and spec_shader's RTL: rtl/spec_shader.f, without the files a job replaces."""
    with open(os.path.join(ROOT, "rtl", "spec_shader.f")) as f:
        return [os.path.join(rtl_dir, line.strip()) for line in f if line.strip() and line.strip() not in exclude]


JOBS = {
    "spec_unit": dict(
        core="spec_unit", wrapper="fv_spec_unit",
        expose=["c_q", "dzeta_q", "zeta0_q", "n_q", "u_cnt5.q", "u_ctrl14.ff39", "u_ctrl14.gen40",
                "u_ctrl14.ff41", "u_ctrl14.ff43", "u_ctrl14.ff44", "fresh8", "u_dp.vs", "start_q", "len_q"],
        depth=2, bmc=40, cover=48),
    # spec_stream with LANES = 1, 2 (PACK = 1) and 4 (PACK = 0): the span generator's, the pipeline's and the
    # output's flags made ports for the helper invariants of fv_spec_stream.v. LANES = 1: proved by induction
    # (k = 1, one query per assertion: formal/induct.py); its base case needs only k cycles, and 12 take z3 about
    # two minutes with the helper invariants (32 did not finish in 12 minutes: each cycle past the first pixel's
    # latency costs more)
    "spec_stream": dict(
        core="spec_stream", wrapper="fv_spec_stream", params={},
        expose=["ce", "u_gen.tk", "u_gen.pl", "u_gen.pl_n", "u_gen.room", "u_gen.prep_v", "u_gen.head_v",
                "u_gen.tail_v", "u_gen.head_l", "u_gen.head_zg", "u_gen.tail", "u_gen.prep_lq0", "u_gen.prep_lq1",
                "u_gen.prep_lq2p", "u_gen.prep_nlqm1", "u_gen.prep_nlqm2", "u_gen.prep_lr", "u_gen.r_v",
                "u_gen.r_ntk", "u_gen.r_last1_bc", "u_gen.r_second", "u_gen.r_end", "u_gen.r_s", "u_gen.bc",
                "u_gen.r_nt2", "u_gen.bv", "u_gen.blst", "ctl_v", "ctl_l", "u_out.have_q", "u_out.skid_v",
                "u_out.skid_keep", "u_out.skid_last"],
        # the datapath's pixel value is cut off and left free (every value possible): the properties are
        # about flow control, and without the multipliers, ROMs and the 32-bit accumulator z3 is much faster
        cut=["dp_out"],
        # the covers and the mutants' bounded checks on a model without the helper invariants (lean_defines:
        # FV_NO_HELPERS): a cover needs no assertion (z3 spent minutes evaluating them on every cover trace), and
        # the mutants show what the properties catch, as before the helpers (deep bounded checks with them are slow)
        depth=1, split=True, bmc=12, cover=36, lean_defines=["FV_NO_HELPERS"]),
    # spec_setup (issue 28, docs/setup.md): its holding register, credits and descriptor FIFO around the arithmetic,
    # which is left out (formal/fv_setup_stub.v: spec_setup_machine's slot and span counters, spec_setup_finish as
    # a LATENCY-clock pipeline that passes each started span's side information on), at the small schedule of
    # FV_SCHED (II = 2, LATENCY = 3: a 4-word FIFO, 6 credits) and with the memories mapped to registers before
    # `expose`, so that the helper invariants can name every word: order, no loss or duplication, AXI rules,
    # no deadlock, reset, for traces of any length by induction (k = 1; formal/fv_spec_setup.v)
    "spec_setup": dict(
        core="spec_setup", wrapper="fv_spec_setup", shader=True, sched=True, map_memories=True,
        exclude=["spec_setup_machine.v", "spec_setup_finish.v"], extra=["formal/fv_setup_stub.v"],
        expose=["held", "ready_q", "credit", "h_n", "h_l", "h_rule", "h_inv", "u_mach.tau", "u_fin.v", "u_fin.sd",
                "u_fifo.cm", "u_fifo.wp", "u_fifo.rp", "u_fifo.rv", "u_fifo.rd", "u_fifo.skid_v", "u_fifo.skid_d",
                "u_fifo.mem*"],
        depth=1, bmc=12, cover=32, lean_defines=["FV_NO_HELPERS"]),
    # spec_shader: the composition (flags FIFO, tuser, the gating of spec_stream's input) with the setup's
    # arithmetic left out as in the spec_setup job (the stubs, FV_SCHED) and the pixel value cut off; bounded
    # (formal/fv_spec_shader.v). The covers: the first pixel of the second span handed over in step 36, the last
    # pixel of the third after a stall in step 40, so the bound is 40 (steps 0 .. 39: that pixel offered and held);
    # z3's time grows about 1.5x with each step there: 11 minutes at 40 on the shared machine, over 20 at 42.
    "spec_shader": dict(
        core="spec_shader", wrapper="fv_spec_shader", shader=True, sched=True,
        exclude=["spec_setup_machine.v", "spec_setup_finish.v"], extra=["formal/fv_setup_stub.v"],
        chparam={"FLAGS_AW": 2}, expose=["fcnt"],
        cut=["g_stream.u_stream.dp_out"], steps=["bmc", "cover"], depth=0, bmc=40, cover=41),
}
# spec_stream_seq (the compact back end, one span at a time; formal/fv_spec_stream_seq.v): AXI rules, l + 1 pixels a
# span in order with tlast on the last, one span at a time, no deadlock; k = 1 with helper invariants over the
# datapath's valid and last flags (spec_datapath's vs_q and ls_q); the
# covers and the mutants on the model without the helper invariants (the mutants show what the properties catch)
JOBS["spec_stream_seq"] = dict(
    core="spec_stream_seq", wrapper="fv_spec_stream_seq",
    expose=["ready_q", "run", "cnt", "ce", "u_dp.g_ctrl.vs_q", "u_dp.g_ctrl.ls_q",
            "u_out.have_q", "u_out.skid_v", "u_out.skid_keep", "u_out.skid_last"],
    cut=["dp_out"], depth=1, split=True, bmc=24, cover=34, lean_defines=["FV_NO_HELPERS"])
# The small setup (spec_setup_small, the up5k configuration's: spec_setup_engine, spec_setup_backend;
# formal/fv_setup_engine.v): the handshake, the accounting and a ranking key that grows while a span is in flight (no
# deadlock), for traces of any length by k-induction. k = 3: the output words' stability needs the two memories'
# read registers (the engine's vector memory, the back end's register file) to have read the same word for two
# cycles, which the induction sees in three states without the memories' words being named. A span takes over a
# thousand cycles at these widths: the bounded base case and the covers reach the vectors' load and the first runs.
JOBS["setup_engine"] = dict(
    core="spec_setup_small", wrapper="fv_setup_engine", shader=True, rom="rom_n10", widths=WIDTHS_N10,
    small_widths=SETUP_SMALL,
    expose=["u_engine." + w for w in (
        "st", "ph", "it", "rph", "qt", "run", "run_tests", "ld_v", "ld_c", "be_start", "bad", "rule_reg", "opp",
        "v_ra", "v_we", "n_reg", "l_reg")] + ["u_engine.u_back." + w for w in (
        "pc1", "bph", "ph2", "lam_q", "a_fast", "a_idle", "a_div", "a_norm", "a_shift", "a_out", "done", "lge_nz",
        "sc_nz", "div_done", "out_rdy", "acc_en_pre", "c_rw", "c_act", "c_fl", "c_cd", "lg_e", "sc", "dcnt",
        "zero_c", "sat", "nohl", "flat", "ccode", "c_out", "f_out")],
    # the two multipliers' products feed data only (the opposite test, the table interpolation): left free
    cut=["u_engine.rho2k", "u_engine.u_back.tprod"],
    depth=3, bmc=12, cover=16)
# Pow mode (issue 30, docs/pow.md): the control is the patent's, so the same proofs run with pow mode's
# parameters: the generator's pow images and header at the reduced widths (a log table of 2 x 4 segments x 4
# entries, 8-bit values; ROM 12 of 16 positions of 9 bits: pow mode needs TBL_FRAC >= 8), the datapath
# spec_powpath with its longer latency (the wrappers read it from the header)
# (POW_ARGS: the first pair replaces WIDTHS' --tbl-frac, the rest follow; docs/verification.md quotes them)
POW_ARGS = ["--tbl-frac", "8", "--mode", "pow", "--pow-seg-w", "2", "--pow-idx-w", "2", "--pow-frac", "2",
            "--pow-val-w", "8", "--pow-dlt-w", "8", "--pow-sh-w", "4", "--pow-xb", "4", "--pow-yf", "6", "--pow-yi", "3"]
WIDTHS_POW = with_args(WIDTHS, {POW_ARGS[0]: POW_ARGS[1]}) + POW_ARGS[2:]
# The pipeline is 8 stages longer at these widths (spec_unit's first pixel in cycle 23 instead of 15; the longest
# span, l = 7, ends in cycle 37; a Start without a load repeats a span of l = 3, the second ending near cycle 60):
# the base case and the covers reach as far past them as patent mode's jobs do. spec_stream_seq takes the next
# descriptor only when the datapath is empty, so its covers of a second span (its second pixel; two spans out and
# one in the datapath) pass through the longer pipeline twice: 16 cycles more than patent mode's 34.
JOBS["spec_unit_pow"] = dict(JOBS["spec_unit"], rom="rom_pow", widths=WIDTHS_POW, bmc=48, cover=64)
JOBS["spec_stream_pow"] = dict(JOBS["spec_stream"], rom="rom_pow", widths=WIDTHS_POW, cover=46)
JOBS["spec_stream_seq_pow"] = dict(JOBS["spec_stream_seq"], rom="rom_pow", widths=WIDTHS_POW, cover=50)
for _lanes, _pack in ((2, 1), (4, 0)):
    # bounded checks and covers only: fv_spec_stream.v's helper invariants are written for LANES = 1
    JOBS["spec_stream_l%d%s" % (_lanes, "p" if _pack else "")] = dict(JOBS["spec_stream"], depth=None, bmc=32,
                                                                  lean_defines=None,
                                                                  params={"LANES": _lanes, "PACK": _pack})


# Mutants (--mutants): small bugs put into a copy of rtl/; a bounded check of the named job (MUTANT_BMC
# cycles deep) must fail on each, which shows that the properties can fail and what they catch. An equivalent
# change must pass (spec_unit's, spec_setup's, setup_engine's; for spec_stream a passing check takes z3 far longer
# than the failing ones, which stop at their first counterexample: over ten minutes at 24 cycles).
# setup_engine: a span takes over a thousand cycles, beyond a bounded check, and spec_setup: a bounded check of the
# model without the helper invariants doubles its time with every cycle past 18 (about three minutes at 20), so
# their mutants are also run through the job's induction step (MUTANT_STEPS; on the model with the helper
# invariants, as the proof runs it): a mutant counts as caught when the bounded check finds a trace from reset (a
# real failure) or, failing that, the k-induction no longer proves the properties (its counterexample starts in a
# state where every assertion held for k cycles, not necessarily one reachable from reset; the equivalent change
# shows that the proof survives a harmless edit).
MUTANT_BMC = {"spec_unit": 40, "spec_stream": 32, "spec_stream_l2p": 32, "spec_stream_l4": 32, "spec_setup": 20,
              "spec_shader": 40, "spec_stream_seq": 36, "setup_engine": 8, "spec_unit_pow": 48,
              "spec_stream_pow": 40, "spec_stream_seq_pow": 44}
MUTANT_STEPS = {"spec_setup": ["bmc", "induction"], "setup_engine": ["bmc", "induction"]}
MUTANTS = [
    ("spec_unit", "spec_unit.v", "wire len_we = ~len_load_n & idle;", "wire len_we = ~len_load_n;",
     "counter 5 loads while busy"),
    ("spec_unit", "spec_unit.v", ".we(c_we & idle)", ".we(c_we)", "register 1 written while busy"),
    ("spec_unit", "spec_unit.v", "wire start_go = start & ~start_q & idle;", "wire start_go = start & ~start_q;",
     "Start not ignored while busy"),
    ("spec_unit", "spec_unit.v", "wire start_go = start & ~start_q & idle;", "wire start_go = start & idle;",
     "Start as a level (the 211-pixel trap)"),
    ("spec_unit", "spec_unit.v", ".load_n(~(len_we | start_go))", ".load_n(~len_we)",
     "a Start without a load runs 2^L_W pixels (counter 5 not reloaded)"),
    ("spec_unit", "spec_unit.v", "assign busy_o = sig28 | fresh8 | dp_busy;", "assign busy_o = sig28 | fresh8;",
     "busy_o falls before the last pixel is out"),
    ("spec_unit", "spec_counter.v", "(q == {W{1'b0}})", "(q == {{(W - 1) {1'b0}}, 1'b1})",
     "the span ends one pixel early"),
    ("spec_unit", "spec_ctrl.v", "gen40 <= ff39 & ~gen40;", "gen40 <= ~gen40;",
     "pulse generator free-running while idle (latency varies)"),
    ("spec_unit", "spec_ctrl.v", "if (sig37) begin", "if (sig37 && ff41) begin", "an equivalent change (must pass)"),
    ("spec_stream", "spec_spangen.v", "wire r_last1 = (r_v & ~r_ntk) | r_last1_bc;",
     "wire r_last1 = r_last1_bc;", "a span's last beat missed (spans run long)"),
    ("spec_stream", "spec_stream_out.v", "(in_valid & m_axis_tvalid & ~m_axis_tready);", "1'b0;",
     "the skid buffer drops a pixel on a stall"),
    ("spec_stream", "spec_spangen.v", "wire accept = s_axis_tvalid & ready_q;", "wire accept = s_axis_tvalid;",
     "a descriptor taken while tready is low"),
    ("spec_stream", "spec_stream_out.v", "end else if (o_load) begin\n            m_axis_tdata",
     "end else if (o_load | ~m_axis_tready) begin\n            m_axis_tdata", "tdata reloaded while stalled"),
    ("spec_stream", "spec_stream_out.v", "            m_axis_tvalid <= 1'b0;\n            skid_v <= 1'b0;",
     "            m_axis_tvalid <= 1'b0;", "reset leaves the skid buffer full"),
    ("spec_stream_l4", "spec_stream_out.v", "m_axis_tkeep <= skid_v ? skid_keep : in_keep;",
     "m_axis_tkeep <= skid_v ? skid_keep : {LANES{1'b1}};", "tkeep keeps every slot of a span's last beat"),
    ("spec_setup", "spec_setup.v", "credit <= DEPTH;", "credit <= DEPTH + 1'b1;",
     "spec_setup: one credit more than the FIFO holds"),
    ("spec_setup", "spec_setup_fifo.v", "if (~skid_v) skid_d <= rd;", "skid_d <= rd;",
     "spec_setup: the skid buffer overwritten while full"),
    ("spec_setup", "spec_setup_fifo.v", "wire re = ce && (cm != {(AW + 1) {1'b0}});", "wire re = (cm != {(AW + 1) {1'b0}});",
     "spec_setup: the FIFO read while its read stage is held"),
    ("spec_setup", "spec_setup.v", "ready_q <= ~(take | (held & ~start));", "ready_q <= ~(held & ~start);",
     "spec_setup: s_axis_tready not lowered after a take (a second beat overwrites the held one)"),
    ("spec_setup", "spec_setup.v", "held <= take | (held & ~start);", "held <= take | held;",
     "spec_setup: the held beat not released by its start (started again)"),
    ("spec_setup", "spec_setup.v", "wire start = tau0 & held & (credit != {(FIFO_AW + 2) {1'b0}});",
     "wire start = tau0 & held;", "spec_setup: a span started without a credit"),
    ("spec_setup", "spec_setup.v",
     "credit <= credit - {{(FIFO_AW + 1) {1'b0}}, start} + {{(FIFO_AW + 1) {1'b0}}, handover};",
     "credit <= credit - {{(FIFO_AW + 1) {1'b0}}, start};",
     "spec_setup: the credit not returned on a handover (deadlock)"),
    ("spec_setup", "spec_setup_fifo.v", "wire re = ce && (cm != {(AW + 1) {1'b0}});",
     "wire re = ce && (cm > {{AW{1'b0}}, 1'b1});", "spec_setup: the FIFO's last word not read (deadlock)"),
    ("spec_setup", "spec_setup.v", "wire take = s_axis_tvalid & ready_q;", "wire take = s_axis_tvalid & ready_q & ~held;",
     "spec_setup: an equivalent change (must pass)"),
    ("spec_shader", "spec_shader.v", "else m_axis_tuser <= pop ? fmem[fr_next] : d_flags;",
     "else m_axis_tuser <= pop ? fmem[fr] : d_flags;", "spec_shader: the finished span's flags kept on tuser"),
    ("spec_shader", "spec_shader.v", "fspace <= fcnt_n < (1 << FLAGS_AW) - 1;", "fspace <= 1'b1;",
     "spec_shader: the flags FIFO not full-checked"),
    ("spec_shader", "spec_shader.v", "fone <= fcnt_n == {{FLAGS_AW{1'b0}}, 1'b1};", "fone <= 1'b0;",
     "spec_shader: fone never set (a span that arrives as the only one leaves gets stale flags)"),
    ("spec_stream_seq", "spec_stream_seq.v", "ready_q <= ~accept & ~run & ~dp_busy;", "ready_q <= ~accept & ~run;",
     "seq: a descriptor taken while the datapath holds the span before"),
    ("spec_stream_seq", "spec_stream_seq.v", "wire last = (cnt == {L_W{1'b0}});",
     "wire last = (cnt == {{(L_W - 1) {1'b0}}, 1'b1});", "seq: the span ends one pixel early"),
    ("spec_stream_seq", "spec_stream_seq.v", "wire take = run & ce;", "wire take = run;",
     "seq: pixels counted while the pipeline is stalled"),
    ("spec_stream_seq", "spec_stream_seq.v", "wire accept = s_axis_tvalid & ready_q;", "wire accept = s_axis_tvalid;",
     "seq: a descriptor taken while tready is low"),
    ("spec_stream_seq", "spec_stream_out.v", "(in_valid & m_axis_tvalid & ~m_axis_tready);", "1'b0;",
     "seq: the skid buffer drops a pixel on a stall"),
    # pow mode (issue 30): the same control under pow mode's longer datapath
    ("spec_unit_pow", "spec_unit.v", "assign busy_o = sig28 | fresh8 | dp_busy;", "assign busy_o = sig28 | fresh8;",
     "pow: busy_o falls before the last pixel is out"),
    ("spec_unit_pow", "spec_datapath.v", "else if (ce) vs_q <= {vs_q[LAT-1:1], in_valid};",
     "else if (ce) vs_q <= {vs_q[LAT-2:1], in_valid, in_valid};", "pow: the valid pipeline one stage short"),
    ("spec_stream_pow", "spec_stream_out.v", "(in_valid & m_axis_tvalid & ~m_axis_tready);", "1'b0;",
     "pow: the skid buffer drops a pixel on a stall"),
    ("spec_stream_seq_pow", "spec_stream_seq.v", "ready_q <= ~accept & ~run & ~dp_busy;", "ready_q <= ~accept & ~run;",
     "pow seq: a descriptor taken while the datapath holds the span before"),
    ("setup_engine", "spec_setup_engine.v", "                        s_tready <= 1'b0;\n                        run_fields",
     "                        run_fields", "engine: s_tready stays 1 after a span is taken"),
    ("setup_engine", "spec_setup_engine.v", "            st <= ST_IDLE;\n            s_tready <= 1'b0;",
     "            st <= ST_IDLE;", "engine: s_tready not reset"),
    ("setup_engine", "spec_setup_engine.v", "if (be_done) st <= ST_IDLE;", "st <= ST_IDLE;",
     "engine: idle before the back end is done"),
    ("setup_engine", "spec_setup_backend.v", "if (m_tvalid && m_tready) done <= 1'b1;", "if (m_tvalid) done <= 1'b1;",
     "back end: done before the handover"),
    ("setup_engine", "spec_setup_backend.v", "if (m_tvalid && m_tready) m_tvalid <= 1'b0;",
     "if (m_tvalid) m_tvalid <= 1'b0;", "back end: m_tvalid dropped without m_tready"),
    ("setup_engine", "spec_setup_backend.v", "if (div_done && out_rdy && !m_tvalid && !done) m_tvalid <= 1'b1;",
     "if (out_rdy && !m_tvalid && !done) m_tvalid <= 1'b1;", "back end: offered before dzeta is divided"),
    ("setup_engine", "spec_setup_backend.v", "wire norm_more = !lgx[F+1] && lge_nz;", "wire norm_more = !lgx[F+1];",
     "back end: log2 of 0 normalizes forever (deadlock)"),
    ("setup_engine", "spec_setup_backend.v", "wire wrap = a_out;", "wire wrap = a_out & stp;",
     "back end: an equivalent change (must pass)"),
]


def run(cmd, log, cwd, timeout=None):
    with open(log, "w") as f:
        try:
            p = subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT, timeout=timeout)
        except subprocess.TimeoutExpired:
            f.write("\nformal.py: stopped after %.0f s (--step-timeout)\n" % timeout)
            return 124
    return p.returncode


def tail(path, n=15):
    with open(path) as f:
        lines = f.read().splitlines()
    return "\n".join(lines[-n:])


def inc_dirs(job):
    """The header directories a job reads, first first: its ROM directory, after it <rom>_fv (FV_SCHED) for `sched`."""
    rdir = job.get("rom", "rom")
    return ([rdir + "_fv"] if job.get("sched") else []) + [rdir]


def build_model(job, name, work, yosys, rtl_dir):
    rtl = core_files(rtl_dir)
    inc = " ".join("-I " + d for d in inc_dirs(job))
    if job.get("shader"):
        rtl += shader_files(rtl_dir, job.get("exclude", ())) + [os.path.join(ROOT, f) for f in job.get("extra", [])]
    script = [
        "read_verilog -defer %s " % inc + " ".join(rtl),
    ] + ["chparam -set %s %d %s" % (k, v, job["core"]) for k, v in job.get("chparam", {}).items()] + [
        "hierarchy -top " + job["core"] + "".join(" -chparam %s %d" % kv for kv in job.get("params", {}).items()),
        "proc",
        "flatten",
    ] + (["memory_nordff", "memory_map"] if job.get("map_memories") else []) + (
        ["expose " + " ".join("w:" + w for w in job["expose"])] if job["expose"] else []) + (
        ["expose -cut " + " ".join("w:" + w for w in job["cut"])] if job.get("cut") else []) + [
        "rename %s fv_core_%s" % (job["core"], job["core"].split("_", 1)[1]),
        "read_verilog -formal %s " % inc + "".join(" -D" + d for d in job.get("defines", [])) + " " +
        os.path.join(ROOT, "formal", job["wrapper"] + ".v"),
        "hierarchy -check -top " + job["wrapper"] +
        "".join(" -chparam %s %d" % kv for kv in job.get("params", {}).items()),
        "proc",
        "flatten",
        "opt_clean",
        "memory_nordff",
        "memory_map",
        "opt -fast",
        "async2sync",
        "opt_clean",
        "dffunmap",
        "stat",
        "write_smt2 -wires %s.smt2" % name,
    ]
    with open(os.path.join(work, name + ".ys"), "w") as f:
        f.write("\n".join(script) + "\n")
    return run([yosys, "-q", "-l", name + "_yosys.log", "-s", name + ".ys"], os.path.join(work, name + "_yosys.out"), work)


def induction_cmd(a, job, vcd, smt):
    """The k-induction step of a job (k = its depth): yosys-smtbmc -i, or formal/induct.py for a `split` job."""
    if job.get("split"):
        cmd = [sys.executable, os.path.join(ROOT, "formal", "induct.py"), "-s", a.solver, "--unroll"]
    else:
        cmd = [a.smtbmc, "-s", a.solver, "--presat", "--unroll", "--noprogress", "-i"]
    return cmd + ["-t", str(job["depth"]), "--dump-vcd", vcd, smt]


def write_data(path, obj):
    if path:
        obj = dict(obj, date=time.strftime("%Y-%m-%d"), solver=a_solver_version())
        with open(path, "w") as f:
            json.dump(obj, f, indent=1)
            f.write("\n")


def a_solver_version():
    try:
        return subprocess.run(["z3", "--version"], stdout=subprocess.PIPE, universal_newlines=True).stdout.strip()
    except OSError:
        return None


def rom_dirs(jobs):
    """The generated ROM and header directories the jobs read (a job's `rom`, default rom/ at WIDTHS)."""
    return sorted(set(JOBS[j].get("rom", "rom") for j in jobs))


def make_roms(a, work, jobs):
    """specrom (and setuprom for the setup and shader jobs) into each directory the jobs read."""
    for rdir in rom_dirs(jobs):
        js = [JOBS[j] for j in jobs if JOBS[j].get("rom", "rom") == rdir]
        os.makedirs(os.path.join(work, rdir), exist_ok=True)
        log = os.path.join(work, "specrom_%s.log" % rdir)
        if run([a.specrom, "--out", rdir] + js[0].get("widths", WIDTHS), log, work) != 0:
            print("formal: specrom failed:\n" + tail(log), file=sys.stderr)
            return 1
        if any(j.get("shader") for j in js):
            # both setups' headers (Yosys reads every file of rtl/spec_shader.f): the multiplier setup's as
            # setuprom makes it, the small setup's at the job's reduced format (small_widths)
            small = next((j["small_widths"] for j in js if "small_widths" in j), [])
            for config, args in (("ecp5", []), ("up5k", small)):
                log = os.path.join(work, "setuprom_%s_%s.log" % (rdir, config))
                if run([os.path.abspath(a.setuprom), "--out", rdir, "--config", config] + args, log, work) != 0:
                    print("formal: setuprom failed:\n" + tail(log), file=sys.stderr)
                    return 1
            if rdir != "rom":
                # setuprom names its tables rom/...: this directory's instead
                for vh in ("setup_params.vh", "setup_small_params.vh"):
                    path = os.path.join(work, rdir, vh)
                    text = open(path).read()
                    open(path, "w").write(text.replace('"rom/', '"%s/' % rdir))
        if any(j.get("sched") for j in js):
            # FV_SCHED: the generated header with the small schedule, in a directory read before rdir
            text = open(os.path.join(work, rdir, "setup_params.vh")).read()
            for macro, value in FV_SCHED.items():
                text, n = re.subn(r"^`define %s \S+" % macro, "`define %s %d" % (macro, value), text, flags=re.M)
                if n != 1:
                    print("formal: setup_params.vh has no `define %s (FV_SCHED): update formal.py" % macro,
                          file=sys.stderr)
                    return 1
            os.makedirs(os.path.join(work, rdir + "_fv"), exist_ok=True)
            with open(os.path.join(work, rdir + "_fv", "setup_params.vh"), "w") as f:
                f.write("// formal.py (FV_SCHED): setuprom's header with the formal jobs' small schedule\n" + text)
    return 0


def run_mutants(a, work):
    bad = 0
    results = []
    for i, (name, fname, old, new, what) in enumerate(MUTANTS):
        if name not in a.jobs.split(","):
            continue
        mdir = os.path.join(work, "mutant%d" % i)
        shutil.rmtree(mdir, ignore_errors=True)
        shutil.copytree(os.path.join(ROOT, "rtl"), os.path.join(mdir, "rtl"))
        for rdir in inc_dirs(JOBS[name]):
            os.symlink(os.path.join(work, rdir), os.path.join(mdir, rdir))
        path = os.path.join(mdir, "rtl", fname)
        text = open(path).read()
        if text.count(old) != 1:
            print("mutant %d (%s): '%s' not found once in rtl/%s - update formal.py" % (i, what, old, fname))
            bad += 1
            continue
        open(path, "w").write(text.replace(old, new))
        job = JOBS[name]
        if job.get("lean_defines"):
            job = dict(job, defines=job.get("defines", []) + job["lean_defines"])
        if build_model(job, name, mdir, a.yosys, os.path.join(mdir, "rtl")) != 0:
            print("mutant %d: Yosys failed" % i)
            bad += 1
            continue
        base = [a.smtbmc, "-s", a.solver, "--presat", "--unroll", "--noprogress"]
        for mstep in MUTANT_STEPS.get(name, ["bmc"]):
            log = os.path.join(mdir, "%s_%s.log" % (name, mstep))
            if mstep == "bmc":
                cmd = base + ["-t", str(MUTANT_BMC[name]), "--dump-vcd", "cex_bmc.vcd", name + ".smt2"]
            else:
                # the induction step as the proof runs it: on the model with the helper invariants
                smt = name + ".smt2"
                if job is not JOBS[name]:
                    smt = name + "_full.smt2"
                    if build_model(JOBS[name], name + "_full", mdir, a.yosys, os.path.join(mdir, "rtl")) != 0:
                        print("mutant %d: Yosys failed (the model with the helper invariants)" % i)
                        rc = None
                        break
                cmd = induction_cmd(a, JOBS[name], "cex_induction.vcd", smt)
            rc = run(cmd, log, mdir, a.step_timeout)
            text = open(log).read()
            caught = rc != 0 and "FAILED" in text
            if caught:
                break
        if rc is None:
            bad += 1
            continue
        expect = "must pass" not in what
        m = re.search(r"Assert failed in \S+: (\S+)", text)
        where = (" (%s)" % os.path.basename(m.group(1))) if m else ""
        ok = caught == expect
        print("mutant %d %-58s %s%s" % (i, what, ("caught" if caught else "not caught") + ("" if ok else "  <- WRONG"),
                                          (where + ("" if mstep == "bmc" else " by the induction step"))
                                          if caught else ""), flush=True)
        results.append({"job": name, "file": fname, "bug": what, "caught": caught, "expected": expect,
                        "assertion": where.strip(" ()") if caught else None,
                        "step": mstep if caught else None})
        if not ok:
            bad += 1
    print("formal: %s" % ("every mutant caught as expected" if bad == 0 else "%d mutant(s) wrong" % bad))
    if bad == 0:
        # the jobs run now replace their rows; the other jobs' rows (an earlier run's) stay
        jobs = a.jobs.split(",")
        old = {}
        if a.data and os.path.exists(a.data):
            try:
                old = json.load(open(a.data))
            except ValueError:
                old = {}
        # (rows of a job or a mutant no longer in JOBS or MUTANTS go: they describe RTL that is gone)
        known = set((m[0], m[4]) for m in MUTANTS)
        keep = [r for r in old.get("mutants", []) if r["job"] not in jobs and (r["job"], r["bug"]) in known]
        order = {k: i for i, k in enumerate(JOBS)}
        results = sorted(keep + results, key=lambda r: order.get(r["job"], len(order)))
        write_data(a.data, {"mutants": results, "bmc_cycles": MUTANT_BMC, "steps": MUTANT_STEPS})
    return 0 if bad == 0 else 1


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--specrom", default=os.path.join(ROOT, "build", "specrom"))
    ap.add_argument("--setuprom", default=os.path.join(ROOT, "build", "setuprom"),
                    help="spec_setup's generator (its header, for the spec_setup and spec_shader jobs)")
    ap.add_argument("--work", default=os.path.join(ROOT, "build", "formal"))
    ap.add_argument("--jobs", default=",".join(JOBS))
    ap.add_argument("--yosys", default="yosys")
    ap.add_argument("--smtbmc", default="yosys-smtbmc")
    ap.add_argument("--solver", default="z3")
    ap.add_argument("--rtl", default=os.path.join(ROOT, "rtl"), help="RTL directory (a mutant's, to see a proof fail)")
    ap.add_argument("--steps", default="bmc,induction,cover")
    ap.add_argument("--step-timeout", type=float, help="stop a step (a failure) after this many seconds")
    ap.add_argument("--mutants", action="store_true", help="check that the properties fail on broken RTL")
    ap.add_argument("--data", help="write the results as JSON (docs/data/formal.json, formal_mutants.json)")
    a = ap.parse_args()
    a.specrom = os.path.abspath(a.specrom)

    for tool in (a.yosys, a.smtbmc, a.solver):
        if shutil.which(tool) is None:
            print("formal: '%s' not found (make deps-formal installs yosys and z3)" % tool, file=sys.stderr)
            return 2
    if not os.access(a.specrom, os.X_OK):
        print("formal: no generator at %s (build it first)" % a.specrom, file=sys.stderr)
        return 2
    jobs = [j for j in a.jobs.split(",") if j]
    for j in jobs:
        if j not in JOBS:
            print("formal: unknown job '%s' (jobs: %s)" % (j, ", ".join(JOBS)), file=sys.stderr)
            return 2

    work = os.path.abspath(a.work)
    if make_roms(a, work, jobs) != 0:
        return 1

    if a.mutants:
        return run_mutants(a, work)

    failed = 0
    rows = []
    for name in jobs:
        job = JOBS[name]
        t0 = time.time()
        if build_model(job, name, work, a.yosys, os.path.abspath(a.rtl)) != 0:
            print("formal: %s: Yosys failed:\n%s" % (name, tail(os.path.join(work, name + "_yosys.out"))))
            failed += 1
            continue
        smt = name + ".smt2"
        # --unroll: z3 4.8 takes minutes to read the model's nested function definitions otherwise
        base = [a.smtbmc, "-s", a.solver, "--presat", "--unroll", "--noprogress"]
        steps = [
            ("bmc", "base case, %d cycles" % job["bmc"],
             base + ["-t", str(job["bmc"]), "--dump-vcd", name + "_bmc.vcd", smt]),
            ("induction", "induction, k = %s" % job["depth"] + (", per assertion" if job.get("split") else ""),
             induction_cmd(a, job, name + "_induction.vcd", smt)),
            ("cover", "covers within %d cycles" % job["cover"],
             base + ["-c", "-t", str(job["cover"]), "--dump-vcd", name + "_cover%.vcd",
                     (name + "_cover.smt2") if job.get("lean_defines") else smt]),
        ]
        if job.get("lean_defines") and "cover" in a.steps.split(","):
            cjob = dict(job, defines=job.get("defines", []) + job["lean_defines"])
            if build_model(cjob, name + "_cover", work, a.yosys, os.path.abspath(a.rtl)) != 0:
                print("formal: %s: Yosys failed (cover model):\n%s" % (
                    name, tail(os.path.join(work, name + "_cover_yosys.out"))))
                failed += 1
                continue
        for step, what, cmd in steps:
            if step not in a.steps.split(",") or step not in job.get("steps", [step]) or (
                    step == "induction" and job["depth"] is None):
                continue
            log = os.path.join(work, "%s_%s.log" % (name, step))
            t1 = time.time()
            rc = run(cmd, log, work, a.step_timeout)
            dt = time.time() - t1
            text = open(log).read()
            ok = rc == 0 and "PASSED" in text
            extra = ""
            if step == "cover":
                n = len(re.findall(r"Reached cover statement", text))
                extra = " (%d reached)" % n
            rows.append({"job": name, "step": step, "what": what, "pass": ok, "seconds": round(dt, 1),
                         "covers": (n if step == "cover" else None)})
            print("%-12s %-40s %-5s %6.1f s" % (name, what + extra, "pass" if ok else "FAIL", dt), flush=True)
            if not ok:
                failed += 1
                print("  log: %s\n%s" % (log, tail(log, 12)))
        del t0
    print("formal: %s" % ("all proofs and covers passed" if failed == 0 else "%d step(s) failed" % failed))
    if failed == 0:
        # the jobs run now replace their rows; the other jobs' rows (an earlier run's, with its date) stay
        today = time.strftime("%Y-%m-%d")
        for r in rows:
            r["date"] = today
        old = {}
        if a.data and os.path.exists(a.data):
            try:
                old = json.load(open(a.data))
            except ValueError:
                old = {}
        # (rows of a job no longer in JOBS go: they describe a proof that is gone)
        keep = [dict(r, date=r.get("date", old.get("date"))) for r in old.get("steps", [])
                if r["job"] not in jobs and r["job"] in JOBS]
        order = {k: i for i, k in enumerate(JOBS)}
        steps = sorted(keep + rows, key=lambda r: order.get(r["job"], len(order)))
        job_info = {k: v for k, v in old.get("jobs", {}).items() if k not in jobs and k in JOBS}
        job_info.update({k: {"bmc": JOBS[k]["bmc"], "depth": JOBS[k]["depth"], "cover": JOBS[k]["cover"]} for k in jobs})
        write_data(a.data, {"steps": steps, "widths": WIDTHS, "jobs": job_info})
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
