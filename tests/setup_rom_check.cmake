# Regenerates both setup configurations' tables, microcode and headers (setuprom: ecp5, up5k) and fails when a
# committed file in rom/ differs.
file(REMOVE_RECURSE ${OUT_DIR})
file(MAKE_DIRECTORY ${OUT_DIR})
foreach(cfg ecp5 up5k)
  execute_process(COMMAND ${SETUPROM} --out ${OUT_DIR} --config ${cfg} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "setuprom --config ${cfg} failed (${rc})")
  endif()
endforeach()
foreach(f setup_efu.hex setup_exp2.hex setup_ucode.hex setup_params.vh setup_params.h
          setup_small_log2.hex setup_small_exp2.hex setup_small_params.vh setup_small_params.h)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${ROM_DIR}/${f} ${OUT_DIR}/${f} RESULT_VARIABLE diff)
  if(NOT diff EQUAL 0)
    message(FATAL_ERROR "rom/${f} differs from what setuprom makes now: run 'make roms' and commit")
  endif()
  message(STATUS "rom/${f}: matches the generator")
endforeach()
