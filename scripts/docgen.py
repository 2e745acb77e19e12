#!/usr/bin/env python3
"""docgen.py - the numbers in README.md and docs/*.md come from commands, and a ctest keeps them current.

usage: docgen.py --build BUILD (--update | --check) [FILE.md ...]       (default: README.md, docs/*.md)

Two kinds of marks in a markdown file (HTML comments: invisible where the markdown is rendered):

  <!--v:KEY-->TEXT<!--/v-->          an inline value: TEXT is the fact KEY, formatted (KEY|FMT: a %-format
                                      such as %.1f, or a format named in FORMATS)
  <!-- gen:NAME -->                  a block: every line up to the end mark is what BLOCKS[NAME] makes
  ...
  <!-- /gen:NAME -->

Facts come from the running code: the generated headers (cfg.*, cfg_up5k.*), the bit-exact model's accuracy run
(accuracy.*), the render of the default scene through the Verilated core (render.*), and from the measurements
the optional targets write into docs/data/*.json (data.<file>.*: `make synth`, `make bench`, `make coverage`,
`make formal` update those files; the check compares the documents with them, it does not rerun synthesis).

--update rewrites the marks in place (make docs); --check (the ctest docs_current) fails, listing every stale
mark, when a document differs from what the commands give now, or when a document holds a tool's error text
(a shell's "No such file or directory", a Python traceback, ...), or a mark names an unknown fact or block.
"""
import argparse
import glob
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

INLINE = re.compile(r"<!--v:([^>|]+?)(?:\|([^>]*?))?-->(.*?)<!--/v-->", re.S)
BLOCK = re.compile(r"(<!-- gen:([\w.-]+) -->\n)(.*?)(<!-- /gen:\2 -->)", re.S)
ERROR_TEXT = re.compile(r"No such file or directory|command not found|Traceback \(most recent call last\)|"
                        r"^bash: |Segmentation fault|core dumped|^%Error|CMake Error|^make: \*\*\*", re.M)


class DocError(Exception):
    pass


class Facts:
    """Lazily computed facts; each provider runs once."""

    def __init__(self, build):
        self.build = build
        self.cache = {}
        self.specsim = os.path.join(build, "specsim")
        self.specrom = os.path.join(build, "specrom")

    def run(self, cmd):
        p = subprocess.run(cmd, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
        if p.returncode != 0:
            raise DocError("%s failed (exit %d): %s" % (" ".join(cmd), p.returncode, p.stderr.strip()[-300:]))
        return p.stdout

    def once(self, name, fn):
        if name not in self.cache:
            self.cache[name] = fn()
        return self.cache[name]

    # ---- providers --------------------------------------------------------------------------------------------
    def header(self, config):
        def make():
            if config == "default":
                path = os.path.join(ROOT, "rom", "spec_params.h")
            else:
                d = tempfile.mkdtemp(prefix="docgen_")
                self.run([self.specrom] + (["--mode", "tuned"] if config == "tuned" else ["--config", config]) +
                         ["--out", d])
                path = os.path.join(d, "spec_params.h")
            vals = {}
            for m in re.finditer(r"constexpr int (\w+) = (-?\d+);", open(path).read()):
                vals[m.group(1)] = int(m.group(2))
            return vals
        return self.once("header." + config, make)

    def render(self, mode="patent"):
        """The default scene at 512 x 512 through the Verilated core (patent or tuned mode): the statistics JSON."""
        def make():
            d = tempfile.mkdtemp(prefix="docgen_")
            stats = os.path.join(d, "stats.json")
            self.run([self.specsim, "render", "--scene", "default", "--size", "512", "--model", "rtl", "--quiet",
                      "--mode", mode, "--out", os.path.join(d, "r.png"), "--stats", stats])
            return json.load(open(stats))
        return self.once("render." + mode, make)

    def compare(self):
        """`specsim compare`: its two tables (rel: worst relative error in the epicentre, abs: worst absolute / C),
        rows by label; and the text."""
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
            if len(tables) != 2:
                raise DocError("specsim compare printed %d tables, not 2" % len(tables))
            return {"rel": tables[0], "abs": tables[1], "text": out}
        return self.once("compare", make)

    def tables_md(self):
        """Rows of docs/tables.md (`make tables` writes it, a ctest compares it with `specsim tables --quick`)."""
        def make():
            rows = []
            for line in open(os.path.join(ROOT, "docs", "tables.md"), encoding="utf-8"):
                cells = [c.strip() for c in line.strip().strip("|").split("|")]
                if len(cells) == 9 and cells[1] in ("patent", "tuned"):
                    rows.append(cells)
            return rows
        return self.once("tables_md", make)

    def accuracy(self, config):
        def make():
            args = [self.specsim, "accuracy"] + ([] if config == "default" else ["--config", config])
            out = self.run(args)
            rows = {}
            for line in out.splitlines():
                if line.startswith("| n = "):
                    cells = [c.strip() for c in line.strip("|").split("|")]
                    rows[cells[0]] = cells
            m = re.search(r"Fixed point adds at most ([\d.]+) %.*\(n = (\d+)\)", out)
            return {"rows": rows, "added": float(m.group(1)) if m else None, "text": out}
        return self.once("accuracy." + config, make)

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
        if head == "render":
            return walk(self.render(), parts[1:], key)
        if head == "render_tuned":
            return walk(self.render("tuned"), parts[1:], key)
        if head == "compare":   # compare.rel|abs.<row slug>.<column>: the number in that cell
            return percent(self.compare()[parts[1]][parts[2]][int(parts[3])], key)
        if head == "data":
            return walk(self.data(parts[1]), parts[2:], key)
        if head in ("accuracy", "accuracy_up5k"):
            acc = self.accuracy("default" if head == "accuracy" else "up5k")
            if parts[1] == "added":
                return acc["added"]
            raise DocError("unknown fact %s" % key)
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


def walk(obj, parts, key):
    for p in parts:
        if isinstance(obj, list):
            obj = obj[int(p)]
        elif isinstance(obj, dict) and p in obj:
            obj = obj[p]
        else:
            raise DocError("unknown fact %s (no '%s')" % (key, p))
    return obj


def bad_input_rows():
    sys.path.insert(0, os.path.join(ROOT, "tests"))
    import bad_input
    return sum(1 for l in open(os.path.join(ROOT, "docs", "bad-input.md")) if bad_input.ROW.match(l.rstrip("\n")))


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
    "long_pixels": lambda f: sum(r["pixels"] for r in f.data("test_long")["runs"]),
    "long_minutes": lambda f: f.data("test_long")["seconds"] / 60.0,
    # the rows of docs/bad-input.md that tests/bad_input.py runs (its ROW pattern)
    "bad_input_rows": lambda f: bad_input_rows(),
}


def fmt(value, spec):
    if spec in (None, ""):
        if isinstance(value, float):
            return "%g" % value
        return str(value)
    if spec == "int_sep":   # 8 600 -> thin-space thousands as the documents write them
        return "{:,}".format(int(value)).replace(",", " ")
    if spec == "yesno":
        return "yes" if value else "no"
    return spec % value


# ---- blocks ------------------------------------------------------------------------------------------------
def block_render_stats(f):
    s = f.render()["against_ref"]
    rows = [("rtl", "rtl (= golden bit for bit)"), ("prototype", "prototype"),
            ("host", "host alone (its angles, exact cos^n)")]
    if "shader" in s:
        rows.insert(1, ("shader", "shader (spec_setup in RTL, then spec_stream)"))
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
    rows = f.data("synth")
    if isinstance(rows, dict):
        rows = rows.get("results", [])
    hdr = "| target | top | config | LUT | FF | BRAM | DSP | Fmax (MHz) | goal (MHz) | fits | ROMs in BRAM | goal met |"
    out = [hdr, "|" + "---|" * 12]
    for r in rows:
        out.append("| %s | %s | %s | %d | %d | %d | %d | %s | %s | %s | %s | %s |" % (
            r["target"], r["top"], r["config"], r["lut"], r["ff"], r["bram"], r["dsp"],
            "-" if r.get("fmax_mhz") is None else "%.1f" % r["fmax_mhz"],
            "-" if r.get("goal_mhz") is None else "%.1f" % r["goal_mhz"],
            "yes" if r["fits"] else "no", "no" if r.get("roms_in_logic") else "yes", "yes" if r["met"] else "no"))
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


def block_formal_steps(f):
    d = f.data("formal")
    out = ["| job | step | result | time (s) |", "|---|---|---|---|"]
    for r in d["steps"]:
        what = r["what"] + ((" (%d reached)" % r["covers"]) if r.get("covers") is not None else "")
        out.append("| %s | %s | %s | %.0f |" % (r["job"], what, "pass" if r["pass"] else "FAIL", r["seconds"]))
    out.append("")
    out.append("(`make formal` on %s, %s, 2 cores; times vary with the machine's load.)" % (d["date"], d.get("solver")))
    return "\n".join(out)


def block_formal_mutants(f):
    d = f.data("formal_mutants")
    out = ["| job | the bug (`formal/formal.py` MUTANTS) | caught by |", "|---|---|---|"]
    for m in d["mutants"]:
        if m["expected"]:
            res = "`%s`" % m["assertion"] if m.get("assertion") else "caught"
        else:
            res = "not caught, as it must not be (an equivalent change)"
        out.append("| %s | %s | %s |" % (m["job"], m["bug"], res))
    out.append("")
    out.append("(`make formal-mutants` on %s: bounded checks of %s cycles.)" % (
        d["date"], ", ".join("%s %d" % kv for kv in sorted(d["bmc_cycles"].items()))))
    return "\n".join(out)


def block_coverage(f):
    d = f.data("coverage")

    def cell(hit_tot):
        hit, tot = hit_tot
        return "%.1f %% (%d/%d)" % (100.0 * hit / tot, hit, tot) if tot else "no statements"
    out = ["| RTL file | line coverage | toggle coverage |", "|---|---|---|"]
    for name, v in sorted(d["files"].items()):
        out.append("| `%s` | %s | %s |" % (name, cell(v["line"]), cell(v["toggle"]) if v["toggle"][1] else "-"))
    out.append("| all | %s | %s |" % (cell(d["all"]["line"]), cell(d["all"]["toggle"])))
    out.append("")
    out.append("(`make coverage` on %s.)" % d["date"])
    return "\n".join(out)


# ---- the reference designs on boards (issue 15, docs/boards.md): make board-split, make bitstream -------------
def block_board_split(f):
    out = []
    for name, label in (("board_split_640x480", "640 × 480 (ULX3S)"), ("board_split_320x240", "320 × 240 (iCEBreaker)")):
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
        out = ["| mode | device | LUT | FF | BRAM | DSP | clock | constraint (MHz) | Fmax (MHz) | met |",
               "|" + "---|" * 10]
        for r in d["designs"]:
            for i, c in enumerate(r["clocks"]):
                lead = ("| %s | %s | %d | %d | %d | %d |" % (r["mode"], r.get("device", ""), r["lut"], r["ff"], r["bram"],
                                                            r["dsp"]) if i == 0 else "| | | | | | |")
                out.append("%s %s | %.2f | %.2f | %s |" % (lead, c["net"].replace("$glbnet$", ""), c["constraint_mhz"],
                                                         c["fmax_mhz"], "yes" if c["met"] else "no"))
            if not r["clocks"]:
                out.append("| %s | %s | %d | %d | %d | %d | %s | | | no |" % (r["mode"], r.get("device", ""), r["lut"],
                                                                             r["ff"], r["bram"], r["dsp"], r.get("note", "")))
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


BLOCKS = {
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
    "tables-excerpt": block_tables_excerpt,
    "render-stats": block_render_stats,
    "accuracy": block_accuracy,
    "fig8": block_fig8,
    "fig11-waves": block_fig11_waves,
    "synth-table": block_synth_table,
    "bench-stream": block_bench_stream,
}


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
