#!/usr/bin/env python3
"""rom_check.py - the ROM-image checks of rtl/spec_rom*.v for flows that do not simulate (synthesis, formal).

Simulators run the checks in the RTL at time 0; Yosys defines SYNTHESIS and skips them, and its $readmemh only
warns about an image that does not fit. So every synthesis flow of the project calls this first: it reads the
core's parameters (the defaults of a spec_params.vh, overridden by -G NAME=VALUE as the flow passes them) and
fails, naming the file and what differs, when
  - an image cannot be read,
  - its first line is not specrom's, or names other parameters than the core's (a pow mode image in a core with
    POW = 0, or the other way round, is named as such),
  - it holds another number of words than the ROM has, or a word wider than the ROM's words.

usage: rom_check.py --header rom/spec_params.vh --rom9 F --rom12 F [-G NAME=VALUE ...]
exit 0: the images fit; 2: they do not (one line on stderr: the first problem and how many more).
"""
import argparse
import re
import sys

HEAD9 = re.compile(r"^// specrom ROM 9: n_w=(\d+) scale_w=(\d+) scale_frac=(\d+) decoder_rom=(\d+) tsel_w=(\d+)")
HEAD12 = re.compile(r"^// specrom ROM 12: tbl_aw=(\d+) tsel_w=(\d+) tbl_frac=(\d+) interp=(\d+) delta_w=(\d+)")
# pow mode's images (docs/pow.md): the log table (ROM 9) and the exp2 table (ROM 12)
HEAD9_POW = re.compile(r"^// specrom ROM 9 pow: ang_frac=(\d+) half_pi=(\d+) seg_w=(\d+) idx_w=(\d+) val_w=(\d+) "
                       r"dlt_w=(\d+) sh_w=(\d+) xb=(\d+)")
HEAD12_POW = re.compile(r"^// specrom ROM 12 pow: tbl_aw=(\d+) tbl_frac=(\d+) interp=(\d+) delta_w=(\d+)")


def header_params(path):
    """The SPEC_* integer macros of a generated spec_params.vh, without the prefix."""
    params = {}
    with open(path) as f:
        for line in f:
            m = re.match(r"^`define SPEC_([A-Z0-9_]+) (-?\d+)\b", line)
            if m:
                params[m.group(1)] = int(m.group(2))
    return params


def read_image(path):
    """(first line, words) of a $readmemh image; raises ValueError on a line that is not a word or comment."""
    with open(path) as f:
        lines = f.read().splitlines()
    words = []
    for i, line in enumerate(lines, 1):
        t = line.strip()
        if not t or t.startswith("//"):
            continue
        tok = t.split("//")[0].strip()
        if not re.fullmatch(r"[0-9a-fA-F]+", tok):
            raise ValueError("line %d is not a hex word or a // comment" % i)
        words.append(tok)
    return (lines[0] if lines else ""), words


def check_words(path, words, depth, width, problems):
    if len(words) != depth:
        problems.append("%s holds %d words, but the ROM has %d: the image was made for other parameters"
                        % (path, len(words), depth))
    digits = (width + 3) // 4
    for i, w in enumerate(words):
        if len(w) > digits or int(w, 16) >> width:
            problems.append("%s word %d (%s) is wider than the ROM's %d bits: the image was made for other "
                            "parameters" % (path, i, w, width))
            break


def check(p, rom9, rom12):
    """Problems (strings) of the two images against the parameter dict p (C_W ... TSEL_W, POW ...)."""
    problems = []
    dec = p["DECODER_ROM"] != 0
    pow_mode = p.get("POW", 0) != 0
    if pow_mode:
        roms = (
            (rom9, HEAD9_POW,
             [("ANG_FRAC", p["ANG_FRAC"]), ("POW_K", p["POW_K"]), ("POW_SEG_W", p["POW_SEG_W"]),
              ("POW_IDX_W", p["POW_IDX_W"]), ("POW_VAL_W", p["POW_VAL_W"]), ("POW_DLT_W", p["POW_DLT_W"]),
              ("POW_SH_W", p["POW_SH_W"]), ("POW_XB", p["POW_XB"])],
             1 << (1 + p["POW_SEG_W"] + p["POW_IDX_W"]), p["POW_SH_W"] + 1 + p["POW_DLT_W"] + p["POW_VAL_W"]),
            (rom12, HEAD12_POW,
             [("TBL_AW", p["TBL_AW"]), ("TBL_FRAC", p["TBL_FRAC"]), ("INTERP", int(p["INTERP"] != 0)),
              ("DELTA_W", p["DELTA_W"] if p["INTERP"] else None)],
             1 << p["TBL_AW"], p["TBL_FRAC"] + 1 + (p["DELTA_W"] if p["INTERP"] else 0)),
        )
    else:
        roms = (
            (rom9, HEAD9,
             [("N_W", p["N_W"]), ("SCALE_W", p["SCALE_W"]), ("SCALE_FRAC", p["SCALE_FRAC"]),
              ("DECODER_ROM", int(dec)), ("TSEL_W", p["TSEL_W"] if dec else None)],
             1 << p["N_W"], p["SCALE_W"] + (p["TSEL_W"] if dec else 0)),
            (rom12, HEAD12,
             [("TBL_AW", p["TBL_AW"]), ("TSEL_W", p["TSEL_W"]), ("TBL_FRAC", p["TBL_FRAC"]),
              ("INTERP", int(p["INTERP"] != 0)), ("DELTA_W", p["DELTA_W"] if p["INTERP"] else None)],
             1 << (p["TBL_AW"] + p["TSEL_W"]), p["TBL_FRAC"] + 1 + (p["DELTA_W"] if p["INTERP"] else 0)),
        )
    for path, head, expect, depth, width in roms:
        try:
            first, words = read_image(path)
        except OSError as e:
            problems.append("cannot read ROM image %s: %s" % (path, e.strerror))
            continue
        except ValueError as e:
            problems.append("ROM image %s: %s" % (path, e))
            continue
        m = head.match(first)
        if not m and not pow_mode and re.match(r"^// specrom ROM \d+ pow:", first):
            problems.append("ROM image %s was made for pow mode (specrom --mode pow), but the core has POW=0" % path)
        elif not m and pow_mode and re.match(r"^// specrom ROM \d+:", first):
            problems.append("ROM image %s was made for patent or tuned mode, but the core has POW=1" % path)
        elif not m:
            problems.append("ROM image %s does not start with specrom's header line; make it with specrom" % path)
        else:
            got = [int(g) for g in m.groups()]
            for (name, want), have in zip(expect, got):
                if want is not None and want != have:
                    problems.append("ROM image %s was made for %s=%d, the core has %s=%d"
                                    % (path, name, have, name, want))
        check_words(path, words, depth, width, problems)
    return problems


def main():
    ap = argparse.ArgumentParser(description="check ROM images against the core's parameters")
    ap.add_argument("--header", required=True, help="spec_params.vh with the parameters' defaults")
    ap.add_argument("--rom9", required=True)
    ap.add_argument("--rom12", required=True)
    ap.add_argument("-G", action="append", default=[], metavar="NAME=VALUE", help="a parameter override")
    a = ap.parse_args()
    try:
        p = header_params(a.header)
    except OSError as e:
        print("rom_check: cannot read %s: %s" % (a.header, e.strerror), file=sys.stderr)
        return 2
    for g in a.G:
        m = re.fullmatch(r"([A-Z0-9_]+)=(-?\d+)", g)
        if not m:
            continue  # string parameters (file names) are not checked here
        p[m.group(1)] = int(m.group(2))
    missing = [k for k in ("N_W", "SCALE_W", "SCALE_FRAC", "DECODER_ROM", "TSEL_W", "TBL_AW", "TBL_FRAC",
                           "INTERP", "DELTA_W") if k not in p]
    if missing:
        print("rom_check: %s does not define %s" % (a.header, ", ".join(missing)), file=sys.stderr)
        return 2
    problems = check(p, a.rom9, a.rom12)
    if problems:
        more = " (and %d more problems)" % (len(problems) - 1) if len(problems) > 1 else ""
        print("rom_check: " + problems[0] + more, file=sys.stderr)
    return 2 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
