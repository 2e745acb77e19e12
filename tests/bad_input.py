#!/usr/bin/env python3
"""bad_input.py - runs every row of docs/bad-input.md (ctest bad_input_table).

usage: bad_input.py SPECSIM SPECROM SRC WORK

Each row's command (third column, in backticks) runs from an empty directory, with `specsim` / `specrom` / `setuprom`
replaced by the built programs and ${SRC} by the repository. It must exit with the code the fourth column
gives (2), write exactly one line to stderr, starting with the program's name and containing the text in
backticks in the fourth column, write nothing to stdout (unless the row says "after printing its results")
and leave the directory empty: no partial file.
"""
import os
import re
import shlex
import shutil
import subprocess
import sys

ROW = re.compile(r"^\| [^|]+ \| [^|]+ \| `([^`]*)` \| exit ([0-9]+)([^:]*): `([^`]*)` \|$")


def main():
    specsim, specrom, src, work = (os.path.abspath(a) for a in sys.argv[1:5])
    progs = {"specsim": specsim, "specrom": specrom}
    if len(sys.argv) > 5:   # the setup's generator
        progs["setuprom"] = os.path.abspath(sys.argv[5])
    rows = [m for m in (ROW.match(l.rstrip("\n")) for l in open(os.path.join(src, "docs", "bad-input.md"))) if m]
    if len(rows) < 50:
        print("only %d rows found in docs/bad-input.md: did the table's format change?" % len(rows))
        return 1
    bad = 0
    for i, m in enumerate(rows, 1):
        cmd, want_rc, note, want_msg = m.group(1), int(m.group(2)), m.group(3), m.group(4)
        argv = shlex.split(cmd.replace("${SRC}", src))
        if argv[0] not in progs:
            print("row %d: unknown program '%s'" % (i, argv[0]))
            bad += 1
            continue
        d = os.path.join(work, "row%d" % i)
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
        try:
            p = subprocess.run([progs[argv[0]]] + argv[1:], cwd=d, capture_output=True, text=True, timeout=120)
        except subprocess.TimeoutExpired:
            print("row %d `%s`: no answer within 120 s" % (i, cmd))
            bad += 1
            continue
        err = p.stderr
        why = ""
        if p.returncode != want_rc:
            why = "exit code %d, not %d" % (p.returncode, want_rc)
        elif err.count("\n") != 1 or not err.endswith("\n"):
            why = "stderr is not one line: %r" % err
        elif not err.startswith(argv[0] + ": ") or want_msg not in err:
            why = "stderr %r does not say '%s: ...%s'" % (err, argv[0], want_msg)
        elif "after printing" not in note and p.stdout:
            why = "wrote to stdout: %r" % p.stdout[:200]
        elif os.listdir(d):
            why = "left files behind: %s" % ", ".join(sorted(os.listdir(d)))
        if why:
            print("row %d `%s`: %s" % (i, cmd, why))
            bad += 1
        shutil.rmtree(d, ignore_errors=True)
    if bad:
        print("%d of %d rows of docs/bad-input.md failed" % (bad, len(rows)))
        return 1
    print("all %d rows of docs/bad-input.md: exit 2, one line on stderr, no file left behind" % len(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
