#!/usr/bin/env python3
"""ci_check.py - the GitHub Actions workflow runs what users run (ctest ci_workflow).

usage: ci_check.py SRC

.github/workflows/ci.yml must run `make test` in a debian:12 container within the 90 minutes CI allows, on
pushes and pull requests, after installing what checkout and make need (deps.sh installs the rest as root);
.ci/run must run `make test`; README's badge must show that workflow. Plain text checks: Debian's python3 has
no YAML parser.
"""
import os
import re
import sys


def main():
    src = sys.argv[1]
    errors = []
    wf_path = os.path.join(src, ".github", "workflows", "ci.yml")
    if not os.path.exists(wf_path):
        print("missing .github/workflows/ci.yml")
        return 1
    wf = open(wf_path).read()
    lines = [l.split("#", 1)[0].rstrip() for l in wf.splitlines()]
    text = "\n".join(lines)
    if not re.search(r"^\s+container:\s*debian:12\s*$", text, re.M):
        errors.append("the job does not run in the debian:12 container")
    if not re.search(r"^\s+run:\s*make test\b", text, re.M):
        errors.append("no step runs `make test`")
    m = re.search(r"^\s+timeout-minutes:\s*(\d+)\s*$", text, re.M)
    if not m or int(m.group(1)) > 90:
        errors.append("timeout-minutes missing or above the 90 minutes CI allows")
    for event in ("push", "pull_request"):
        if not re.search(r"^\s+%s:" % event, text, re.M):
            errors.append("not run on %s" % event)
    if "apt-get install" not in text or not re.search(r"\bmake\b", text.split("actions/checkout")[0]):
        errors.append("make (and git) are not installed before the checkout: debian:12 has neither")
    if "sudo" in text:
        errors.append("sudo: the container runs as root and has no sudo")
    run = open(os.path.join(src, ".ci", "run")).read()
    if "make test" not in run:
        errors.append(".ci/run does not run make test")
    readme = open(os.path.join(src, "README.md")).read()
    if not re.search(r"\[!\[[^]]*\]\([^)]*actions/workflows/ci\.yml/badge\.svg\)\]\([^)]*actions/workflows/ci\.yml\)",
                     readme):
        errors.append("README has no badge of .github/workflows/ci.yml")
    for e in errors:
        print("ci_check: " + e)
    if not errors:
        print("ci_check: .github/workflows/ci.yml runs make test in debian:12; README shows its badge")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
