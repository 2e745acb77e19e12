# Included by CMakeLists.txt when SPEC_COVERAGE=ON (make coverage, docs/verification.md).
#
# Verilator keeps a model's coverage counts in its VerilatedContext and writes them only when asked. The
# drivers (sim/rtl) and the module tests own their contexts, so instead of changing them, the coverage build
# links spec_tests with `-Wl,--wrap` on each model's final(): coverage_hook.cpp writes the model's counts to
# $SPEC_COVERAGE_DIR/cov-<pid>-<n>.dat and then runs the real final(). Models whose final() never runs (a
# test that drops its model without it) are not counted; every driver and the module tests' Dut call it.
set(SPEC_COV_MODELS
  Vspec_unit Vspec_stream Vspec_stream_up5k Vspec_unit_tuned Vspec_stream_tuned
  Vspec_unit_up5k Vspec_ctrl Vspec_datapath Vspec_counter Vspec_accum Vspec_decoder Vspec_mul11 Vspec_mul13
  Vparallax_step Vparallax_iter Vparallax_iter_s1 Vparallax_iter_s16
  Vspec_setup Vspec_setup_small Vspec_shader Vspec_shader_up5k
  Vspec_stream_l2 Vspec_stream_l4 Vspec_stream_l2p Vspec_stream_l4p Vspec_stream_l2p_up5k
  Vspec_stream_seq Vspec_stream_seq_up5k Vspec_stream_seq_tuned)
set(_inc "")
set(_wraps "")
foreach(m ${SPEC_COV_MODELS})
  string(LENGTH ${m} _n)
  set(_sym _ZN${_n}${m}5finalEv)
  string(APPEND _inc "SPEC_COV_WRAP(${_sym})\n")
  list(APPEND _wraps "-Wl,--wrap=${_sym}")
endforeach()
file(WRITE ${CMAKE_BINARY_DIR}/coverage_models.inc "${_inc}")
target_sources(spec_tests PRIVATE ${CMAKE_SOURCE_DIR}/tests/coverage/coverage_hook.cpp)
target_include_directories(spec_tests PRIVATE ${CMAKE_BINARY_DIR})
target_link_options(spec_tests PRIVATE ${_wraps})
