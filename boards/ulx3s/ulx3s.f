# The ULX3S design: its primitives (ECP5 cells) and top level; boards/ulx3s/sim/ holds the cells' simulation
# models (for Verilator / Icarus only).
boards/ulx3s/ulx3s_prims.v
boards/ulx3s/ulx3s_top.v
