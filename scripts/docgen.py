#!/usr/bin/env python3
"""docgen.py - the numbers in README.md and docs/*.md come from commands, and a ctest keeps them current.

usage: docgen.py --build BUILD (--update | --check) [FILE.md ...]       (default: README.md, docs/*.md)

Two kinds of marks in a markdown file (HTML comments: invisible where the markdown is rendered):

  <!--v:KEY-->TEXT<!--/v-->          an inline value: TEXT is the fact KEY, formatted (KEY|FMT: a %-format
                                      such as %.1f, or a format named in FORMATS)
  <!-- gen:NAME -->                  a block: every line up to the end mark is what BLOCKS[NAME] makes
  ...
  <!-- /gen:NAME -->

Facts come from the running code: the generated headers (cfg.*, cfg_up5k.*, cfg_tuned.*, cfg_up5k_tuned.*), the
bit-exact model's accuracy runs (accuracy.*, acc.<variant>.*), `specsim compare` (compare.*), Fig. 8 (q.N, a.N,
fig8k.*), renders through the Verilated core or the model (render.*, render_<variant>.*: RENDERS), Yosys's
synth_ice40 of the ROMs (ice40.*; Yosys is a required dependency), `specsim tables` (tables.*, docs/tables.md), a
GoogleTest's recorded properties (gtest.*), the bound-ratio rows of docs/verification.md that their tests compare
(vrow.*), small derived values (calc.*: CALC), and the measurements the optional targets write into
docs/data/*.json (data.<file>.*: `make synth`, `make bench`, `make bench-render`, `make coverage`, `make formal`
update those files; the check compares the documents with them, it does not rerun synthesis or benchmarks).

--update rewrites the marks in place (make docs); --check (the ctest docs_current) fails, listing every stale
mark, when a document differs from what the commands give now, or when a document holds a tool's error text
(a shell's "No such file or directory", a Python traceback, ...), or a mark names an unknown fact or block.
"""
import argparse
import glob
import json
import math
import os
import re
import subprocess
import sys
import tempfile

import docgen_shader

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

INLINE = re.compile(r"<!--v:([^>|]+?)(?:\|([^>]*?))?-->(.*?)<!--/v-->", re.S)
BLOCK = re.compile(r"(<!-- gen:([\w.-]+) -->\n)(.*?)(<!-- /gen:\2 -->)", re.S)
ERROR_TEXT = re.compile(r"No such file or directory|command not found|Traceback \(most recent call last\)|"
                        r"^bash: |Segmentation fault|core dumped|^%Error|CMake Error|^make: \*\*\*", re.M)


DocError = docgen_shader.DocError   # one exception type for both modules


class Facts:
    """Lazily computed facts; each provider runs once."""

    def __init__(self, build):
        self.build = build
        self.cache = {}
        self.specsim = os.path.join(build, "specsim")
        self.specrom = os.path.join(build, "specrom")

    def run(self, cmd):
        try:
            p = subprocess.run(cmd, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
        except OSError as e:
            raise DocError("%s: %s (make build first)" % (cmd[0], e.strerror))
        if p.returncode != 0:
            raise DocError("%s failed (exit %d): %s" % (" ".join(cmd), p.returncode, p.stderr.strip()[-300:]))
        return p.stdout

    def once(self, name, fn):
        if name not in self.cache:
            self.cache[name] = fn()
        return self.cache[name]

    # ---- providers --------------------------------------------------------------------------------------------
    def rom_dir(self, config):
        """The directory of a configuration's ROM images and headers: rom/ for the default, otherwise what
        specrom writes (config: tuned, up5k, up5k_tuned)."""
        def make():
            if config == "default":
                return os.path.join(ROOT, "rom")
            args = {"tuned": ["--mode", "tuned"], "up5k": ["--config", "up5k"],
                    "up5k_tuned": ["--config", "up5k", "--mode", "tuned"], "pow": ["--mode", "pow"],
                    "up5k_pow": ["--config", "up5k", "--mode", "pow"]}.get(config)
            if args is None:
                raise DocError("unknown configuration %s" % config)
            d = tempfile.mkdtemp(prefix="docgen_")
            self.run([self.specrom] + args + ["--out", d])
            return d
        return self.once("rom_dir." + config, make)

    def header(self, config):
        def make():
            vals = {}
            for m in re.finditer(r"constexpr int (\w+) = (-?\d+);",
                                 open(os.path.join(self.rom_dir(config), "spec_params.h")).read()):
                vals[m.group(1)] = int(m.group(2))
            return vals
        return self.once("header." + config, make)

    def ice40_brams(self, rom, config):
        """SB_RAM40_4K cells of Yosys's synth_ice40 of spec_rom9 / spec_rom12 with a configuration's image and
        parameters (Yosys is a required dependency of make test)."""
        def make():
            h = self.header(config)
            top = "spec_rom%s" % rom
            names = {"9": ("rom9_scale.hex", ["N_W", "SCALE_W", "SCALE_FRAC", "DECODER_ROM", "TSEL_W"]),
                     "12": ("rom12_cosk.hex", ["TBL_AW", "TSEL_W", "TBL_FRAC", "INTERP", "DELTA_W"])}
            if rom not in names:
                raise DocError("no ROM %s" % rom)
            image, params = names[rom]
            sets = " ".join("-set %s %d" % (p, h[p]) for p in params)
            if h["POW"]:   # pow mode's ROMs are spec_rom inside spec_powpath: its address and word widths
                top = "spec_rom"
                aw, dw = ((1 + h["POW_SEG_W"] + h["POW_IDX_W"], h["POW_SH_W"] + 1 + h["POW_DLT_W"] + h["POW_VAL_W"])
                          if rom == "9" else (h["TBL_AW"], h["TBL_DW"] + (h["DELTA_W"] if h["INTERP"] else 0)))
                sets = "-set AW %d -set DW %d" % (aw, dw)
            d = tempfile.mkdtemp(prefix="docgen_")
            stat = os.path.join(d, "stat.txt")
            files = "rtl/spec_rom.v" + ("" if top == "spec_rom" else " rtl/%s.v" % top)
            self.run(["yosys", "-q", "-p", 'read_verilog -defer %s; chparam -set INIT_FILE "%s" %s %s; '
                      'synth_ice40 -top %s; tee -q -o %s stat' % (files, os.path.join(self.rom_dir(config), image), sets,
                                                                 top, top, stat)])
            m = re.search(r"SB_RAM40_4K\s+(\d+)", open(stat).read())
            return int(m.group(1)) if m else 0
        return self.once("ice40.%s.%s" % (rom, config), make)

    def yosys_version(self):
        return self.once("yosys_version", lambda: re.search(r"Yosys ([\d.]+)", self.run(["yosys", "-V"])).group(1))

    def render(self, variant="render"):
        """A scene rendered with statistics (RENDERS[variant]: by default the default scene at 512 x 512 through
        the Verilated core): the statistics JSON, and from what the command prints the core's clock cycles
        ("cycles", rtl only) and --cull-specular's counts ("cull")."""
        def make():
            if variant not in RENDERS:
                raise DocError("unknown render %s" % variant)
            d = tempfile.mkdtemp(prefix="docgen_")
            stats = os.path.join(d, "stats.json")
            out = self.run([self.specsim, "render", "--quiet", "--out", os.path.join(d, "r.png"), "--stats", stats] +
                           RENDERS[variant])
            res = json.load(open(stats))
            m = re.search(r", (\d+) clock cycles", out)
            if m:
                res["cycles"] = int(m.group(1))
            m = re.search(r"cull-specular: (\d+) of (\d+) triangles, (\d+) of (\d+) spans, (\d+) of (\d+) core pixels", out)
            if m:
                v = [int(x) for x in m.groups()]
                res["cull"] = {"triangles": v[0], "of_triangles": v[1], "spans": v[2], "of_spans": v[3],
                               "pixels": v[4], "of_pixels": v[5]}
            return res
        return self.once("render." + variant, make)

    def compare(self):
        """`specsim compare`: its three tables (rel: worst relative error in the epicentre, abs: worst absolute / C,
        side: the choices side by side in fixed point, with the per-material table, ROM bits and a material
        change's cost), rows by label; and the text."""
        def make():
            out = self.run([self.specsim, "compare"])
            tables, cur = [], None
            for line in out.splitlines():
                if line.startswith("| BRDF range"):
                    cur = {}
                    tables.append(cur)
                elif line.startswith("| ") and cur is not None:
                    cells = [c.strip() for c in line.strip().strip("|").split("|")]
                    cur[slug(cells[0])] = cells
            if len(tables) != 3:
                raise DocError("specsim compare printed %d tables, not 3" % len(tables))
            return {"rel": tables[0], "abs": tables[1], "side": tables[2], "text": out}
        return self.once("compare", make)

    def tables_text(self):
        """What `specsim tables` writes as tables.md now (docs/tables.md is that text, block `tables`)."""
        def make():
            d = tempfile.mkdtemp(prefix="docgen_")
            self.run([self.specsim, "tables", "--out-dir", d])
            return open(os.path.join(d, "tables.md"), encoding="utf-8").read()
        return self.once("tables_text", make)

    def tables_md(self):
        """Rows of the table set table (`specsim tables`, docs/tables.md)."""
        def make():
            rows = []
            for line in self.tables_text().splitlines():
                cells = [c.strip() for c in line.strip().strip("|").split("|")]
                if len(cells) == 9 and cells[1] in ("patent", "tuned"):
                    rows.append(cells)
            return rows
        return self.once("tables_md", make)

    def accuracy(self, variant):
        """`specsim accuracy` (variant: default, up5k, tuned, up5k_tuned, tbl_aw_N): its rows by slug, the worst
        core relative error over all rows, and what fixed point adds at most."""
        def make():
            args = {"default": [], "up5k": ["--config", "up5k"], "tuned": ["--mode", "tuned"],
                    "up5k_tuned": ["--config", "up5k", "--mode", "tuned"], "pow": ["--mode", "pow"],
                    "up5k_pow": ["--config", "up5k", "--mode", "pow"]}.get(variant)
            if args is None and variant.startswith("tbl_aw_"):
                args = ["--tbl-aw", variant[7:]]
            if args is None:
                raise DocError("unknown accuracy run %s" % variant)
            out = self.run([self.specsim, "accuracy"] + args)
            rows = {}
            for line in out.splitlines():
                if line.startswith("| n = "):
                    cells = [c.strip() for c in line.strip().strip("|").split("|")]
                    rows[slug(cells[0])] = cells
            m = re.search(r"Fixed point adds at most ([\d.]+) %.*\(n = (\d+)\)", out)
            worst = max(rows.values(), key=lambda c: percent(c[3], "accuracy"))
            res = {"rows": rows, "added": float(m.group(1)) if m else None, "added_n": int(m.group(2)) if m else None,
                   "worst_core": worst[3], "text": out}
            # pow mode: every angle and every n (acc.<variant>.every, every_n, every_angle, every_rel, every_rel_n,
            # positions, goal, stretch)
            m = re.search(r"; (\d+) positions .*?worst \|2\^-y - cos\^n\| = ([\d.]+) % \(n = (\d+), angle ([\d.]+) rad\)"
                          r".*?worst relative error in the epicentre ([\d.]+) % \(n = (\d+)\)\s*Goal 0\.1 % of C \+ "
                          r"2\^-14: ([^(]+?) \(stretch goal 0\.025 % of C \+ 2\^-14: ([^)]+)\)", out, re.S)
            if m:
                res.update({"positions": int(m.group(1)), "every": float(m.group(2)), "every_n": int(m.group(3)),
                            "every_angle": float(m.group(4)), "every_rel": float(m.group(5)),
                            "every_rel_n": int(m.group(6)), "goal": m.group(7).strip(), "stretch": m.group(8).strip()})
            return res
        return self.once("accuracy." + variant, make)

    def fig8_mode(self, mode):
        """`specsim fig8 --mode MODE`'s text: per table k, the range of n whose relative error stays within 1 %."""
        return self.once("fig8_mode." + mode, lambda: self.run([self.specsim, "fig8", "--mode", mode]))

    def fig8_all(self):
        """q(n) and a(n) in %, every n, from `specsim fig8 --all` (double precision, the Fig. 10 rule)."""
        def make():
            q, a = {}, {}
            for m in re.finditer(r"^\s*(\d+)\s+(\d+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s*$",
                                 self.run([self.specsim, "fig8", "--all"]), re.M):
                q[int(m.group(1))] = float(m.group(3))
                a[int(m.group(1))] = float(m.group(4))
            if len(q) < 1000:
                raise DocError("specsim fig8 --all printed %d rows of q(n)" % len(q))
            return q, a
        return self.once("fig8_all", make)

    def gtest(self, test):
        """The properties a GoogleTest test records (RecordProperty), from a run of that test alone."""
        def make():
            d = tempfile.mkdtemp(prefix="docgen_")
            out = os.path.join(d, "t.json")
            self.run([os.path.join(self.build, "spec_tests"), "--gtest_filter=" + test, "--gtest_output=json:" + out])
            for suite in json.load(open(out))["testsuites"]:
                for t in suite["testsuite"]:
                    if "%s.%s" % (suite["name"], t["name"]) == test:
                        return t
            raise DocError("test %s did not run" % test)
        return self.once("gtest." + test, make)

    def data(self, name):
        def make():
            path = os.path.join(ROOT, "docs", "data", name + ".json")
            if not os.path.exists(path):
                raise DocError("docs/data/%s.json does not exist (its make target writes it)" % name)
            return json.load(open(path))
        return self.once("data." + name, make)

    # ---- facts by key -------------------------------------------------------------------------------------------
    def get(self, key):
        parts = key.split(".")
        head = parts[0]
        if head == "cfg":
            return self.header("default")[parts[1]]
        if head.startswith("cfg_"):
            return self.header(head[4:])[parts[1]]
        if head in docgen_shader.HEADS:   # spec_setup / spec_shader (issue 13): scripts/docgen_shader.py
            return docgen_shader.get(self, head, parts, key)
        if head.startswith("render"):   # render[_VARIANT].<path in the statistics JSON> (RENDERS)
            return walk(self.render(head), parts[1:], key)
        if head == "compare":   # compare.rel|abs.<row slug>.<column>[.n]: the number in that cell (or its n)
            return cell_value(self.compare()[parts[1]][parts[2]][int(parts[3])], parts[4:], key)
        if head == "tables":   # tables.<k slug>.<mode>.<ROM 12 slug>.<column>[.n]: a cell of specsim tables' table
            rows = [r for r in self.tables_md() if slug(r[0]) == parts[1] and r[1] == parts[2] and slug(r[2]) == parts[3]]
            if len(rows) != 1:
                raise DocError("fact %s: %d rows of docs/tables.md match" % (key, len(rows)))
            return cell_value(rows[0][TABLES_COLUMNS[parts[4]]], parts[5:], key)
        if head == "data":
            return walk(self.data(parts[1]), parts[2:], key)
        if head in ("accuracy", "accuracy_up5k"):
            acc = self.accuracy("default" if head == "accuracy" else "up5k")
            if parts[1] == "added":
                return acc["added"]
            raise DocError("unknown fact %s" % key)
        if head == "acc":   # acc.<variant>.added|added_n, acc.<variant>.worst[.n], acc.<variant>.rows.<slug>.<col>[.n]
            acc = self.accuracy(parts[1])
            if parts[2] in ("added", "added_n", "positions", "every", "every_n", "every_angle", "every_rel",
                            "every_rel_n", "goal", "stretch"):
                if parts[2] not in acc or acc[parts[2]] is None:
                    raise DocError("fact %s: specsim accuracy printed no such figure" % key)
                return acc[parts[2]]
            if parts[2] == "worst":
                return cell_value(acc["worst_core"], parts[3:], key)
            if parts[2] == "rows":
                return cell_value(acc["rows"][parts[3]][int(parts[4])], parts[5:], key)
            raise DocError("unknown fact %s" % key)
        if head == "ice40":   # ice40.9|12.<configuration>: SB_RAM40_4K of that ROM (Yosys synth_ice40)
            return self.ice40_brams(parts[1], parts[2])
        if head == "tool" and parts[1] == "yosys":
            return self.yosys_version()
        if head == "desc":   # desc.<FIELD>[.<config>]: the descriptor field's bits as [msb:lsb]
            h = self.header(parts[2] if len(parts) > 2 else "default")
            width = {"C": h["C_W"], "N": h["N_W"], "L": h["L_W"], "ZETA0": h["ANG_W"], "DZETA": h["ANG_W"]}[parts[1]]
            lsb = h["DESC_%s_LSB" % parts[1]]
            return "[%d:%d]" % (lsb + width - 1, lsb)
        if head == "romline":   # romline.<image in rom/>: the image's first line (specrom's parameter comment)
            return open(os.path.join(ROOT, "rom", parts[1] + ".hex")).readline().strip()
        if head == "gtest":   # gtest.<Suite>.<Test>.<property>: what the test records (a number)
            return float(walk(self.gtest(parts[1] + "." + parts[2]), parts[3:], key))
        if head == "src":   # src.<source>.<NAME>.<key>: a constant of a project script (SOURCES), e.g. synth goals
            return walk(source_constant(parts[1], parts[2]), parts[3:], key)
        if head == "vrow":   # vrow.<Suite>.<Test>.<column>: a cell of docs/verification.md's bound-ratio rows
            name = "`%s.%s`" % (parts[1], parts[2])
            for line in open(os.path.join(ROOT, "docs", "verification.md"), encoding="utf-8"):
                cells = [c.strip() for c in line.strip().strip("|").split("|")]
                if cells and cells[0] == name:
                    return cell_value(cells[int(parts[3])], parts[4:], key)
            raise DocError("fact %s: no row %s in docs/verification.md" % (key, name))
        if head == "fig8k":   # fig8k.<mode>.<k> or .<k1>-<k2>: the n whose error stays within 1 % (same for all)
            ranges = {}
            for m in re.finditer(r"^\s+(\d+) \| (\S+(?: \(with gaps\))?)\s+\|", self.fig8_mode(parts[1]), re.M):
                ranges[int(m.group(1))] = m.group(2)
            lo, _, hi = parts[2].partition("-")
            got = sorted({ranges[k] for k in range(int(lo), int(hi or lo) + 1)})
            return "; ".join(got)
        if head in ("q", "a"):   # q(n), a(n) in %
            return self.fig8_all()[0 if head == "q" else 1][int(parts[1])]
        if head == "calc":   # small derived values
            return CALC[parts[1]](self)
        raise DocError("unknown fact %s" % key)


def slug(label):
    return re.sub(r"[^a-z0-9]+", "_", label.lower()).strip("_")


def percent(cell, key):
    m = re.match(r"\**\s*(-?[\d.]+)\s*%", cell)
    if not m:
        raise DocError("fact %s: '%s' is not a percentage" % (key, cell))
    return float(m.group(1))


def cell_value(cell, rest, key):
    """A table cell's number: 'P %' -> P, 'P % (n = N)' -> P or, with rest == ['n'], N; a plain number -> it."""
    if rest == ["n"]:
        m = re.search(r"\(n = (\d+)\)", cell)
        if not m:
            raise DocError("fact %s: '%s' names no n" % (key, cell))
        return int(m.group(1))
    if rest:
        raise DocError("unknown fact %s" % key)
    if "%" in cell:
        return percent(cell, key)
    try:
        return float(cell) if "." in cell else int(cell)
    except ValueError:
        return cell


# docs/tables.md's columns by name (tables.* facts)
TABLES_COLUMNS = {"rom9": 3, "kbit": 4, "double": 5, "core": 6, "abs": 7, "meets": 8}

# The renders facts render[_VARIANT].* come from: specsim render's options (besides --quiet, --out, --stats)
RENDERS = {"render": ["--scene", "default", "--size", "512", "--model", "rtl", "--mode", "patent"],
           "render_tuned": ["--scene", "default", "--size", "512", "--model", "rtl", "--mode", "tuned"],
           "render_pow": ["--scene", "default", "--size", "512", "--model", "rtl", "--mode", "pow"],
           "render_perchannel": ["--scene", "default", "--size", "512", "--model", "rtl", "--rgb", "per-channel"],
           "render_cull": ["--scene", "default", "--size", "512", "--model", "rtl", "--cull-specular"]}
for _size in (256, 384, 768, 1024):
    RENDERS["render_s%d" % _size] = ["--scene", "default", "--size", str(_size), "--model", "rtl"]
for _scene in ("default", "sphere", "torus", "teapot"):
    for _rule in ("patent", "midpoint"):
        RENDERS["render_%s_%s" % (_scene, _rule)] = ["--scene", _scene, "--size", "512", "--model", "golden",
                                                     "--host", _rule]
    if _scene != "default":
        RENDERS["render_cull_%s" % _scene] = ["--scene", _scene, "--size", "512", "--model", "golden", "--cull-specular"]


def walk(obj, parts, key):
    for p in parts:
        if isinstance(obj, list):
            obj = obj[int(p)]
        elif isinstance(obj, dict) and p in obj:
            obj = obj[p]
        else:
            raise DocError("unknown fact %s (no '%s')" % (key, p))
    return obj


def shader_run(f, target, config):
    """docs/data/synth_shader.json's row of spec_shader on target in config."""
    for r in f.data("synth_shader")["results"]:
        if r["target"] == target and r["config"] == config:
            return r
    raise DocError("docs/data/synth_shader.json has no %s %s row (make synth)" % (target, config))


def bad_input_rows():
    sys.path.insert(0, os.path.join(ROOT, "tests"))
    import bad_input
    return sum(1 for l in open(os.path.join(ROOT, "docs", "bad-input.md")) if bad_input.ROW.match(l.rstrip("\n")))


def synth_row(f, name):
    """A run of docs/data/synth.json (make synth) by its name, target-top-config[-lLANES]."""
    rows = f.data("synth").get("by_run", {})
    if name not in rows:
        raise DocError("docs/data/synth.json has no run %s (make synth)" % name)
    return rows[name]


def pow_rom_bits(h):
    """ROM 9 (the log table) and ROM 12 (exp2) of a pow-mode header, in bits."""
    rom9 = 2 ** (1 + h["POW_SEG_W"] + h["POW_IDX_W"]) * (h["POW_SH_W"] + 1 + h["POW_DLT_W"] + h["POW_VAL_W"])
    rom12 = 2 ** h["TBL_AW"] * (h["TBL_DW"] + (h["DELTA_W"] if h["INTERP"] else 0))
    return rom9 + rom12


def pow_edge_step():
    """kPowEdgeStep of rom/gen/pow_table.h: what the log table's entry at |angle| = K adds to the next one's."""
    m = re.search(r"constexpr double kPowEdgeStep = ([\d.]+);", open(os.path.join(ROOT, "rom", "gen", "pow_table.h")).read())
    if not m:
        raise DocError("rom/gen/pow_table.h has no kPowEdgeStep")
    return float(m.group(1))


def q_below_from(f, limit):
    """The smallest n0 with q(n) <= limit for every n0 <= n <= 1000."""
    q = f.fig8_all()[0]
    n0 = 1000
    while n0 > 1 and q[n0 - 1] <= limit:
        n0 -= 1
    return n0


CALC = {
    # how many times smaller the tuned approximation's worst epicentre error is than the patent's
    "rom9_tuned_bits": lambda f: f.header("tuned")["SCALE_W"] + f.header("tuned")["TSEL_W"],
    "tuned_factor": lambda f: percent(f.compare()["rel"]["all_n_0_1023"][3], "tuned_factor") /
    percent(f.compare()["rel"]["all_n_0_1023"][5], "tuned_factor"),
    "q06_from": lambda f: q_below_from(f, 0.6),
    # pixel i of spec_unit, cycles after Start: FIRST + 2i; busy_o from t+1 to t+FIRST+2l
    "unit_busy_end_plus1": lambda f: f.header("default")["UNIT_FIRST_PIXEL"] + 1,
    # the verification summary (docs/verification.md) from the JSON the slow targets write
    "formal_minutes": lambda f: sum(r["seconds"] for r in f.data("formal")["steps"]) / 60.0,
    "formal_proofs": lambda f: sum(1 for r in f.data("formal")["steps"] if r["step"] == "induction"),
    "formal_covers": lambda f: sum(r["covers"] or 0 for r in f.data("formal")["steps"] if r["step"] == "cover"),
    "formal_all_pass": lambda f: all(r["pass"] for r in f.data("formal")["steps"]),
    "formal_bugs": lambda f: sum(1 for m in f.data("formal_mutants")["mutants"] if m["expected"]),
    "formal_equivalents": lambda f: sum(1 for m in f.data("formal_mutants")["mutants"] if not m["expected"]),
    "coverage_line_min": lambda f: min(100.0 * v["line"][0] / v["line"][1]
                                       for v in f.data("coverage")["files"].values() if v["line"][1]),
    "coverage_toggle_all": lambda f: 100.0 * f.data("coverage")["all"]["toggle"][0] /
    f.data("coverage")["all"]["toggle"][1],
    "coverage_drift": lambda f: coverage_drift(f.data("coverage")),
    # the iCEBreaker's routed Fmax over its design clock, in % (docs/boards.md)
    "icebreaker_slack_pct": lambda f: 100.0 * (f.data("bitstream_icebreaker")["designs"][0]["clocks"][0]["fmax_mhz"] /
                                               f.data("bitstream_icebreaker")["designs"][0]["clocks"][0]["constraint_mhz"] - 1.0),
    "long_pixels": lambda f: sum(r["pixels"] for r in f.data("test_long")["runs"]),
    "long_minutes": lambda f: f.data("test_long")["seconds"] / 60.0,
    # the rows of docs/bad-input.md that tests/bad_input.py runs (its ROW pattern)
    "bad_input_rows": lambda f: bad_input_rows(),
    # formats and ranges that follow from the header's widths (docs/interface.md, docs/decisions.md)
    "ang_int": lambda f: f.header("default")["ANG_W"] - f.header("default")["ANG_FRAC"] - 1,
    "ang_max": lambda f: 2 ** (f.header("default")["ANG_W"] - f.header("default")["ANG_FRAC"] - 1),
    "n_max": lambda f: 2 ** f.header("default")["N_W"] - 1,
    "l_max": lambda f: 2 ** f.header("default")["L_W"] - 1,
    "l_wrap": lambda f: 2 ** f.header("default")["L_W"],
    "scale_int": lambda f: f.header("default")["SCALE_W"] - f.header("default")["SCALE_FRAC"],
    "tbl_dw": lambda f: f.header("default")["TBL_FRAC"] + 1,
    "rom12_bits": lambda f: f.header("default")["ROM12_DEPTH"] * f.header("default")["TBL_DW"],
    "rom12_tables": lambda f: f.header("default")["ROM12_DEPTH"] >> f.header("default")["TBL_AW"],
    "rom12_positions": lambda f: 2 ** f.header("default")["TBL_AW"],
    "up5k_positions": lambda f: 2 ** f.header("up5k")["TBL_AW"],
    # cos(pi/2 - h) = sin(h) for h half a table step: the largest k = 1 value the early switch to 0 drops
    "half_step_cos": lambda f: math.sin(math.pi / 2 / 2 ** f.header("default")["TBL_AW"] / 2),
    # iCE40 block RAMs of ROM 9 + ROM 12 (Yosys synth_ice40)
    "ice40_up5k": lambda f: f.ice40_brams("9", "up5k") + f.ice40_brams("12", "up5k"),
    "ice40_up5k_tuned": lambda f: f.ice40_brams("9", "up5k_tuned") + f.ice40_brams("12", "up5k_tuned"),
    "rom9_up5k_tuned_bits": lambda f: f.header("up5k_tuned")["SCALE_W"] + f.header("up5k_tuned")["TSEL_W"],
    # pow mode (docs/pow.md): ROM bits of both tables, per configuration; the up5k configuration's SB_RAM40_4K
    "pow_rom_bits": lambda f: pow_rom_bits(f.header("pow")),
    "pow_up5k_rom_bits": lambda f: pow_rom_bits(f.header("up5k_pow")),
    "patent_rom_bits": lambda f: f.header("default")["ROM9_DEPTH"] * f.header("default")["SCALE_W"] +
    f.header("default")["ROM12_DEPTH"] * f.header("default")["TBL_DW"],
    "ice40_up5k_pow": lambda f: f.ice40_brams("9", "up5k_pow") + f.ice40_brams("12", "up5k_pow"),
    "pow_rom9_words": lambda f: 2 ** (1 + f.header("pow")["POW_SEG_W"] + f.header("pow")["POW_IDX_W"]),
    "pow_up5k_rom9_words": lambda f: 2 ** (1 + f.header("up5k_pow")["POW_SEG_W"] + f.header("up5k_pow")["POW_IDX_W"]),
    "pow_rom9_width": lambda f: f.header("pow")["POW_SH_W"] + 1 + f.header("pow")["POW_DLT_W"] + f.header("pow")["POW_VAL_W"],
    "pow_segments": lambda f: 2 ** f.header("pow")["POW_SEG_W"],
    "pow_last_octave": lambda f: 2 ** f.header("pow")["POW_SEG_W"] - 2,
    "pow_entries": lambda f: 2 ** f.header("pow")["POW_IDX_W"],
    "pow_up5k_entries": lambda f: 2 ** f.header("up5k_pow")["POW_IDX_W"],
    "pow_lowest_octave": lambda f: 2 ** f.header("pow")["POW_SEG_W"] - 1,
    "pow_up5k_rom12_width": lambda f: f.header("up5k_pow")["TBL_DW"] + f.header("up5k_pow")["DELTA_W"],
    # the log table's edge at |angle| = K (docs/pow.md): -log2 cos K, the generator's kPowEdgeStep, the worst
    # |2^-(c (1 - f)) - f| over f with c = kPowEdgeStep (in units of the next entry's cos), the last segment's
    # spacing 2^-e rad, and cos^2 there 2^-2e
    "pow_edge_log": lambda f: -math.log2(math.cos(f.header("pow")["POW_K"] * 2.0 ** -f.header("pow")["ANG_FRAC"])),
    "pow_edge_step": lambda f: pow_edge_step(),
    "pow_edge_err": lambda f: max(abs(2.0 ** (-pow_edge_step() * (1 - i / 10000.0)) - i / 10000.0)
                                  for i in range(10001)),
    "pow_edge_spacing_exp": lambda f: 2 ** f.header("pow")["POW_SEG_W"] - 1 + f.header("pow")["POW_IDX_W"],
    "pow_edge_n2_exp": lambda f: 2 * (2 ** f.header("pow")["POW_SEG_W"] - 1 + f.header("pow")["POW_IDX_W"]),
    "patent_up5k_rom_bits": lambda f: f.header("up5k")["ROM9_DEPTH"] * f.header("up5k")["SCALE_W"] +
    f.header("up5k")["ROM12_DEPTH"] * (f.header("up5k")["TBL_DW"] + f.header("up5k")["DELTA_W"]),
    "tuned_rom_bits": lambda f: f.header("tuned")["ROM9_DEPTH"] * (f.header("tuned")["SCALE_W"] +
                                                                     f.header("tuned")["TSEL_W"]) +
    f.header("tuned")["ROM12_DEPTH"] * f.header("tuned")["TBL_DW"],
    "tuned_up5k_rom_bits": lambda f: f.header("up5k_tuned")["ROM9_DEPTH"] * (f.header("up5k_tuned")["SCALE_W"] +
                                                                           f.header("up5k_tuned")["TSEL_W"]) +
    f.header("up5k_tuned")["ROM12_DEPTH"] * (f.header("up5k_tuned")["TBL_DW"] + f.header("up5k_tuned")["DELTA_W"]),
    # the worst absolute error / C of each mode's core (specsim compare) in steps of an 8-bit display
    "patent_abs_steps": lambda f: 2.55 * percent(f.compare()["abs"]["all_n_0_1023"][4], "patent_abs_steps"),
    "tuned_abs_steps": lambda f: 2.55 * percent(f.compare()["abs"]["all_n_0_1023"][6], "tuned_abs_steps"),
    "pow_abs_steps": lambda f: 2.55 * percent(f.compare()["abs"]["all_n_0_1023"][8], "pow_abs_steps"),
    "ice40_pow": lambda f: f.ice40_brams("9", "pow") + f.ice40_brams("12", "pow"),
    "ice40_default": lambda f: f.ice40_brams("9", "default") + f.ice40_brams("12", "default"),
    # what pow mode adds on the UP5K (make synth, spec_stream LANES = 1, up5k configuration)
    "pow_extra_lut_l1": lambda f: synth_row(f, "ice40-up5k-spec_stream-up5k-pow")["lut"] -
    synth_row(f, "ice40-up5k-spec_stream-up5k")["lut"],
    "pow_extra_ff_l1": lambda f: synth_row(f, "ice40-up5k-spec_stream-up5k-pow")["ff"] -
    synth_row(f, "ice40-up5k-spec_stream-up5k")["ff"],
    # make synth: the rows where pow mode's worst seed is below patent mode's, and those where it is not
    "pow_synth_slower": lambda f: pow_synth_rows_where(f, True),
    "pow_synth_not_slower": lambda f: pow_synth_rows_where(f, False),
    "pow_synth_none_slower": lambda f: pow_synth_rows_where(f, True) == "none",
    # docs/tables.md: can any patent-mode row meet 0.25 %?
    "tables_patent_meets": lambda f: any(r[8] == "yes" for r in f.tables_md() if r[1] == "patent"),
    # the renderer (docs/renderer.md, docs/host.md)
    "render_pixels_per_span": lambda f: f.render()["against_ref"]["rtl"]["model_pixels"] / f.render()["spans"],
    "render_cycles_per_pixel": lambda f: f.render()["cycles"] / f.render()["against_ref"]["rtl"]["model_pixels"],
    "render_rtl_max_sizes": lambda f: span_of(f.render("render_s%d" % n)["against_ref"]["rtl"]["max_abs"]
                                              for n in (256, 384, 768, 1024)),
    "render_proto_max_sizes": lambda f: span_of(f.render("render_s%d" % n)["against_ref"]["prototype"]["max_abs"]
                                                for n in (256, 384, 768, 1024)),
    "cull_spans_pct": lambda f: 100.0 * f.render("render_cull")["cull"]["spans"] / f.render("render_cull")["cull"]["of_spans"],
    "cull_cycles_pct": lambda f: 100.0 * (1 - f.render("render_cull")["cycles"] / f.render()["cycles"]),
    "cull_single_pct": lambda f: span_of(round(100.0 * f.render("render_cull_" + sc)["cull"]["spans"] /
                                               f.render("render_cull_" + sc)["cull"]["of_spans"])
                                         for sc in ("sphere", "torus", "teapot")),
    # host.md: for n = 3 (table k = 4, scale sqrt(3/4) < 1) the table is read up to the angle pi/2 / sqrt(3/4),
    # and at pi/2, where the true BRDF is 0, it gives cos^4(sqrt(3/4) pi/2)
    "n3_table_end": lambda f: math.pi / 2 / math.sqrt(0.75),
    "n3_at_right_angle_pct": lambda f: 100.0 * math.cos(math.sqrt(0.75) * math.pi / 2) ** 4,
    "perchannel_cycles_ratio": lambda f: f.render("render_perchannel")["cycles"] / f.render()["cycles"],
}


# Project scripts whose constants documents quote (src.* facts)
SOURCES = {"synth": "syn/synth.py", "formal": "formal/formal.py"}


def source_constant(source, name):
    """A literal assigned at the top level of a project script; a list of "--flag", "value" pairs as a dict."""
    import ast
    if source not in SOURCES:
        raise DocError("unknown source %s" % source)
    tree = ast.parse(open(os.path.join(ROOT, SOURCES[source]), encoding="utf-8").read())
    for node in tree.body:
        if isinstance(node, ast.Assign) and any(getattr(t, "id", None) == name for t in node.targets):
            value = ast.literal_eval(node.value)
            if isinstance(value, dict):   # tuple keys (e.g. synth.py's GOALS by target and LANES) as "a:b"
                value = {":".join(map(str, k)) if isinstance(k, tuple) else k: v for k, v in value.items()}
            if isinstance(value, list) and value and all(isinstance(v, str) for v in value) and value[0].startswith("--"):
                value = {value[i][2:]: value[i + 1] for i in range(0, len(value) - 1, 2)}
            return value
    raise DocError("%s has no constant %s" % (SOURCES[source], name))


def span_of(values):
    """'3' when all values are equal, else 'lo-hi'."""
    v = sorted(set(values))
    return "%s" % v[0] if len(v) == 1 else "%s-%s" % (v[0], v[-1])


def fmt(value, spec):
    if spec in (None, ""):
        if isinstance(value, float):
            return "%g" % value
        return str(value)
    if spec == "int_sep":   # 8 600 -> thin-space thousands as the documents write them
        return "{:,}".format(int(value)).replace(",", " ")
    if spec == "yesno":
        return "yes" if value else "no"
    if spec == "code":   # an inline code span (a mark inside backticks would show as text)
        return "`%s`" % value
    if spec == "can":
        return "can" if value else "cannot"
    if spec == "int_comma":   # 65536 -> 65,536
        return "{:,}".format(int(value))
    if spec == "sci_up":   # an upper bound in one digit: 0.0001917 -> 2e-4
        e = math.floor(math.log10(value))
        m = math.ceil(value / 10 ** e - 1e-12)
        return "%de%d" % (m, e) if m < 10 else "1e%d" % (e + 1)
    if spec == "thousands":   # 13 896 -> 14 000
        return "{:,}".format(int(round(value, -3))).replace(",", " ")
    return spec % value


# ---- blocks ------------------------------------------------------------------------------------------------
def block_render_stats(f):
    s = f.render()["against_ref"]
    rows = [("rtl", "rtl (= golden bit for bit)"), ("prototype", "prototype"),
            ("host", "host alone (its angles, exact cos^n)")]
    s = dict(s, shader=docgen_shader.render_shader(f)["against_ref"]["shader"])
    rows.insert(1, ("shader", "shader (`--model shader`: spec_setup in RTL too)"))
    out = ["| model | max \\|error\\| | mean \\|error\\| on objects | PSNR | pixels > 4 levels off |",
           "|---|---|---|---|---|"]
    for k, label in rows:
        r = s[k]
        out.append("| %s | %d | %.3f | %.1f dB | %s |" % (label, r["max_abs"], r["mean_abs"], r["psnr_db"],
                                                          fmt(r["pixels_over_4"], "int_sep")))
    return "\n".join(out)


def block_accuracy(f):
    return "\n".join(l for l in f.accuracy("default")["text"].splitlines() if l.startswith("|"))


def block_fig8(f):
    out = f.run([f.specsim, "fig8"])
    comp, pat = [], []
    for line in out.splitlines():
        m = re.match(r"^\s+(\d+) \| (\S+)\s+\| (\S+)", line)
        if m:
            comp.append((int(m.group(1)), m.group(2), m.group(3)))
    # merge runs of equal columns (10..14 when both rows agree) as the README writes them
    cols = []
    for k, c, p in comp:
        c = c if c.split("..")[0] != c.split("..")[-1] else c.split("..")[0]
        if cols and cols[-1][1] == c and cols[-1][2] == p and cols[-1][0][1] == k - 1:
            cols[-1] = ((cols[-1][0][0], k), c, p)
        else:
            cols.append(((k, k), c, p))
    head = ["k"] + ["%d" % a if a == b else "%d..%d" % (a, b) for (a, b), _, _ in cols]
    crow = ["computed"] + [("**%s**" % c if c != p else c) for _, c, p in cols]
    prow = ["patent"] + [p for _, _, p in cols]
    return "\n".join(["| " + " | ".join(head) + " |", "|" + "---|" * len(head),
                      "| " + " | ".join(crow) + " |", "| " + " | ".join(prow) + " |"])


def block_fig11_waves(f):
    text = open(os.path.join(ROOT, "docs", "fig11-timing.txt"), encoding="utf-8").read()
    lines = [l for l in text.splitlines() if l.startswith("              ") or re.match(r"^[a-z_0-9]+ +\d\d ", l)]
    return "```\n" + "\n".join(lines) + "\n```"


def block_synth_table(f):
    d = f.data("synth")
    rows = d.get("results", []) if isinstance(d, dict) else d
    f1 = lambda v: "-" if v is None else "%.1f" % v
    out = ["| target | top | config | LANES | LUT | FF | BRAM | DSP | Fmax (MHz), worst seed | Fmax per seed 1, 2, ... | "
           "icetime (MHz), worst | Mpixel/s | goal (MHz) | fits | goal met |", "|" + "---|" * 15]
    for r in rows:
        seeds = r.get("fmax_seeds") or []
        out.append("| %s | %s | %s | %d | %d | %d | %d | %d | %s | %s | %s | %s | %s | %s | %s |" % (
            r["target"], r["top"], r["config"], r.get("lanes", 1), r["lut"], r["ff"], r["bram"], r["dsp"],
            f1(r.get("fmax_mhz")), ", ".join("%.1f" % x for x in seeds if x is not None) or "-",
            f1(r.get("icetime_mhz")), f1(r.get("mpix_s")), "-" if r.get("goal_mhz") is None else "%g" % r["goal_mhz"],
            "yes" if r["fits"] else "no", "-" if r.get("goal_mhz") is None else ("yes" if r["met"] else "no")))
    return "\n".join(out)


def block_bench_lanes(f):
    b = f.data("bench_lanes")
    out = ["| frame | spans | pixels | pixels per span | LANES = 1 | 2 | 2, PACK = 1 | 4 | 4, PACK = 1 |",
           "|---|---|---|---|---|---|---|---|---|"]
    for r in b["rows"]:
        p = r["ppc"]
        out.append("| %dx%d | %d | %d | %.1f | %s |" % (
            r["w"], r["h"], r["spans"], r["pixels"], r["pixels"] / max(1, r["spans"]),
            " | ".join("%.3f" % p[k]["pixels_per_clock"] for k in ("l1", "l2", "l2p", "l4", "l4p"))))
    return "\n".join(out)


def block_bench_stream(f):
    b = f.data("bench_stream")
    cpp = b["cycles_per_pixel"]
    pps = b["pixels_per_second"]
    ref = pps["verilator_stream"]
    out = ["Workload: %d spans, %d pixels (l = 0..24, random n), %d runs, medians" % (b["spans"], b["pixels"], b["runs"]),
           "", "| core and stalls | clock cycles per pixel |", "|---|---|",
           "| spec_stream, no stalls | %.4f |" % cpp["stream_no_stalls"],
           "| spec_stream, source and sink ready 90 %% of cycles | %.4f |" % cpp["stream_stalls_90"],
           "| spec_stream, sink ready 50 %% of cycles | %.4f |" % cpp["stream_sink_50"],
           "| spec_unit (patent control block, span by span) | %.4f |" % cpp["unit"], "",
           "| simulator | core | simulated pixels per second | ratio to Verilator spec_stream |", "|---|---|---|---|"]
    for key, sim, core in (("verilator_stream", "Verilator", "spec_stream"), ("verilator_unit", "Verilator", "spec_unit"),
                           ("icarus_stream", "Icarus (vvp, incl. start-up)", "spec_stream"),
                           ("icarus_unit", "Icarus (vvp, incl. start-up)", "spec_unit")):
        r = pps[key] / ref
        out.append("| %s | %s | %.3g | %s |" % (sim, core, pps[key], "1" if key == "verilator_stream" else
                                                  ("%.2f" % r if r >= 0.01 else "%.3f" % r)))
    return "\n".join(out)


# make synth's pow rows beside patent mode's at the same target, LANES and seeds (docs/pow.md, README)
POW_SYNTH_ROWS = [("ice40-up5k", "spec_stream", 1), ("ice40-up5k", "spec_stream", 2), ("ecp5-25f", "spec_stream", 1),
                  ("ecp5-25f", "spec_stream", 4), ("ice40-up5k", "spec_stream_seq", 1)]


def pow_synth_pairs(f):
    """(target, top, LANES, patent mode's row, pow mode's row) of make synth's pow comparison."""
    return [(target, top, lanes) + tuple(synth_row(f, "%s-%s-%s%s" % (target, top, config,
                                                                     "" if lanes == 1 else "-l%d" % lanes))
                                         for config in ("up5k", "up5k-pow"))
            for target, top, lanes in POW_SYNTH_ROWS]


def median(xs):
    xs = sorted(xs)
    return xs[len(xs) // 2] if len(xs) % 2 else (xs[len(xs) // 2 - 1] + xs[len(xs) // 2]) / 2


def block_synth_pow(f):
    out = ["| target | top | LANES | mode | LUT4 | FF | BRAM | DSP | ROM bits (ROM 9 + ROM 12) | "
           "Fmax (MHz), worst seed | median of the seeds | Fmax per seed 1, 2, ... | goal (MHz) | "
           "pow / patent, worst seed |", "|" + "---|" * 14]
    bits = {"patent": f.get("calc.patent_up5k_rom_bits"), "pow": f.get("calc.pow_up5k_rom_bits")}
    for target, top, lanes, pat, pw in pow_synth_pairs(f):
        for mode, r in (("patent", pat), ("pow", pw)):
            seeds = [x for x in (r.get("fmax_seeds") or []) if x is not None]
            ratio = "-"
            if mode == "pow" and r.get("fmax_mhz") and pat.get("fmax_mhz"):
                ratio = "%.2f" % (r["fmax_mhz"] / pat["fmax_mhz"])
            out.append("| %s | %s | %d | %s | %d | %d | %d | %d | %s | %s | %s | %s | %s | %s |" % (
                target, top, lanes, mode, r["lut"], r["ff"], r["bram"], r["dsp"], fmt(bits[mode], "int_sep"),
                "-" if r.get("fmax_mhz") is None else "%.1f" % r["fmax_mhz"],
                "%.1f" % median(seeds) if seeds else "-", ", ".join("%.1f" % x for x in seeds) or "-",
                "-" if r.get("goal_mhz") is None else "%g" % r["goal_mhz"], ratio))
    return "\n".join(out)


def pow_synth_rows_where(f, slower):
    """The rows where pow mode's worst seed is below patent mode's (slower) or not, as text."""
    names = ["%s %s with LANES = %d" % ({"ice40-up5k": "UP5K", "ecp5-25f": "ECP5-25F"}[t], top, lanes)
             for t, top, lanes, pat, pw in pow_synth_pairs(f)
             if (pw["fmax_mhz"] < pat["fmax_mhz"]) == slower]
    if not names:
        return "none"
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def block_compare_side(f):
    """The third table of specsim compare: the choices side by side (docs/pow.md)."""
    lines = f.compare()["text"].splitlines()
    starts = [i for i, l in enumerate(lines) if l.startswith("| BRDF range")]
    out = []
    for l in lines[starts[2]:]:
        if not l.startswith("|"):
            break
        out.append(l)
    return "\n".join(out)


def block_accuracy_pow(f):
    """specsim accuracy --mode pow: its table and the paragraph on every angle and every n (docs/pow.md)."""
    text = f.accuracy("pow")["text"]
    table = [l for l in text.splitlines() if l.startswith("|")]
    every = text[text.index("Every angle and every n"):].strip().splitlines()
    return "\n".join(table + ["", "```"] + every + ["```"])


def block_compare_rel(f):
    lines = f.compare()["text"].splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("| BRDF range"))
    out = []
    for l in lines[start:]:
        if not l.startswith("|"):
            break
        out.append(l)
    return "\n".join(out)


# The excerpt of docs/tables.md in README: (tables k, ROM 12 as tables.md writes it)
TABLES_EXCERPT = [("2", "1 x 2^12 x 17"), ("1,4", "2 x 2^7 x 28 (interp.)"), ("1,2,4,16", "4 x 2^12 x 17"),
                  ("1,2,4,16", "4 x 2^10 x 17"), ("1,2,4,16", "4 x 2^7 x 28 (interp.)"),
                  ("1,2,4,8,16,32,64", "7 x 2^12 x 17"), ("1,2,3,4,8,16", "6 x 2^7 x 28 (interp.)")]


def block_tables_excerpt(f):
    rows = f.tables_md()
    out = ["| tables k | ROM 12 | ROM kbit (patent mode / tuned mode) | patent mode | tuned mode |", "|---|---|---|---|---|"]
    for k, rom12 in TABLES_EXCERPT:
        pick = {r[1]: r for r in rows if r[0] == k and r[2] == rom12}
        if set(pick) != {"patent", "tuned"}:
            raise DocError("docs/tables.md has no rows for tables %s, ROM 12 %s" % (k, rom12))
        p, t = pick["patent"], pick["tuned"]
        kbit = p[4] if p[4] == t[4] else "%s / %s" % (p[4], t[4])
        out.append("| %s | %s | %s | %s | %s |" % (k.replace(",", ", "), rom12.replace(" x ", " × "), kbit, p[6], t[6]))
    return "\n".join(out)


def block_formal_steps(f, name="formal"):
    d = f.data(name)
    out = ["| job | step | result | time (s) |", "|---|---|---|---|"]
    for r in d["steps"]:
        what = r["what"] + ((" (%d reached)" % r["covers"]) if r.get("covers") is not None else "")
        out.append("| %s | %s | %s | %.0f |" % (r["job"], what, "pass" if r["pass"] else "FAIL", r["seconds"]))
    out.append("")
    dates = sorted(set(r.get("date", d["date"]) for r in d["steps"]))
    out.append("(`make formal` on %s, %s, 2 cores; times vary with the machine's load.)" % (
        " and ".join(dates), d.get("solver")))
    return "\n".join(out)


def block_formal_mutants(f, name="formal_mutants"):
    d = f.data(name)
    out = ["| job | the bug (`formal/formal.py` MUTANTS) | caught by |", "|---|---|---|"]
    for m in d["mutants"]:
        if m["expected"]:
            res = "`%s`" % m["assertion"] if m.get("assertion") else "caught"
            if m.get("step") == "induction":
                res += " (the induction step)"
        else:
            res = "not caught, as it must not be (an equivalent change)"
        out.append("| %s | %s | %s |" % (m["job"], m["bug"], res))
    out.append("")
    jobs = set(m["job"] for m in d["mutants"])
    out.append("(`make %s` on %s: bounded checks of %s cycles%s.)" % (
        "formal-shader" if name == "formal_mutants_shader" else "formal-mutants", d["date"],
        ", ".join("%s %d" % kv for kv in sorted(d["bmc_cycles"].items()) if kv[0] in jobs),
        "".join("; %s: then the induction step" % j for j in sorted(d.get("steps", {})) if j in jobs)))
    return "\n".join(out)


def block_coverage(f):
    d = f.data("coverage")

    def cell(hit_tot):
        hit, tot = hit_tot
        return "%.1f %% (%d/%d)" % (100.0 * hit / tot, hit, tot) if tot else "no statements"
    out = ["| RTL file | line coverage | toggle coverage |", "|---|---|---|"]
    for name, v in sorted(d["files"].items()):
        if not v["line"][1] and not v["toggle"][1]:
            out.append("| `%s` | no logic (elaboration-time checks) | - |" % name)
            continue
        out.append("| `%s` | %s | %s |" % (name, cell(v["line"]), cell(v["toggle"]) if v["toggle"][1] else "-"))
    out.append("| all | %s | %s |" % (cell(d["all"]["line"]), cell(d["all"]["toggle"])))
    out.append("")
    out.append("(`make coverage` on %s; %s.)" % (d["date"], coverage_drift(d)))
    return "\n".join(out)


def coverage_drift(d):
    """Which RTL files differ from what the coverage run measured (docs/data/coverage.json's blob hashes):
    the table above holds for the files as they were then, not for these."""
    import importlib.util   # scripts/coverage.py by path: a module named coverage may also be installed
    spec = importlib.util.spec_from_file_location("spec_coverage", os.path.join(ROOT, "scripts", "coverage.py"))
    cov = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(cov)
    blob = cov.blob_hash
    now = sorted(os.path.basename(p) for p in glob.glob(os.path.join(ROOT, "rtl", "*.v")))
    changed = [n for n in now if n in d["files"] and "blob" in d["files"][n] and
               d["files"][n]["blob"] != blob(os.path.join(ROOT, "rtl", n))]
    unknown = [n for n in now if n in d["files"] and "blob" not in d["files"][n]]
    new = [n for n in now if n not in d["files"]]
    gone = [n for n in sorted(d["files"]) if n not in now]
    parts = []
    if changed:
        parts.append("changed since that run, so not measured as they are now: " + ", ".join(changed))
    if new:
        parts.append("added since, not measured: " + ", ".join(new))
    if gone:
        parts.append("removed since: " + ", ".join(gone))
    if unknown:
        parts.append("the run recorded no content hashes, so changes since are not known")
    return "; ".join(parts) if parts else "every RTL file is as that run measured it"


# ---- the reference designs on boards (issue 15, docs/boards.md): make board-split, make bitstream -------------
def block_board_split(f):
    out = []
    for name, label in (("board_split_640x480", "640 × 480 (ULX3S)"), ("board_split_320x240", "320 × 240 (the frame-buffer designs' raster; both tables through the ecp5 setup's model)")):
        d = f.data(name)
        out.append("%s, %d frames:" % (label, d["frames"]))
        out.append("")
        out.append("| K | sub-spans a line (mean, most) | n = 1 | n = 3 | n = 10 | n = 100 | n = 1000 | largest | worst PSNR |")
        out.append("|" + "---|" * 9)
        for r in d["rows"]:
            out.append("| %d | %.1f, %d | %s | %d | %.1f dB |" % (r["k"], r["spans_per_line"], r["spans_max_line"],
                       " | ".join(str(v) for v in r["max_by_sphere"]), r["max"], r["psnr_db"]))
        out.append("")
    return "\n".join(out[:-1])


def block_board_bitstream(board):
    def make(f):
        d = f.data("bitstream_" + board)
        out = ["| mode | device | LUT | FF | BRAM | DSP | clock | constraint (MHz) | Fmax (MHz), the bitstream's seed "
               "(the worst) | Fmax, seeds %s | met (every seed) |" % ", ".join(str(x) for x in d.get("seeds", [])),
               "|" + "---|" * 11]
        for r in d["designs"]:
            for i, c in enumerate(r["clocks"]):
                lead = ("| %s | %s | %d | %d | %d | %d |" % (r["mode"], r.get("device", ""), r["lut"], r["ff"], r["bram"],
                                                            r["dsp"]) if i == 0 else "| | | | | | |")
                seeds = ", ".join("%.2f" % x for x in r.get("fmax_seeds", {}).get(c["net"], []) if x is not None)
                met = all(x is not None and x >= c["constraint_mhz"]
                          for x in r.get("fmax_seeds", {}).get(c["net"], [c["fmax_mhz"]]))
                out.append("%s %s | %.2f | %.2f (seed %s) | %s | %s |" % (lead, c["net"].replace("$glbnet$", ""),
                                                                        c["constraint_mhz"], c["fmax_mhz"],
                                                                        r.get("seed", "-"), seeds,
                                                                        "yes" if met else "no"))
            if not r["clocks"]:
                out.append("| %s | %s | %d | %d | %d | %d | %s | | | | no |" % (r["mode"], r.get("device", ""), r["lut"],
                                                                               r["ff"], r["bram"], r["dsp"],
                                                                               r.get("note", "")))
        return "\n".join(out)
    return make


def block_board_breakdown(board):
    def make(f):
        d = f.data("bitstream_" + board)
        out = []
        for r in d["designs"]:
            b = r.get("breakdown")
            if not b or any(o is r for o in out):
                continue
            out.append("| block (with its submodules) | LUT | FF | carry | BRAM | DSP |")
            out.append("|" + "---|" * 6)
            for name, c in sorted(b.items(), key=lambda kv: -kv[1]["lut"]):
                label = {"spec_setup": "`spec_setup` (the small engine, its tables)", "spec_shader": "`spec_shader`'s own",
                         "top": "the top level, `board_core_fb`, PLL, I/O", "sync_fifo": "`sync_fifo` (all)"}.get(
                             name, "`%s`" % name)
                out.append("| %s | %d | %d | %d | %d | %d |" % (label, c["lut"], c["ff"], c["carry"], c["bram"], c["dsp"]))
            tot = {k: sum(c[k] for c in b.values()) for k in ("lut", "ff", "carry", "bram", "dsp")}
            out.append("| all (hierarchy kept) | %d | %d | %d | %d | %d |" % (tot["lut"], tot["ff"], tot["carry"], tot["bram"],
                                                                          tot["dsp"]))
            break
        return "\n".join(out)
    return make


def block_test_mutants(f):
    """The table of tests/mutants.py's mutants with make test-mutants' results (docs/data/mutants.json)."""
    sys.path.insert(0, os.path.join(ROOT, "tests"))
    import mutants
    d = f.data("mutants")

    def code(t):
        return "`%s`" % t.replace("|", "\\|")
    out = ["| mutant | the change | what it stands for | test that must fail | still passes (the old, weaker check) "
           "| result |", "|---|---|---|---|---|---|"]
    for m in mutants.MUTANTS:
        if m["name"] not in d["results"]:
            raise DocError("mutant %s has no result in docs/data/mutants.json: run make test-mutants" % m["name"])
        still = ", ".join(code(mutants.test_label(c)) for c in m["passes"]) or "-"
        out.append("| %s | `%s`: %s → %s | %s | %s | %s | %s |" % (
            m["name"], m["file"], code(m["old"]), code(m["new"]), m["why"], code(mutants.test_label(m["cmd"])),
            still, d["results"][m["name"]]))
    return "\n".join(out)


def block_test_long(f):
    """make test-long's table (docs/data/test_long.json, written by spec_long with the default pixel count)."""
    d = f.data("test_long")

    def num(v):
        return "{:,}".format(v).replace(",", " ")
    out = ["Result of `make test-long` (seed %d, %d s):" % (d["seed"], d["seconds"]), "",
           "| core | pixels checked | spans | cycles | resets / inits | other |", "|---|---|---|---|---|---|"]
    for r in d["runs"]:
        other = re.sub(r"\d{4,}", lambda m: num(int(m.group(0))), r["other"])
        events = re.sub(r"\d{4,}", lambda m: num(int(m.group(0))), r["events"])
        out.append("| %s | %s | %s | %s | %s | %s |" % (r["core"], num(r["pixels"]), num(r["spans"]), num(r["cycles"]),
                                                     events, other))
    return "\n".join(out)


def block_tables(f):
    """docs/tables.md: what `specsim tables` writes as tables.md (every set, mode and size; about half a minute)."""
    return f.tables_text()


def block_bench_render(f):
    """make bench-render's table (docs/data/bench_render.json, written by specsim render-bench --json)."""
    b = f.data("bench_render")
    st = b["stages"]

    def si(v):
        return "%.2g M" % (v / 1e6) if v >= 1e6 else "%.3g k" % (v / 1e3)

    def row(what, key, unit, frame=False):
        r = st[key]
        if frame:
            return "| %s | %.3f s | %.3f .. %.3f s |" % (what, r["median"], r["min"], r["max"])
        return "| %s | %s %s | %s .. %s %s |" % (what, si(r["median"]), unit, si(r["min"]), si(r["max"]), unit)
    return "\n".join([
        "Scene %s, %d × %d: %s spans, %s pixels through the model per frame; %d runs." % (
            b["scene"], b["size"], b["size"], fmt(b["spans"], "int_sep"), fmt(b["model_pixels"], "int_sep"), b["runs"]),
        "", "| what | median | range of the runs |", "|---|---|---|",
        row("host span setup (patent's γ)", "host_spans_per_s", "spans/s"),
        row("golden: specular stage", "golden_pixels_per_s", "pixels/s"),
        row("rtl: specular stage through the Verilated core", "rtl_pixels_per_s", "pixels/s"),
        row("rtl: simulated clock", "rtl_cycles_per_s", "cycles/s"),
        row("ref (two slerps and a pow per pixel)", "ref_pixels_per_s", "pixels/s"),
        row("whole frame with rtl", "frame_rtl_s", "", True),
        row("whole frame with golden", "frame_golden_s", "", True),
        "| golden / rtl (ratio of medians) | %.1f | |" % b["golden_over_rtl"]])


def block_host_gamma(f):
    """The host's share of the error with either γ rule, per built-in scene (specsim render --stats --host RULE)."""
    out = ["| scene | host alone, patent γ | host alone, midpoint γ | golden, patent γ | golden, midpoint γ |",
           "|---|---|---|---|---|"]
    for sc in ("default", "sphere", "torus", "teapot"):
        p, m = f.render("render_%s_patent" % sc)["against_ref"], f.render("render_%s_midpoint" % sc)["against_ref"]
        out.append("| %s | %d (mean %.3f) | %d (mean %.3f) | %d | %d |" % (
            sc, p["host"]["max_abs"], p["host"]["mean_abs"], m["host"]["max_abs"], m["host"]["mean_abs"],
            p["golden"]["max_abs"], m["golden"]["max_abs"]))
    return "\n".join(out)


def block_added_by_tbl_aw(f):
    """What fixed point adds in the epicentre for ROM 12 sizes (specsim accuracy --tbl-aw N)."""
    default = f.header("default")["TBL_AW"]
    sizes = [10, 11, 12, 13]
    head = ["2^%d%s" % (n, " (default)" if n == default else "") for n in sizes]
    vals = ["%.3f %%" % f.accuracy("tbl_aw_%d" % n)["added"] for n in sizes]
    return "\n".join(["| positions per table | " + " | ".join(head) + " |", "|---|" + "---|" * len(sizes),
                      "| added relative error, worst n | " + " | ".join(vals) + " |"])


BLOCKS = dict(docgen_shader.BLOCKS)
BLOCKS.update({
    "formal-shader": lambda f: block_formal_steps(f, "formal_shader"),
    "formal-mutants-shader": lambda f: block_formal_mutants(f, "formal_mutants_shader"),
    "tables": block_tables,
    "bench-render": block_bench_render,
    "host-gamma": block_host_gamma,
    "added-by-tbl-aw": block_added_by_tbl_aw,
    "board_split": block_board_split,
    "board_breakdown_icebreaker": block_board_breakdown("icebreaker"),
    "board_bitstream_ulx3s": block_board_bitstream("ulx3s"),
    "board_bitstream_icebreaker": block_board_bitstream("icebreaker"),
    "test-long": block_test_long,
    "test-mutants": block_test_mutants,
    "formal-steps": block_formal_steps,
    "formal-mutants": block_formal_mutants,
    "coverage": block_coverage,
    "compare-rel": block_compare_rel,
    "compare-side": block_compare_side,
    "synth-pow": block_synth_pow,
    "accuracy-pow": block_accuracy_pow,
    "tables-excerpt": block_tables_excerpt,
    "render-stats": block_render_stats,
    "accuracy": block_accuracy,
    "fig8": block_fig8,
    "fig11-waves": block_fig11_waves,
    "synth-table": block_synth_table,
    "bench-stream": block_bench_stream,
    "bench-lanes": block_bench_lanes,
})


def process(path, facts, problems, stale):
    """Returns (old text, new text); hard problems go to `problems`, stale marks to `stale`."""
    text = open(path, encoding="utf-8").read()
    rel = os.path.relpath(path, ROOT)

    def inline(m):
        key, spec, old = m.group(1).strip(), m.group(2), m.group(3)
        try:
            new = fmt(facts.get(key), spec)
        except DocError as e:
            problems.append("%s: %s" % (rel, e))
            return m.group(0)
        except (KeyError, TypeError, ValueError) as e:
            problems.append("%s: fact %s: %r" % (rel, key, e))
            return m.group(0)
        if new != old:
            stale.append("%s: %s is %s in the document, %s now" % (rel, key, old, new))
        return "<!--v:%s%s-->%s<!--/v-->" % (m.group(1), ("|" + spec) if spec is not None else "", new)

    def block(m):
        name, old = m.group(2), m.group(3)
        if name not in BLOCKS:
            problems.append("%s: unknown block %s" % (rel, name))
            return m.group(0)
        try:
            new = BLOCKS[name](facts).rstrip("\n") + "\n"
        except DocError as e:
            problems.append("%s: block %s: %s" % (rel, name, e))
            return m.group(0)
        if new != old:
            stale.append("%s: block %s differs from what its command gives now" % (rel, name))
        return m.group(1) + new + m.group(4)

    fence, para = False, ""   # a mark inside a fenced block or an inline code span would show as text
    for no, line in enumerate(text.splitlines(), 1):
        if line.startswith("```"):
            fence, para = not fence, ""
            continue
        para = "" if not line.strip() or line.startswith("|") else para
        for m in re.finditer(r"<!--v:", line):
            if fence or (para + line[:m.start()]).count("`") % 2:
                problems.append("%s:%d: a mark inside code shows as text where the markdown is rendered" % (rel, no))
        para += line + "\n"
    new_text = INLINE.sub(inline, text)
    new_text = BLOCK.sub(block, new_text)
    for m in ERROR_TEXT.finditer(new_text):
        line = new_text.count("\n", 0, m.start()) + 1
        problems.append("%s:%d: a tool's error text in the document: %r" % (rel, line, m.group(0)))
    return text, new_text


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    g = ap.add_mutually_exclusive_group(required=True)
    g.add_argument("--update", action="store_true")
    g.add_argument("--check", action="store_true")
    ap.add_argument("files", nargs="*")
    a = ap.parse_args()
    files = a.files or ([os.path.join(ROOT, "README.md")] + sorted(glob.glob(os.path.join(ROOT, "docs", "*.md"))) +
                        sorted(glob.glob(os.path.join(ROOT, "boards", "*", "README.md"))))
    facts = Facts(os.path.abspath(a.build))
    problems, stale = [], []
    marks = 0
    for path in files:
        old, new = process(path, facts, problems, stale)
        marks += len(INLINE.findall(old)) + len(BLOCK.findall(old))
        if a.update and new != old:
            with open(path, "w", encoding="utf-8") as fh:
                fh.write(new)
            print("docgen: updated %s" % os.path.relpath(path, ROOT))
    if a.check:
        problems += stale
    if problems:
        for p in problems:
            print("docgen: " + p, file=sys.stderr)
        print("docgen: %d problem(s); run 'make docs' (and the make target that writes docs/data/*.json) and commit"
              % len(problems), file=sys.stderr)
        return 1
    print("docgen: %d marks in %d documents are %s" % (marks, len(files), "updated" if a.update else "current"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
