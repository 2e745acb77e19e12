# Included by CMakeLists.txt: the fuzz targets (make fuzz, docs/verification.md) and their regression
# replays. Every build makes fuzz_replay_<target> (any compiler) and registers a ctest that runs it on the
# committed corpus (fuzz/corpus/<target>) and on every input that once broke a promise (fuzz/regress/<target>).
# With SPEC_FUZZ=ON (clang, -fsanitize=...,fuzzer-no-link; make fuzz) it also makes the libFuzzer binaries
# fuzz_<target>.
option(SPEC_FUZZ "Build the libFuzzer targets (clang only; make fuzz)" OFF)
set(FUZZ_DIR ${CMAKE_SOURCE_DIR}/fuzz)

# specsim's sources again, with main renamed, for the in-process command-line target
get_target_property(_specsim_src specsim SOURCES)
get_target_property(_specsim_libs specsim LINK_LIBRARIES)
add_library(specsim_lib STATIC EXCLUDE_FROM_ALL ${_specsim_src})
target_compile_definitions(specsim_lib PRIVATE main=specsim_main SPEC_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
target_include_directories(specsim_lib SYSTEM PRIVATE ${VERILATOR_ROOT}/include)
target_link_libraries(specsim_lib PUBLIC ${_specsim_libs})

set(_fuzz_libs_cli specmodel)
set(_fuzz_libs_format specmodel)
set(_fuzz_libs_host specrender)
set(_fuzz_libs_obj specrender)
set(_fuzz_libs_specsim specsim_lib)
set(_fuzz_libs_setup specsetup)                # spec_setup's bit-exact model (issue 13)
set(_fuzz_libs_specsim_setup specsim_lib)      # specsim setup
set(SPEC_FUZZ_TARGETS cli format host obj specsim setup specsim_setup)
foreach(t ${SPEC_FUZZ_TARGETS})
  add_executable(fuzz_replay_${t} ${FUZZ_DIR}/fuzz_${t}.cpp ${FUZZ_DIR}/replay_main.cpp)
  target_include_directories(fuzz_replay_${t} PRIVATE ${FUZZ_DIR})
  target_link_libraries(fuzz_replay_${t} PRIVATE ${_fuzz_libs_${t}})
  add_test(NAME fuzz_replay_${t} COMMAND fuzz_replay_${t} ${FUZZ_DIR}/corpus/${t} ${FUZZ_DIR}/regress/${t})
  if(SPEC_FUZZ)
    add_executable(fuzz_${t} ${FUZZ_DIR}/fuzz_${t}.cpp)
    target_include_directories(fuzz_${t} PRIVATE ${FUZZ_DIR})
    target_link_libraries(fuzz_${t} PRIVATE ${_fuzz_libs_${t}})
    target_link_options(fuzz_${t} PRIVATE -fsanitize=fuzzer)
  endif()
endforeach()
