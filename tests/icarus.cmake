# Icarus Verilog run: specsim writes spans and expected pixels from the bit-exact model, the Verilog
# testbench TB (tb_spec_unit or tb_spec_stream) drives the core with them and exits non-zero ($fatal) on
# the first mismatch, a lost or extra pixel, or an output that is X after the one reset pulse.
# The simulation runs in WORK, outside the repository, as a user's would: the default configuration's images are
# passed by absolute path (the ROM path parameters, -P); with CONFIG (optional, e.g. "--mode tuned" or
# "--tables 1,2,3,4,8,16,32,64") SPECROM writes that configuration's images and header into WORK/rom, and the
# header names the images by absolute path (the include directory way).
if(NOT DEFINED TB)
  set(TB tb_spec_unit)
endif()
file(MAKE_DIRECTORY ${WORK})
set(INC ${SRC}/rom)
set(ROMPARAMS "-P${TB}.ROM9_FILE=\"${SRC}/rom/rom9_scale.hex\"" "-P${TB}.ROM12_FILE=\"${SRC}/rom/rom12_cosk.hex\"")
if(DEFINED CONFIG)
  separate_arguments(CONFIG_ARGS UNIX_COMMAND "${CONFIG}")
  file(MAKE_DIRECTORY ${WORK}/rom)
  execute_process(COMMAND ${SPECROM} ${CONFIG_ARGS} --out ${WORK}/rom RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "specrom failed (${rc})")
  endif()
  set(INC ${WORK}/rom)
  set(ROMPARAMS "")
endif()
execute_process(COMMAND ${SPECSIM} vectors --out ${WORK}/vectors.hex --spans 400 --seed 7 ${CONFIG_ARGS}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "specsim vectors failed (${rc})")
endif()
# the core's RTL: the one file list rtl/spec_core.f
file(STRINGS ${SRC}/rtl/spec_core.f RTL)
list(TRANSFORM RTL PREPEND ${SRC}/rtl/)
# TBPARAMS (optional): "NAME=VALUE ..." parameters of the testbench (tb_spec_stream's LANES, PACK)
set(TBP "")
if(DEFINED TBPARAMS)
  separate_arguments(TBPARAMS_LIST UNIX_COMMAND "${TBPARAMS}")
  foreach(kv ${TBPARAMS_LIST})
    list(APPEND TBP "-P${TB}.${kv}")
  endforeach()
endif()
execute_process(COMMAND ${IVERILOG} -g2005 -Wall -I${INC} -o ${WORK}/${TB}.vvp -s ${TB} ${ROMPARAMS} ${TBP}
                        ${SRC}/tests/iverilog/${TB}.v ${RTL}
                WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "iverilog failed (${rc})")
endif()
execute_process(COMMAND ${VVP} -n ${WORK}/${TB}.vvp +vectors=${WORK}/vectors.hex ${PLUSARGS}
                WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "Icarus testbench failed (${rc})")
endif()
if(NOT out MATCHES "PASS")
  message(FATAL_ERROR "Icarus testbench did not report PASS")
endif()
