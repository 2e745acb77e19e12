#!/usr/bin/env python3
"""methods_doc.py - the tables of docs/methods.md (and README.md) come from specsim highlight, normalize and
parallax (--tables FILE writes them as named blocks); `make methods` embeds them, ctest methods_doc_tables checks
that the documents carry what the commands print now.

Usage: methods_doc.py embed|check DOC [DOC ...] -- TABLES [TABLES ...]
       methods_doc.py synth DOC SYNTH_JSON     (the doc's make-synth row of that run's target and top: LUT, FF,
                                                BRAM and DSP must equal the JSON's; ctest methods_synth_cells)

A block in a document is
    <!-- methods:NAME -->
    ...
    <!-- /methods:NAME -->
and is replaced by (embed) or compared with (check) the block of the same name in the TABLES files. Every block
a document has must be among the generated ones: a block the commands no longer print is an error.
"""
import difflib
import re
import sys

BLOCK = re.compile(r"<!-- methods:([a-z0-9-]+) -->\n(.*?)<!-- /methods:\1 -->\n", re.S)


def blocks(text):
    return {m.group(1): m.group(2) for m in BLOCK.finditer(text)}


def synth(doc, js):
    import json
    r = json.load(open(js))
    text = open(doc, encoding="utf-8").read()
    m = re.search(r"<!-- synth:%s -->\n(.*?)<!-- /synth:%s -->" % (r["top"], r["top"]), text, re.S)
    if not m:
        print("methods_doc: %s has no <!-- synth:%s --> block" % (doc, r["top"]), file=sys.stderr)
        return 1
    for line in m.group(1).splitlines():
        cells = [c.strip() for c in line.strip("|").split("|")]
        if len(cells) >= 7 and cells[0] == r["target"] and cells[1] == r["top"]:
            want = [str(r[k]) for k in ("lut", "ff", "bram", "dsp")]
            if cells[3:7] != want:
                print("methods_doc: %s: %s %s row says LUT/FF/BRAM/DSP %s, synthesis gives %s (run 'make synth' and "
                      "update the row)" % (doc, r["target"], r["top"], "/".join(cells[3:7]), "/".join(want)))
                return 1
            print("methods_doc: %s %s cells as in %s: %s" % (r["target"], r["top"], doc, "/".join(want)))
            return 0
    print("methods_doc: %s has no %s %s row" % (doc, r["target"], r["top"]), file=sys.stderr)
    return 1


def main(argv):
    if len(argv) == 3 and argv[0] == "synth":
        return synth(argv[1], argv[2])
    if len(argv) < 4 or argv[0] not in ("embed", "check") or "--" not in argv:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    mode = argv[0]
    sep = argv.index("--")
    docs, tables = argv[1:sep], argv[sep + 1:]
    generated = {}
    for t in tables:
        for name, body in blocks(open(t, encoding="utf-8").read()).items():
            if name in generated:
                print("methods_doc: block %s generated twice" % name, file=sys.stderr)
                return 1
            generated[name] = body
    bad = 0
    for d in docs:
        text = open(d, encoding="utf-8").read()
        have = blocks(text)
        if not have:
            print("methods_doc: %s has no <!-- methods:NAME --> blocks" % d, file=sys.stderr)
            bad += 1
            continue
        for name, body in have.items():
            if name not in generated:
                print("methods_doc: %s: block %s is not printed by the commands any more" % (d, name), file=sys.stderr)
                bad += 1
            elif body != generated[name] and mode == "check":
                print("methods_doc: %s: block %s differs from what the commands print now (run 'make methods'):" % (d, name))
                sys.stdout.writelines(difflib.unified_diff(body.splitlines(True), generated[name].splitlines(True),
                                                           d + " (" + name + ")", "now", n=1))
                bad += 1
        if mode == "embed" and not bad:
            new = BLOCK.sub(lambda m: "<!-- methods:%s -->\n%s<!-- /methods:%s -->\n"
                            % (m.group(1), generated[m.group(1)], m.group(1)), text)
            if new != text:
                open(d, "w", encoding="utf-8").write(new)
                print("methods_doc: %s updated" % d)
    if mode == "check" and not bad:
        print("methods_doc: %s carry the tables the commands print now" % ", ".join(docs))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
