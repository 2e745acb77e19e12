#!/usr/bin/env python3
"""coverage.py - line and toggle coverage per RTL file from Verilator coverage files (make coverage).

usage: coverage.py [--root DIR] [--annotate DIR] [--goal PCT] [--uncovered] [--markdown] COVERAGE_DIR_OR_FILES...

Reads the coverage-*.dat / cov-*.dat files the coverage build's test binary wrote (one per Verilated model
instance, see tests/coverage/), adds up each coverage point over every model and instance (a line of
spec_delay.v counts as covered when any instance of any model ran it), and prints per RTL file:
  line    Verilator's line coverage points (statement blocks and both arms of every if/case) hit / total
  toggle  signal bits that toggled / total signal bits
With --uncovered it lists every line point that was never hit (file:line and what it is). With --annotate
it also runs `verilator_coverage --annotate DIR` on the merged data (sources with counts beside each line).
With --goal PCT the exit code is 1 when a file's line coverage is below PCT (files named with --allow are
exempt: their uncovered lines are explained in docs/verification.md). --json also records each RTL file's git
blob hash (`git hash-object`), so that the documents can say which files changed after the run.
"""
import argparse
import collections
import glob
import hashlib
import os
import shutil
import subprocess
import sys


def read_points(paths):
    points = collections.Counter()
    for p in paths:
        with open(p, encoding="utf-8", errors="replace") as f:
            for line in f:
                if not line.startswith("C '"):
                    continue
                body, _, count = line.rstrip("\n").rpartition("' ")
                kv = {}
                for item in body[3:].split("\x01"):
                    if "\x02" in item:
                        k, v = item.split("\x02", 1)
                        kv[k] = v
                page = kv.get("page", "").split("/")[0]
                key = (kv.get("f", "?"), int(kv.get("l", "0")), kv.get("n", ""), page, kv.get("o", ""))
                points[key] += int(count)
    return points


# RTL files with no signal and no statement of their own: nothing to cover (not a model that never ran)
NO_LOGIC = {
    "spec_param_check.v": "elaboration-time parameter rules only (a missing module when a rule is broken)",
    "spec_desc_check.v": "elaboration-time descriptor-field rules only (a missing module when a rule is broken)",
}


def blob_hash(path):
    """The file's git blob hash (what `git hash-object PATH` prints)."""
    with open(path, "rb") as fh:
        body = fh.read()
    return hashlib.sha1(b"blob %d\0" % len(body) + body).hexdigest()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("inputs", nargs="+")
    ap.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    ap.add_argument("--rtl", default="rtl", help="RTL directory under --root (files reported)")
    ap.add_argument("--annotate", default="")
    ap.add_argument("--goal", type=float, default=None)
    ap.add_argument("--allow", default="", help="comma-separated files exempt from --goal")
    ap.add_argument("--uncovered", action="store_true")
    ap.add_argument("--markdown", action="store_true")
    ap.add_argument("--json", default="", help="also write the per-file counts as JSON (docs/data/coverage.json)")
    a = ap.parse_args()

    files = []
    for i in a.inputs:
        if os.path.isdir(i):
            files += sorted(glob.glob(os.path.join(i, "*.dat")))
        elif os.path.isfile(i):
            files.append(i)
        else:
            print("coverage: no such file or directory: %s" % i, file=sys.stderr)
            return 2
    if not files:
        print("coverage: no coverage data in %s (did the coverage build's tests run?)" % " ".join(a.inputs),
              file=sys.stderr)
        return 2
    points = read_points(files)

    rtl_dir = os.path.join(a.root, a.rtl)
    rtl_files = sorted(os.path.basename(p) for p in glob.glob(os.path.join(rtl_dir, "*.v")))
    per = {f: {"line": [0, 0], "toggle": [0, 0], "miss": []} for f in rtl_files}
    for (fname, line, col, page, comment), count in points.items():
        base = os.path.basename(fname)
        if base not in per or os.path.abspath(os.path.dirname(fname)) != os.path.abspath(rtl_dir):
            continue
        kind = "toggle" if page == "v_toggle" else "line"
        per[base][kind][1] += 1
        if count > 0:
            per[base][kind][0] += 1
        elif kind == "line":
            per[base]["miss"].append((line, col, comment))

    def pct(hit, tot):
        return 100.0 * hit / tot if tot else None

    allow = set(x for x in a.allow.split(",") if x)
    below = []
    if a.markdown:
        print("| RTL file | line coverage | toggle coverage |")
        print("|---|---|---|")
    else:
        print("%-20s %18s %20s" % ("RTL file", "line", "toggle"))
    tot_l = [0, 0]
    tot_t = [0, 0]
    nodata = []
    for f in rtl_files:
        l, t = per[f]["line"], per[f]["toggle"]
        tot_l = [tot_l[0] + l[0], tot_l[1] + l[1]]
        tot_t = [tot_t[0] + t[0], tot_t[1] + t[1]]
        pl, pt = pct(*l), pct(*t)
        ls = "%6.1f %% (%d/%d)" % (pl, l[0], l[1]) if pl is not None else "no statements" if pt is not None \
            else "no logic" if f in NO_LOGIC else "NO DATA"
        ts = "%6.1f %% (%d/%d)" % (pt, t[0], t[1]) if pt is not None else "-"
        if a.markdown:
            print("| `%s` | %s | %s |" % (f, ls.replace("  ", " ").strip(), ts.strip()))
        else:
            print("%-20s %18s %20s" % (f, ls, ts))
        if a.goal is not None and f not in allow and pl is not None and pl < a.goal:
            below.append(f)
        if a.goal is not None and pl is None and pt is None and f not in NO_LOGIC:
            nodata.append(f)   # no point at all: its model never wrote coverage (not "no statements")
    if a.markdown:
        print("| all | %.1f %% (%d/%d) | %.1f %% (%d/%d) |" % (pct(*tot_l), tot_l[0], tot_l[1], pct(*tot_t),
                                                            tot_t[0], tot_t[1]))
    else:
        print("%-20s %18s %20s" % ("all", "%6.1f %% (%d/%d)" % (pct(*tot_l), *tot_l),
                                   "%6.1f %% (%d/%d)" % (pct(*tot_t), *tot_t)))
    if a.uncovered:
        print("\nline points never hit:")
        for f in rtl_files:
            for line, col, comment in sorted(per[f]["miss"]):
                print("  %s:%d (column %s): %s" % (f, line, col, comment))
    print("(%d coverage files from %s)" % (len(files), ", ".join(a.inputs)))

    if a.annotate:
        vc = shutil.which("verilator_coverage")
        if vc:
            merged = os.path.join(a.annotate, "merged.dat")
            os.makedirs(a.annotate, exist_ok=True)
            subprocess.run([vc, "--write", merged] + files, check=True, stdout=subprocess.DEVNULL)
            subprocess.run([vc, "--annotate", a.annotate, "--annotate-min", "1", merged], check=True,
                           stdout=subprocess.DEVNULL)
            print("annotated sources: %s (lines marked %%000000 never ran)" % a.annotate)
    if nodata:
        print("coverage: no coverage data at all for %s (did its model's final() run?)" % ", ".join(nodata),
              file=sys.stderr)
    if below:
        print("coverage: line coverage below %.0f %% in %s" % (a.goal, ", ".join(below)), file=sys.stderr)
    if a.json and not nodata:   # what was measured, met or not (the documents show the files below the goal)
        import json
        import time
        with open(a.json, "w") as fh:
            json.dump({"date": time.strftime("%Y-%m-%d"), "goal_line_pct": a.goal, "below_goal": below,
                       "files": {f: {"line": per[f]["line"], "toggle": per[f]["toggle"],
                                     "blob": blob_hash(os.path.join(rtl_dir, f))} for f in rtl_files},
                       "all": {"line": tot_l, "toggle": tot_t}, "coverage_files": len(files)}, fh, indent=1)
            fh.write("\n")
    return 1 if below or nodata else 0


if __name__ == "__main__":
    sys.exit(main())
