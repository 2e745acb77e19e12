# ctest glsl_validate: the GLSL libraries of sim/methods/glsl/ validated by Debian's glslangValidator, each
# inside its compute-shader test harness (GLSL 4.30, as tests/test_glsl.cpp runs them on Mesa's llvmpipe) and
# inside a fragment shader as a user would call it (GLSL 3.30). Arguments: GLSLANG, SRC, WORK.
file(MAKE_DIRECTORY ${WORK})
foreach(lib parallax normalize highlight)
  file(READ ${SRC}/sim/methods/glsl/${lib}.glsl library)
  foreach(stage comp frag)
    file(READ ${SRC}/tests/glsl/${lib}.${stage} harness)
    string(FIND "${harness}" "#pragma methods_library" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "tests/glsl/${lib}.${stage} has no '#pragma methods_library' line")
    endif()
    string(REPLACE "#pragma methods_library" "${library}" source "${harness}")
    file(WRITE ${WORK}/${lib}.${stage} "${source}")
    execute_process(COMMAND ${GLSLANG} ${WORK}/${lib}.${stage} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                    ERROR_VARIABLE out)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "glslangValidator ${WORK}/${lib}.${stage} failed:\n${out}")
    endif()
    message(STATUS "glslangValidator: ${lib}.glsl in its ${stage} harness: valid")
  endforeach()
endforeach()
