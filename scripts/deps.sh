#!/usr/bin/env bash
# Installs the Debian packages the build and tests need, only those that are missing (sudo when not root).
# Usage: scripts/deps.sh [extra packages...]
set -euo pipefail
pkgs=(cmake make g++ verilator iverilog yosys libgtest-dev
      libglm-dev libpng-dev libtinyobjloader-dev libstb-dev gnuplot-nox python3
      glslang-tools libosmesa6-dev "$@")  # the last two: the GLSL versions of the companion methods (docs/methods.md)
if ! command -v dpkg-query >/dev/null 2>&1; then
    echo "deps: not a Debian system; install these yourself: ${pkgs[*]}" >&2
    exit 1
fi
missing=()
for p in "${pkgs[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done
if [ ${#missing[@]} -eq 0 ]; then
    exit 0
fi
sudo=""
if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then sudo="sudo"; else
        echo "deps: missing ${missing[*]} and not root (no sudo): install them and run again" >&2
        exit 1
    fi
fi
echo "deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
