"""docgen_shader.py - scripts/docgen.py's facts and blocks for spec_setup / spec_shader (issue 13, docs/setup.md).

Facts: setup_cfg.NAME (rom/setup_params.h, the ecp5 configuration's), setup_race_cfg.NAME (rom/race/setup_params.h:
the racing design's machine, setuprom --format race), setup_small_cfg.NAME
(rom/setup_small_params.h, the up5k configuration's), render_shader.* (the default scene through the Verilated
spec_shader: its statistics JSON), shader_latency.ecp5|up5k (`specsim shader-diagram`), setup_acc.ecp5|up5k.*
(`specsim setup-accuracy --json`: worst, spans, widened, share, eps_log2). Blocks: setup-accuracy[-up5k],
setup-accuracy-summary[-up5k] (`specsim setup-accuracy`), shader-diagram, bench-shader (docs/data/bench_shader.json),
synth-shader (docs/data/synth_shader.json).
"""
import json
import os
import re
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HEADS = ("setup_cfg", "setup_race_cfg", "setup_small_cfg", "render_shader", "shader_latency", "setup_acc")


class DocError(Exception):
    """A fact or block that cannot be made (scripts/docgen.py reports it)."""


def setup_header(f, name="setup_params.h", sub=""):
    """rom/[SUB/]setup_params.h or rom/setup_small_params.h (setuprom; tests/setup_rom_check.cmake keeps them
    current): a setup's formats, beat layout, schedule."""
    def make():
        vals = {}
        text = open(os.path.join(ROOT, "rom", sub, name)).read()
        for m in re.finditer(r"constexpr (?:long long|int) (\w+) = (-?\d+);", text):
            vals[m.group(1)] = int(m.group(2))
        return vals
    return f.once("setup_header." + os.path.join(sub, name), make)


def render_shader(f):
    """The default scene at 512 x 512 through the Verilated spec_shader (setup in RTL too): the statistics JSON."""
    def make():
        d = tempfile.mkdtemp(prefix="docgen_")
        stats = os.path.join(d, "stats.json")
        f.run([f.specsim, "render", "--scene", "default", "--size", "512", "--model", "shader", "--quiet",
                  "--out", os.path.join(d, "r.png"), "--stats", stats])
        return json.load(open(stats))
    return f.once("render_shader", make)


def setup_accuracy(f, config="ecp5"):
    """`specsim setup-accuracy --config C` (the shader's pixels against the host's double-precision setup): its
    text and its JSON."""
    def make():
        d = tempfile.mkdtemp(prefix="docgen_")
        js = os.path.join(d, "acc.json")
        text = f.run([f.specsim, "setup-accuracy", "--config", config, "--json", js])
        return {"text": text, "json": json.load(open(js))}
    return f.once("setup_accuracy." + config, make)


def shader_diagram(f, config):
    """`specsim shader-diagram`: the text and the latency in clocks."""
    def make():
        out = f.run([f.specsim, "shader-diagram", "--config", config])
        m = re.search(r"latency: (\d+) clocks", out)
        if not m:
            raise DocError("specsim shader-diagram printed no latency")
        return {"text": out, "latency": int(m.group(1))}
    return f.once("shader_diagram." + config, make)


def get(f, head, parts, key):
    if head == "setup_cfg":
        return setup_header(f)[parts[1]]
    if head == "setup_race_cfg":
        return setup_header(f, sub="race")[parts[1]]
    if head == "setup_small_cfg":
        return setup_header(f, "setup_small_params.h")[parts[1]]
    if head == "setup_acc":   # setup_acc.ecp5|up5k.worst|spans|widened|share|eps_log2
        obj = setup_accuracy(f, parts[1])["json"]
        if len(parts) < 3 or parts[2] not in obj:
            raise DocError("unknown fact %s" % key)
        return obj[parts[2]]
    if head == "render_shader":
        obj = render_shader(f)
        for p in parts[1:]:
            if not isinstance(obj, dict) or p not in obj:
                raise DocError("unknown fact %s (no '%s')" % (key, p))
            obj = obj[p]
        return obj
    if head == "shader_latency":   # shader_latency.ecp5|up5k: clocks from a beat to its first pixel
        return shader_diagram(f, parts[1])["latency"]
    raise DocError("unknown fact %s" % key)


def block_setup_accuracy(f, config="ecp5"):
    return "\n".join(l for l in setup_accuracy(f, config)["text"].splitlines() if l.startswith("|"))


def block_setup_accuracy_summary(f, config="ecp5"):
    return next(l for l in setup_accuracy(f, config)["text"].splitlines() if l.startswith("worst error / bound"))


def block_shader_diagram(f):
    return "```\n" + shader_diagram(f, "ecp5")["text"].rstrip("\n") + "\n```"


def block_bench_shader(f):
    b = f.data("bench_shader")
    out = ["| configuration | stream | beats | pixels a beat | clocks | clocks a span |", "|---|---|---|---|---|---|"]
    for r in b["clocks_a_span"]:
        out.append("| %s | %s | %d | %.2f | %d | %.2f |" % (r["config"], r["stream"], r["spans"], r["pixels"] / r["spans"],
                                                          r["cycles"], r["clocks_a_span"]))
    out += ["", "| image (ecp5) | spans | pixels | pixels a span | spec_shader clocks | spec_shader pixels per clock | "
            "spec_stream alone, pixels per clock | shader / stream alone |", "|---|---|---|---|---|---|---|---|"]
    for r in b["scenes"]:
        sp, st = r["pixels"] / r["shader_cycles"], r["pixels"] / r["stream_cycles"]
        out.append("| %s | %d | %d | %.2f | %d | %.4f | %.4f | %.4f |" % (
            r["image"].replace("x", " × "), r["spans"], r["pixels"], r["pixels"] / r["spans"], r["shader_cycles"],
            sp, st, sp / st))
    return "\n".join(out)


def block_synth_shader(f):
    d = f.data("synth_shader")
    out = ["| target | configuration | LUT4 | FF | logic cells (iCE40) or slice halves (ECP5), of the device's | "
           "BRAM | DSP | Fmax (MHz) | goal (MHz) | fits | goal met |", "|" + "---|" * 11]
    # the seeds most rows were placed with (the file's own field is the last run's); a row placed with others
    # says so beside its Fmax
    placed = [tuple(r["seeds"]) for r in d["results"] if r.get("seeds") and r.get("fmax_mhz") is not None]
    seeds = list(max(placed, key=placed.count)) if placed else (d.get("seeds") or [d["seed"]])
    for r in d["results"]:
        if r.get("pnr_skipped"):
            fm = "not placed: %s" % r["pnr_skipped"]
        elif r.get("pnr_error"):
            fm = "placement failed"
        else:
            fm = "-" if r.get("fmax_mhz") is None else "%.1f" % r["fmax_mhz"]
            if r.get("seeds") and r["seeds"] != seeds and r.get("fmax_mhz") is not None:
                fm += " (seed%s %s)" % ("s" if len(r["seeds"]) > 1 else "", ", ".join(map(str, r["seeds"])))
        # nextpnr's packed logic cells (iCE40) or slice halves (ECP5, --pack-only) against the device's count
        # (syn/synth.py LIMITS)
        ice = r["target"].startswith("ice40")
        n = r.get("lc") if ice else r.get("comb_packed")
        cells = "-" if n is None else "%d of %d" % (n, f.get("src.synth.LIMITS.%s.%s" % (r["target"], "lut" if ice else "comb")))
        out.append("| %s | %s | %d | %d | %s | %d | %d | %s | %s | %s | %s |" % (
            r["target"], r["config"], r["lut"], r["ff"], cells, r["bram"],
            r["dsp"], fm, "-" if r.get("goal_mhz") is None else "%.1f" % r["goal_mhz"], "yes" if r["fits"] else "no",
            "-" if r.get("goal_mhz") is None else ("yes" if r["met"] else "no")))
    out.append("")
    out.append("(`make synth` on %s, placement seed%s %s%s.)" % (
        d["date"], "s" if len(seeds) > 1 else "", ", ".join(map(str, seeds)), "; Fmax the worst" if len(seeds) > 1 else ""))
    return "\n".join(out)


BLOCKS = {
    "setup-accuracy": block_setup_accuracy,
    "setup-accuracy-summary": block_setup_accuracy_summary,
    "setup-accuracy-up5k": lambda f: block_setup_accuracy(f, "up5k"),
    "setup-accuracy-summary-up5k": lambda f: block_setup_accuracy_summary(f, "up5k"),
    "shader-diagram": block_shader_diagram,
    "bench-shader": block_bench_shader,
    "synth-shader": block_synth_shader,
}
