#!/usr/bin/env python3
"""Replaces the Fig. 11 diagram block in docs/interface.md with docs/fig11-timing.txt (make docs)."""
import re
import sys

iface, diagram = sys.argv[1], sys.argv[2]
text = open(iface, encoding="utf-8").read()
new = open(diagram, encoding="utf-8").read().rstrip("\n")
pattern = re.compile(r"```\nFig\. 11 run.*?\n```", re.S)
if not pattern.search(text):
    sys.exit("embed_diagram: no Fig. 11 block in " + iface)
open(iface, "w", encoding="utf-8").write(pattern.sub(lambda m: "```\n" + new + "\n```", text, count=1))
