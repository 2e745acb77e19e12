// methods_usage.h - the usage texts of specsim highlight, normalize and parallax (each command's --help, and
// specsim --help through kMethodsUsage).
#pragma once

#define SPEC_PARALLAX_USAGE\
    "  parallax   companion paper C: iterative parallax mapping, its variants and the baselines at equal fetch\n"\
    "           budgets, against the exact intersection (docs/methods.md)\n"\
    "           --map NAME (repeatable; waves, bumps, bricks, rocks; default all)  --map-size N (power of two,\n"\
    "           16..2048, default 256)  --depth S (relief depth in texture units, (0, 0.5], default 0.05)\n"\
    "           --threshold T (texture units, (0, 1), default depth / 512)  --max-iter K (the iteration\n"\
    "           table's cap, 1..63, default 16)  --budgets F,F,... (height fetches, 1..256, increasing;\n"\
    "           default 1,2,3,4,6,8,12,16,24,32)  --grid G (fragments G x G per view, 2..256, default 24)\n"\
    "           --out-dir DIR (parallax_MAP.png, fetches_MAP_ELEV.png and their data)  --tables FILE (the\n"\
    "           document's tables, for scripts/methods_doc.py)\n"
