#!/usr/bin/env python3
"""filelist_check.py ROOT - the core's one file list, rtl/spec_core.f, is the list everything reads.

Fails (exit 1, one line per problem) when a listed file does not exist, when the FuseSoC core's rtl fileset
(ua71489_spec.core, which FuseSoC needs written out) differs from the list or its order, or when a module file
rtl/spec_*.v is in neither the core's list nor another rtl/*.f list (a new module someone forgot to list).
"""
import glob
import os
import re
import sys


def read_list(path):
    with open(path) as f:
        return [line.strip() for line in f if line.strip()]


def main():
    root = sys.argv[1]
    problems = []
    core = read_list(os.path.join(root, "rtl", "spec_core.f"))
    for name in core:
        if not os.path.isfile(os.path.join(root, "rtl", name)):
            problems.append("rtl/spec_core.f lists %s, which does not exist" % name)
    text = open(os.path.join(root, "ua71489_spec.core")).read()
    m = re.search(r"^  rtl:\n    files:\n((?:      - .*\n)+)", text, re.M)
    if not m:
        problems.append("ua71489_spec.core has no rtl fileset")
    else:
        listed = [l.strip()[2:] for l in m.group(1).splitlines()]
        rtl = [l[len("rtl/"):] for l in listed if l.startswith("rtl/")]
        if rtl != core:
            problems.append("ua71489_spec.core's rtl files %s differ from rtl/spec_core.f %s" % (rtl, core))
    others = set()
    for f in glob.glob(os.path.join(root, "rtl", "*.f")):
        if os.path.basename(f) != "spec_core.f":
            others.update(read_list(f))
    for path in sorted(glob.glob(os.path.join(root, "rtl", "spec_*.v"))):
        name = os.path.basename(path)
        if name not in core and name not in others:
            problems.append("rtl/%s is in no file list (rtl/spec_core.f or another rtl/*.f)" % name)
    for p in problems:
        print("filelist_check: " + p)
    if problems:
        return 1
    print("filelist_check: rtl/spec_core.f (%d files) and ua71489_spec.core agree" % len(core))
    return 0


if __name__ == "__main__":
    sys.exit(main())
