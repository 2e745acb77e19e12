# ctest methods_synth_cells: the iCE40 cell counts of parallax_iter in docs/methods.md's make-synth row are what
# Debian's Yosys gives now (synthesis only; place and route and Fmax belong to make synth).
# Arguments: PYTHON, SRC, SPECROM, WORK.
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${PYTHON} ${SRC}/syn/synth.py --targets ice40-up5k --tops parallax_iter --no-pnr
                        --out ${WORK} --specrom ${SPECROM}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "syn/synth.py failed: ${out}")
endif()
execute_process(COMMAND ${PYTHON} ${SRC}/scripts/methods_doc.py synth ${SRC}/docs/methods.md
                        ${WORK}/ice40-up5k-parallax_iter-default.json RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "docs/methods.md's parallax_iter synthesis row is stale")
endif()
