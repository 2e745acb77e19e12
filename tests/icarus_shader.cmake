# Icarus Verilog run of spec_shader (tests/iverilog/tb_spec_shader.v): `specsim setup-vectors` writes span-ends
# beats and every pixel the bit-exact models give, the testbench drives the shader with random stalls on both
# sides and exits non-zero ($fatal) on the first mismatch of value, tlast or tuser, a lost or extra pixel, a hang
# or an output that is X after the one reset pulse. CONFIG ecp5 (default): the multiplier setup with spec_stream;
# up5k: the small setup with spec_stream_seq and spec_stream's up5k tables (SPECROM writes their header and
# images into WORK/rom). Runs in WORK with absolute ROM paths.
file(MAKE_DIRECTORY ${WORK})
set(INC -I${SRC}/rom)
set(ROMPARAMS "-Ptb_spec_shader.ROM9_FILE=\"${SRC}/rom/rom9_scale.hex\"" "-Ptb_spec_shader.ROM12_FILE=\"${SRC}/rom/rom12_cosk.hex\"")
if(NOT DEFINED CONFIG)
  set(CONFIG ecp5)
endif()
if(CONFIG STREQUAL "up5k")
  file(MAKE_DIRECTORY ${WORK}/rom)
  execute_process(COMMAND ${SPECROM} --config up5k --out ${WORK}/rom RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "specrom failed (${rc})")
  endif()
  set(INC -I${WORK}/rom -I${SRC}/rom)
  set(ROMPARAMS "-Ptb_spec_shader.ITERATIVE=1" "-Ptb_spec_shader.BACKEND=1"
                "-Ptb_spec_shader.ROM9_FILE=\"${WORK}/rom/rom9_scale.hex\"" "-Ptb_spec_shader.ROM12_FILE=\"${WORK}/rom/rom12_cosk.hex\"")
endif()
foreach(p EFU_FILE:setup_efu EXP2_FILE:setup_exp2 UC_FILE:setup_ucode SMALL_LOG2_FILE:setup_small_log2
          SMALL_EXP2_FILE:setup_small_exp2)
  string(REPLACE ":" ";" pf ${p})
  list(GET pf 0 param)
  list(GET pf 1 file)
  list(APPEND ROMPARAMS "-Ptb_spec_shader.${param}=\"${SRC}/rom/${file}.hex\"")
endforeach()
execute_process(COMMAND ${SPECSIM} setup-vectors --out ${WORK}/v --spans ${SPANS} --seed 7 --config ${CONFIG}
                RESULT_VARIABLE rc OUTPUT_VARIABLE counts)
if(NOT rc EQUAL 0 OR NOT counts MATCHES "spans ([0-9]+) pixels ([0-9]+)")
  message(FATAL_ERROR "specsim setup-vectors failed (${rc}): ${counts}")
endif()
set(NSPANS ${CMAKE_MATCH_1})
set(NPIXELS ${CMAKE_MATCH_2})
file(STRINGS ${SRC}/rtl/spec_core.f RTL_CORE)
file(STRINGS ${SRC}/rtl/spec_shader.f RTL_SHADER)
set(RTL ${RTL_CORE} ${RTL_SHADER})
list(TRANSFORM RTL PREPEND ${SRC}/rtl/)
execute_process(COMMAND ${IVERILOG} -g2005 -Wall ${INC} -o ${WORK}/tb.vvp -s tb_spec_shader ${ROMPARAMS}
                        ${SRC}/tests/iverilog/tb_spec_shader.v ${RTL}
                WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "iverilog failed (${rc})")
endif()
execute_process(COMMAND ${VVP} -n ${WORK}/tb.vvp +beats=${WORK}/v.beats +pixels=${WORK}/v.pixels +spans=${NSPANS}
                        +npixels=${NPIXELS} +stall=30
                WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "Icarus testbench failed (${rc})")
endif()
if(NOT out MATCHES "PASS")
  message(FATAL_ERROR "Icarus testbench did not report PASS")
endif()
