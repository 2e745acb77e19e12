# The iCEBreaker design: its primitives (iCE40 cells) and top level; boards/icebreaker/sim/ holds the cells'
# simulation models (for Verilator / Icarus only).
boards/icebreaker/icebreaker_prims.v
boards/icebreaker/icebreaker_top.v
