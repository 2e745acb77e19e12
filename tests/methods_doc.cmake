# ctest methods_doc_tables: docs/methods.md and README.md carry the tables specsim highlight, normalize and
# parallax print now, with the arguments `make methods` uses (scripts/methods_doc.py check).
# Arguments: SPECSIM, PYTHON, SRC, WORK.
file(MAKE_DIRECTORY ${WORK})
foreach(cmd highlight normalize parallax)
  execute_process(COMMAND ${SPECSIM} ${cmd} --tables ${WORK}/${cmd}.md RESULT_VARIABLE rc OUTPUT_QUIET
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "specsim ${cmd} failed (${rc}): ${err}")
  endif()
endforeach()
execute_process(COMMAND ${PYTHON} ${SRC}/scripts/methods_doc.py check ${SRC}/docs/methods.md ${SRC}/README.md --
                        ${WORK}/highlight.md ${WORK}/normalize.md ${WORK}/parallax.md
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "docs/methods.md or README.md differs from the commands' tables: run 'make methods' and commit")
endif()
