# Icarus Verilog run of spec_shader (tests/iverilog/tb_spec_shader.v): `specsim setup-vectors` writes span-ends
# beats and every pixel the bit-exact models give, the testbench drives the shader with random stalls on both
# sides and exits non-zero ($fatal) on the first mismatch of value, tlast or tuser, a lost or extra pixel, a hang
# or an output that is X after the one reset pulse. ITERATIVE=1: the small configuration with spec_stream's up5k
# configuration (SPECROM writes its header and images into WORK/rom); BACKEND=1 (optional): spec_shader's compact
# back end spec_stream_seq. Runs in WORK with absolute ROM paths.
file(MAKE_DIRECTORY ${WORK})
set(INC -I${SRC}/rom)
set(ROMPARAMS "-Ptb_spec_shader.ROM9_FILE=\"${SRC}/rom/rom9_scale.hex\"" "-Ptb_spec_shader.ROM12_FILE=\"${SRC}/rom/rom12_cosk.hex\"")
set(VCONFIG pipelined)
if(ITERATIVE)
  file(MAKE_DIRECTORY ${WORK}/rom)
  execute_process(COMMAND ${SPECROM} --config up5k --out ${WORK}/rom RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "specrom failed (${rc})")
  endif()
  set(INC -I${WORK}/rom -I${SRC}/rom)
  set(ROMPARAMS "-Ptb_spec_shader.ITERATIVE=1")
  set(VCONFIG small)
endif()
if(DEFINED BACKEND)
  list(APPEND ROMPARAMS "-Ptb_spec_shader.BACKEND=${BACKEND}")
endif()
list(APPEND ROMPARAMS "-Ptb_spec_shader.LOG2_FILE=\"${SRC}/rom/setup_log2.hex\""
                      "-Ptb_spec_shader.EXP2_FILE=\"${SRC}/rom/setup_exp2.hex\"")
execute_process(COMMAND ${SPECSIM} setup-vectors --out ${WORK}/v --spans ${SPANS} --seed 7 --config ${VCONFIG}
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
