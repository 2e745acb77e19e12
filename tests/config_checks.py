#!/usr/bin/env python3
"""config_checks.py - a misconfiguration stops every tool with a message (issue 12, item 2).

usage: config_checks.py CASE --src DIR --work DIR --specrom BIN --romsim BIN
                        [--iverilog iverilog] [--vvp vvp] [--verilator verilator] [--yosys yosys]

One ctest per CASE. Each case makes the misconfiguration and runs every tool that meets it, checking a non-zero
exit and a message that names what is wrong:
  rom_params    spec_unit and spec_stream with the up5k parameters but the default images (Icarus), the up5k
                images under the default parameters (the Verilated ROM model), and the synthesis-flow check
  rom_short     an image with one word too few            rom_long      one word too many
  rom_wide      a word with more digits than the ROM's width
  rom_noheader  an image without specrom's first line     rom_missing   no image at the path
  param_rules   OUT_W != C_W, odd ANG_W, N_W < 4, TSEL_W != 2 with decoder 10's gates: Icarus, Verilator, Yosys
  desc_fields   spec_stream's descriptor fields overlapping or outside DESC_W: Icarus, Verilator, Yosys
  two_headers   two spec_params.vh of different configurations in one compilation: Icarus, Verilator, Yosys
  pow_mode      pow mode's images in a patent-mode core and the other way round (Icarus, the Verilated ROM model,
                the synthesis-flow check), pow images of the other configuration, POW with decoder 10 as a ROM
  good          the right configuration runs in every tool (the checks do not fire on correct input)
Exit 0 when every expectation held; 1 with the first one that did not.
"""
import argparse
import os
import shutil
import subprocess
import sys

UP5K = {"TBL_AW": 8, "INTERP": 1, "INTERP_FRAC": 10, "DELTA_W": 10, "SCALE_W": 16, "SCALE_FRAC": 13}


class Check:
    def __init__(self, a):
        self.a = a
        self.core = [os.path.join(a.src, "rtl", l.strip()) for l in open(os.path.join(a.src, "rtl", "spec_core.f"))
                     if l.strip()]
        self.count = 0

    def run(self, cmd, cwd=None):
        p = subprocess.run(cmd, cwd=cwd or self.a.work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           universal_newlines=True)
        return p.returncode, p.stdout

    def expect_fail(self, what, cmd, needles, cwd=None):
        rc, out = self.run(cmd, cwd)
        if rc == 0:
            sys.exit("config_checks: %s: exit 0, expected a failure\n%s" % (what, out[-2000:]))
        for n in needles:
            if n not in out:
                sys.exit("config_checks: %s: the message does not say %r\n%s" % (what, n, out[-2000:]))
        self.count += 1
        print("ok: %s stops: %s" % (what, next((l for l in out.splitlines() if needles[0] in l), needles[0])))

    def expect_pass(self, what, cmd, needle=None, cwd=None):
        rc, out = self.run(cmd, cwd)
        if rc != 0 or (needle and needle not in out):
            sys.exit("config_checks: %s: expected it to run (exit %d)\n%s" % (what, rc, out[-2000:]))
        self.count += 1
        print("ok: %s runs" % what)

    # ---- the tools -------------------------------------------------------------------------------------------
    def icarus(self, params, inc=None, extra=()):
        """iverilog + vvp of tests/iverilog/tb_elab.v with -P parameters; the command as one shell line."""
        vvp = os.path.join(self.a.work, "tb_elab.vvp")
        ps = []
        for k, v in params.items():
            ps.append("-Ptb_elab.%s=%s" % (k, ('"%s"' % v) if isinstance(v, str) else v))
        comp = [self.a.iverilog, "-g2005", "-Wall", "-I" + (inc or os.path.join(self.a.src, "rom")), "-o", vvp,
                "-s", "tb_elab"] + ps + list(extra) + [os.path.join(self.a.src, "tests", "iverilog", "tb_elab.v")]
        comp += self.core
        return ["sh", "-c", " ".join("'%s'" % c for c in comp) + " && " + "'%s' -n '%s'" % (self.a.vvp, vvp)]

    def verilator(self, params, top="spec_stream", extra=()):
        return [self.a.verilator, "--lint-only", "-Wall", "-I" + os.path.join(self.a.src, "rom"), "--top-module",
                top] + ["-G%s=%s" % kv for kv in params.items()] + list(extra) + self.core

    def yosys(self, params, top="spec_stream"):
        r9, r12 = self.default_images()
        params = dict({"ROM9_FILE": '"%s"' % r9, "ROM12_FILE": '"%s"' % r12}, **params)
        chp = " ".join("-set %s %s" % kv for kv in params.items())
        script = "read_verilog -defer -I%s %s; %s hierarchy -check -top %s" % (
            os.path.join(self.a.src, "rom"), " ".join(self.core), ("chparam %s %s;" % (chp, top)) if chp else "", top)
        return [self.a.yosys, "-q", "-p", script]

    def rom_check(self, rom9, rom12, params=None):
        return [sys.executable, os.path.join(self.a.src, "syn", "rom_check.py"), "--header",
                os.path.join(self.a.src, "rom", "spec_params.vh"), "--rom9", rom9, "--rom12", rom12] + \
               ["-G%s=%s" % kv for kv in (params or {}).items()]

    # ---- images ----------------------------------------------------------------------------------------------
    def default_images(self):
        return os.path.join(self.a.src, "rom", "rom9_scale.hex"), os.path.join(self.a.src, "rom", "rom12_cosk.hex")

    def up5k_images(self):
        d = os.path.join(self.a.work, "rom_up5k")
        os.makedirs(d, exist_ok=True)
        rc, out = self.run([self.a.specrom, "--config", "up5k", "--out", d])
        if rc != 0:
            sys.exit("config_checks: specrom --config up5k failed\n" + out)
        return os.path.join(d, "rom9_scale.hex"), os.path.join(d, "rom12_cosk.hex")

    def romsim_with(self, rom9_text, rom12_text):
        """Puts the two images where the Verilated tb_rom_check reads them and runs it."""
        d = os.path.join(self.a.romsim_dir)
        os.makedirs(d, exist_ok=True)
        for name, text in (("rom9.hex", rom9_text), ("rom12.hex", rom12_text)):
            path = os.path.join(d, name)
            if os.path.exists(path):
                os.remove(path)
            if text is not None:
                with open(path, "w") as f:
                    f.write(text)
        return [self.a.romsim]

    def broken(self, name, text):
        path = os.path.join(self.a.work, name)
        with open(path, "w") as f:
            f.write(text)
        return path


def read(path):
    with open(path) as f:
        return f.read()


def case_rom(c, kind):
    """The default images broken one way: Icarus (full cores, the path as ROM9_FILE/ROM12_FILE), the Verilated ROM
    model and the synthesis-flow check must all stop and name the file."""
    r9, r12 = c.default_images()
    t9, t12 = read(r9), read(r12)
    lines = t12.splitlines(True)
    if kind == "short":
        bad12, needle = "".join(lines[:-1]), "holds 16383 words"
    elif kind == "long":
        bad12, needle = t12 + lines[-1], "holds 16385 words"
    elif kind == "wide":
        bad12, needle = "".join(lines[:5]) + "1" + lines[5] + "".join(lines[6:]), "hex digits"
    elif kind == "noheader":
        bad12, needle = "".join(lines[1:]), "does not start with specrom's"
    elif kind == "missing":
        bad12, needle = None, "cannot"
    else:
        raise ValueError(kind)
    path = os.path.join(c.a.work, "rom12_%s.hex" % kind)
    if bad12 is None:
        if os.path.exists(path):
            os.remove(path)
    else:
        c.broken("rom12_%s.hex" % kind, bad12)
    c.expect_fail("Icarus, ROM 12 %s" % kind, c.icarus({"ROM9_FILE": r9, "ROM12_FILE": path}), [path, needle])
    c.expect_fail("Verilator, ROM 12 %s" % kind, c.romsim_with(t9, bad12), ["rom12.hex", needle])
    # the synthesis flows' check (Yosys skips the RTL's)
    syn_needle = {"short": "holds 16383 words", "long": "holds 16385 words", "wide": "wider than",
                  "noheader": "does not start with specrom's", "missing": "cannot read"}[kind]
    c.expect_fail("synthesis check, ROM 12 %s" % kind, c.rom_check(r9, path), [path, syn_needle])
    if kind == "missing":
        # a relative default path from another working directory: the message says what to do
        c.expect_fail("Icarus, default relative paths outside the repository", c.icarus({}),
                      ["rom/rom9_scale.hex", "pass the ROM path parameters"])


def case_rom_params(c):
    r9, r12 = c.default_images()
    u9, u12 = c.up5k_images()
    # the case: the up5k parameters with the default images
    params = dict(UP5K, ROM9_FILE=r9, ROM12_FILE=r12)
    c.expect_fail("Icarus, up5k parameters with the default images", c.icarus(params),
                  [r9, "was made for other parameters", "SCALE_W=18", "SCALE_W=16"])
    # the default parameters with the up5k images, in the Verilated model
    c.expect_fail("Verilator, default parameters with the up5k images", c.romsim_with(read(u9), read(u12)),
                  ["was made for other parameters", "SCALE_W=16", "SCALE_W=18"])
    c.expect_fail("synthesis check, up5k parameters with the default images", c.rom_check(r9, r12, UP5K),
                  [r9, "SCALE_W=18, the core has SCALE_W=16"])
    c.expect_fail("synthesis check, default parameters with the up5k images", c.rom_check(u9, u12),
                  [u9, "SCALE_W=16, the core has SCALE_W=18"])
    # tuned images (ROM 9 carries the table) under the patent's gates
    t = os.path.join(c.a.work, "rom_tuned")
    os.makedirs(t, exist_ok=True)
    rc, out = c.run([c.a.specrom, "--mode", "tuned", "--out", t])
    if rc != 0:
        sys.exit("config_checks: specrom --mode tuned failed\n" + out)
    c.expect_fail("Icarus, tuned images without DECODER_ROM",
                  c.icarus({"ROM9_FILE": os.path.join(t, "rom9_scale.hex"), "ROM12_FILE": r12}),
                  ["was made for other parameters", "DECODER_ROM=1"])


def case_param_rules(c):
    for params, name in (({"OUT_W": 15}, "spec_parameter_error_OUT_W_must_equal_C_W"),
                         ({"ANG_W": 31, "ANG_FRAC": 27}, "spec_parameter_error_ANG_W_must_be_even"),
                         ({"N_W": 3}, "spec_parameter_error_N_W_must_be_at_least_4"),
                         ({"TSEL_W": 3}, "spec_parameter_error_TSEL_W_must_be_2_when_decoder_10_gates_choose")):
        label = ", ".join("%s=%s" % kv for kv in params.items())
        c.expect_fail("Icarus, %s" % label, c.icarus(params), [name])
        for top in ("spec_unit", "spec_stream"):
            c.expect_fail("Verilator, %s %s" % (top, label), c.verilator(params, top), [name])
        c.expect_fail("Yosys, %s" % label, c.yosys(params, "spec_unit"), [name])


def case_desc_fields(c):
    for params, name in (({"DESC_N_LSB": 8}, "spec_parameter_error_descriptor_fields_overlap"),
                         ({"DESC_ZETA0_LSB": 80}, "spec_parameter_error_descriptor_fields_overlap"),
                         ({"DESC_DZETA_LSB": 100}, "spec_parameter_error_a_descriptor_field_lies_outside_DESC_W"),
                         ({"DESC_W": 96}, "spec_parameter_error_a_descriptor_field_lies_outside_DESC_W")):
        label = ", ".join("%s=%s" % kv for kv in params.items())
        c.expect_fail("Icarus, %s" % label, c.icarus(params), [name])
        c.expect_fail("Verilator, %s" % label, c.verilator(params), [name])
        c.expect_fail("Yosys, %s" % label, c.yosys(params), [name])
    # a layout of one's own that fits is accepted
    ok = {"DESC_W": 160, "DESC_ZETA0_LSB": 96, "DESC_DZETA_LSB": 128}
    c.expect_pass("Verilator, another descriptor layout that fits", c.verilator(ok))
    c.expect_pass("Yosys, another descriptor layout that fits", c.yosys(ok))


def case_two_headers(c):
    a = os.path.join(c.a.work, "cfg_default")
    b = os.path.join(c.a.work, "cfg_up5k")
    for d, args in ((a, []), (b, ["--config", "up5k"])):
        os.makedirs(d, exist_ok=True)
        rc, out = c.run([c.a.specrom, "--out", d] + args)
        if rc != 0:
            sys.exit("config_checks: specrom failed\n" + out)
    top = c.broken("two_headers.v", '`include "%s/spec_params.vh"\n`include "%s/spec_params.vh"\n'
                   "module two_headers;\nendmodule\n" % (a, b))
    same = c.broken("same_header.v", '`include "%s/spec_params.vh"\n`include "%s/spec_params.vh"\n'
                    "module same_header;\nendmodule\n" % (a, a))
    needle = "two_spec_params_vh_of_different_configurations_in_one_compilation"
    c.expect_fail("Icarus, two configurations' headers", [c.a.iverilog, "-g2005", "-o", os.devnull, top], [needle])
    c.expect_fail("Verilator, two configurations' headers", [c.a.verilator, "--lint-only", top], [needle])
    c.expect_fail("Yosys, two configurations' headers", [c.a.yosys, "-q", "-p", "read_verilog " + top], [needle])
    c.expect_pass("Icarus, the same header twice", [c.a.iverilog, "-g2005", "-o", os.devnull, same])
    c.expect_pass("Verilator, the same header twice", [c.a.verilator, "--lint-only", same])


def pow_images(c, config=None):
    d = os.path.join(c.a.work, "rom_pow" + ("_" + config if config else ""))
    os.makedirs(d, exist_ok=True)
    rc, out = c.run([c.a.specrom, "--mode", "pow", "--out", d] + (["--config", config] if config else []))
    if rc != 0:
        sys.exit("config_checks: specrom --mode pow failed\n" + out)
    return os.path.join(d, "rom9_scale.hex"), os.path.join(d, "rom12_cosk.hex")


def case_pow_mode(c):
    r9, r12 = c.default_images()
    p9, p12 = pow_images(c)
    u9, u12 = pow_images(c, "up5k")
    # pow images in a core with POW = 0 (the defaults of rom/spec_params.vh)
    c.expect_fail("Icarus, pow images in a patent-mode core", c.icarus({"ROM9_FILE": p9, "ROM12_FILE": p12}),
                  [p9, "was made for pow mode", "POW = 0"])
    c.expect_fail("Verilator, pow images in a patent-mode ROM 9 and ROM 12", c.romsim_with(read(p9), read(p12)),
                  ["rom9.hex", "was made for pow mode"])
    c.expect_fail("synthesis check, pow images with POW = 0", c.rom_check(p9, p12), [p9, "was made for pow mode"])
    # patent images in a core with POW = 1
    c.expect_fail("Icarus, patent images in a pow-mode core", c.icarus({"POW": 1, "ROM9_FILE": r9, "ROM12_FILE": r12}),
                  [r9, "was made for patent or tuned mode", "POW = 1"])
    c.expect_fail("synthesis check, patent images with POW = 1", c.rom_check(r9, r12, {"POW": 1}),
                  [r9, "was made for patent or tuned mode"])
    # the up5k configuration's pow images under the default pow parameters (another log table and exp2 table)
    c.expect_fail("Icarus, up5k pow images under the default pow parameters",
                  c.icarus({"POW": 1, "ROM9_FILE": u9, "ROM12_FILE": u12}),
                  [u9, "was made for other parameters", "POW_IDX_W=5", "POW_IDX_W=6"])
    c.expect_fail("synthesis check, up5k pow images under the default pow parameters",
                  c.rom_check(u9, u12, {"POW": 1}), [u9, "POW_IDX_W=5, the core has POW_IDX_W=6"])
    # pow mode has no table field
    name = "spec_parameter_error_POW_1_takes_no_table_field_DECODER_ROM_must_be_0"
    c.expect_fail("Icarus, POW = 1 with DECODER_ROM = 1", c.icarus({"POW": 1, "DECODER_ROM": 1}), [name])
    c.expect_fail("Verilator, POW = 1 with DECODER_ROM = 1", c.verilator({"POW": 1, "DECODER_ROM": 1}), [name])
    c.expect_fail("Yosys, POW = 1 with DECODER_ROM = 1", c.yosys({"POW": 1, "DECODER_ROM": 1}, "spec_unit"), [name])
    # and the right ones run
    c.expect_pass("Icarus, pow parameters and images", c.icarus({"POW": 1, "ROM9_FILE": p9, "ROM12_FILE": p12}),
                  "tb_elab: ran")
    c.expect_pass("Icarus, up5k pow parameters and images",
                  c.icarus(dict(UP5K, POW=1, POW_IDX_W=5, ROM9_FILE=u9, ROM12_FILE=u12)), "tb_elab: ran")
    c.expect_pass("Icarus, a pow header on the include path", c.icarus({}, inc=os.path.dirname(p9)), "tb_elab: ran")
    c.expect_pass("synthesis check, pow", c.rom_check(p9, p12, {"POW": 1}))


def case_good(c):
    r9, r12 = c.default_images()
    u9, u12 = c.up5k_images()
    c.expect_pass("Icarus, default parameters and images by absolute path",
                  c.icarus({"ROM9_FILE": r9, "ROM12_FILE": r12}), "tb_elab: ran")
    c.expect_pass("Icarus, up5k parameters and images", c.icarus(dict(UP5K, ROM9_FILE=u9, ROM12_FILE=u12)),
                  "tb_elab: ran")
    # the include-directory way: a header made by specrom --out names its images by absolute path
    c.expect_pass("Icarus, up5k header on the include path, from another directory",
                  c.icarus(UP5K, inc=os.path.dirname(u9)), "tb_elab: ran")
    c.expect_pass("Verilator, the default images", c.romsim_with(read(r9), read(r12)), "accepted")
    c.expect_pass("synthesis check, default", c.rom_check(r9, r12))
    c.expect_pass("synthesis check, up5k", c.rom_check(u9, u12, UP5K))
    c.expect_pass("Yosys, the default parameters", c.yosys({}, "spec_unit"))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case")
    ap.add_argument("--src", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--specrom", required=True)
    ap.add_argument("--romsim", required=True, help="the Verilated tests/verilator/tb_rom_check")
    ap.add_argument("--romsim-dir", required=True, help="where tb_rom_check reads rom9.hex and rom12.hex")
    ap.add_argument("--iverilog", default="iverilog")
    ap.add_argument("--vvp", default="vvp")
    ap.add_argument("--verilator", default="verilator")
    ap.add_argument("--yosys", default="yosys")
    a = ap.parse_args()
    a.work = os.path.join(a.work, a.case)
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    c = Check(a)
    cases = {"rom_params": case_rom_params, "param_rules": case_param_rules, "desc_fields": case_desc_fields,
             "two_headers": case_two_headers, "good": case_good, "pow_mode": case_pow_mode}
    for k in ("short", "long", "wide", "noheader", "missing"):
        cases["rom_" + k] = (lambda kind: lambda c: case_rom(c, kind))(k)
    if a.case not in cases:
        sys.exit("config_checks: unknown case %s (%s)" % (a.case, ", ".join(sorted(cases))))
    cases[a.case](c)
    print("config_checks %s: %d expectations held" % (a.case, c.count))


if __name__ == "__main__":
    main()
