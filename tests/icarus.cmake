# Icarus Verilog run: specsim writes spans and expected pixels from the bit-exact model, the Verilog
# testbench TB (tb_spec_unit or tb_spec_stream) drives the core with them and exits non-zero ($fatal) on
# the first mismatch.
# CONFIG (optional, e.g. "--mode tuned" or "--tables 1,2,3,4,8,16,32,64"): a configuration other than rom/'s;
# SPECROM writes its ROM images and header into WORK/rom, the testbench includes and loads those
# (the header's $readmemh paths are "rom/...", so the simulation runs in WORK), and the vectors use it too.
file(MAKE_DIRECTORY ${WORK})
set(INC ${SRC}/rom)
set(RUNDIR ${SRC})
if(DEFINED CONFIG)
  separate_arguments(CONFIG_ARGS UNIX_COMMAND "${CONFIG}")
  file(MAKE_DIRECTORY ${WORK}/rom)
  execute_process(COMMAND ${SPECROM} ${CONFIG_ARGS} --out ${WORK}/rom RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "specrom failed (${rc})")
  endif()
  set(INC ${WORK}/rom)
  set(RUNDIR ${WORK})
endif()
execute_process(COMMAND ${SPECSIM} vectors --out ${WORK}/vectors.hex --spans 400 --seed 7 ${CONFIG_ARGS}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "specsim vectors failed (${rc})")
endif()
file(GLOB RTL ${SRC}/rtl/*.v)
if(NOT DEFINED TB)
  set(TB tb_spec_unit)
endif()
execute_process(COMMAND ${IVERILOG} -g2005 -Wall -I${INC} -o ${WORK}/${TB}.vvp -s ${TB}
                        ${SRC}/tests/iverilog/${TB}.v ${RTL}
                WORKING_DIRECTORY ${SRC} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "iverilog failed (${rc})")
endif()
# $readmemh paths in the RTL defaults are relative to the repository root (or WORK, with CONFIG)
execute_process(COMMAND ${VVP} -n ${WORK}/${TB}.vvp +vectors=${WORK}/vectors.hex ${PLUSARGS}
                WORKING_DIRECTORY ${RUNDIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "Icarus testbench failed (${rc})")
endif()
if(NOT out MATCHES "PASS")
  message(FATAL_ERROR "Icarus testbench did not report PASS")
endif()
