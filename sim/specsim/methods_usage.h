// methods_usage.h - the usage texts of specsim highlight, normalize and parallax (each command's --help, and
// specsim --help through kMethodsUsage).
#pragma once

#define SPEC_HIGHLIGHT_USAGE\
    "  highlight  companion paper A: the highlight-in-triangle test, what it gates (both readings), and the\n"\
    "           --cull-specular bound, measured (docs/methods.md)\n"\
    "           --size N (16..4096, default 512)  --model rtl|golden (default rtl)  --scene NAME (repeatable;\n"\
    "           default: default, sphere, torus, teapot and the coarse sphere-lo, torus-lo, teapot-lo)\n"\
    "           --coarse-n N (extra rows: the coarse scenes with every exponent N, 0..1023, 0 none; default\n"\
    "           1000)  --samples N (random triangles, 1000..10000000, default 200000)  --out-dir DIR\n"\
    "           (cull_SCENE.png: culled triangles tinted)  --tables FILE (the document's tables)\n"

#define SPEC_NORMALIZE_USAGE\
    "  normalize  companion paper B: adaptive normalization against full, rsqrt, one Newton step and the slerp\n"\
    "           recurrence: operations counted per pixel, span and frame, errors against classic Phong\n"\
    "           --size N (16..4096, default 512)  --diffuse-bound D  --specular-bound S (adaptive's relative\n"\
    "           errors, (0, 0.5), default 0.01)  --extend paper|slerp (how a span is extended to 2^k\n"\
    "           intervals; default paper)  --scene NAME (repeatable; default: the four built-in scenes and\n"\
    "           sphere-lo, torus-lo, teapot-lo of 300-1500 triangles)  --timing (also CPU times, --runs R of\n"\
    "           each, 3..15, default 5)  --out-dir DIR (fig2.png, fig3.png, cost.png, panel_SCENE.png)\n"\
    "           --tables FILE (the document's tables)\n"

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
