#!/usr/bin/env python3
"""Replaces the Fig. 11 diagram block in a markdown file with docs/fig11-timing.txt (make docs).

Usage: embed_diagram.py FILE.md DIAGRAM [full|waves]   (waves: only the ruler and signal rows)"""
import re
import sys

iface, diagram = sys.argv[1], sys.argv[2]
mode = sys.argv[3] if len(sys.argv) > 3 else "full"
text = open(iface, encoding="utf-8").read()
new = open(diagram, encoding="utf-8").read().rstrip("\n")
if mode == "waves":
    lines = new.split("\n")
    new = "\n".join(l for l in lines if l.startswith("    ") or l[:1].isalpha() and " " in l and l.split()[-1][:1] in "_\u203e"
                    or l.startswith("              "))
    pattern = re.compile(r"```\n {14}0.*?\n```", re.S)
else:
    # the block that starts with the diagram's first word ("Fig." or "spec_stream:")
    pattern = re.compile(r"```\n" + re.escape(new.split()[0]) + r" .*?\n```", re.S)
if not pattern.search(text):
    sys.exit("embed_diagram: no block for %s in %s" % (diagram, iface))
open(iface, "w", encoding="utf-8").write(pattern.sub(lambda m: "```\n" + new + "\n```", text, count=1))
