# Reference designs on boards (issue 15, docs/boards.md): the board RTL's Verilated models, the C++ model and
# board simulation (sim/board/), their tests. Included from CMakeLists.txt after the core and the renderer.

# File lists (boards/**/*.f): one path per line from the repository root, # comments
function(board_read_list out list)
  file(STRINGS ${CMAKE_SOURCE_DIR}/${list} lines)
  set(files)
  foreach(l ${lines})
    string(STRIP "${l}" l)
    if(l AND NOT l MATCHES "^#")
      list(APPEND files ${CMAKE_SOURCE_DIR}/${l})
    endif()
  endforeach()
  set(${out} ${files} PARENT_SCOPE)
endfunction()
board_read_list(BOARD_COMMON boards/common/board_common.f)
board_read_list(BOARD_ICEBREAKER boards/icebreaker/icebreaker.f)
board_read_list(BOARD_ULX3S boards/ulx3s/ulx3s.f)
file(GLOB BOARD_ICEBREAKER_SIM ${CMAKE_SOURCE_DIR}/boards/icebreaker/sim/*.v)
file(GLOB BOARD_ULX3S_SIM ${CMAKE_SOURCE_DIR}/boards/ulx3s/sim/*.v)
set(BOARD_CORE_RTL ${RTL_SETUP})   # the core and the shader (rtl/spec_core.f, rtl/spec_shader.f)
set(BOARD_GEN ${CMAKE_SOURCE_DIR}/boards/common/gen)

# The C++ model, the double-precision reference, capture, TMDS, boardsim's parse/compute/report
add_library(boardmodel STATIC
  sim/board/board_scene.cpp sim/board/board_model.cpp sim/board/board_ref.cpp sim/board/board_shaders.cpp
  sim/board/board_capture.cpp sim/board/tmds.cpp sim/board/boardsim_cli.cpp sim/board/boardsim_compute.cpp
  sim/board/boardsim_report.cpp)
target_include_directories(boardmodel PUBLIC sim/board)
target_link_libraries(boardmodel PUBLIC specrender specsetup)
target_compile_options(boardmodel PRIVATE ${WARN})

# The board tops with the primitives' models (Verilator --timing: the PLL models schedule their clocks)
function(board_file_args out mode k setup_dir)
  set(${out} "-GSCENE_FILE=\"${BOARD_GEN}/scene_${mode}.hex\"" "-GSPLIT_FILE=\"${BOARD_GEN}/split_${k}.hex\""
    "-GOBJ_FILE=\"${BOARD_GEN}/objects_${mode}.hex\"" "-GSHADE_FILE=\"${BOARD_GEN}/shade_${mode}.hex\""
    "-GLIGHT_FILE=\"${BOARD_GEN}/light_xy.hex\"" "-GROM9_FILE=\"${UP5K_ROM_DIR}/rom9_scale.hex\""
    "-GROM12_FILE=\"${UP5K_ROM_DIR}/rom12_cosk.hex\"" -GSPLIT_K=${k}
    "-GSETUP_DIR=\"${setup_dir}\"" -I${setup_dir} PARENT_SCOPE)
endfunction()
set(BOARD_VL_ARGS -Wall -Wno-fatal -I${ROM_DIR} -I${BOARD_GEN} -O3 --x-assign fast --x-initial fast --timing)
# The frame-buffer designs build the up5k configuration's small setup, the racing design the ecp5 configuration's
# multiplier setup (sim/board/board_shaders.cpp: board_setup_config, the model's side) on the race machine's units:
# setuprom --format race (II 28, where the ecp5 configuration's units take 41: a line's clocks hold K = 8's
# sub-spans only at 28), committed in rom/race/ (make roms; tests/setup_rom_check.cmake), whose setup_params.vh
# comes before rom/'s on the include path (in the build directory it would not exist when verilate() runs
# Verilator at configure time). The arithmetic, and so the model, is the ecp5 configuration's.
set(RACE_SETUP_DIR ${CMAKE_SOURCE_DIR}/rom/race)
# board_verilate(target board prefix mode k setup_dir verilator-args...)
function(board_verilate target board prefix mode k setup_dir)
  board_file_args(files ${mode} ${k} ${setup_dir})
  if(board STREQUAL "icebreaker")
    set(src ${BOARD_CORE_RTL} ${BOARD_COMMON} ${BOARD_ICEBREAKER} ${BOARD_ICEBREAKER_SIM})
  else()
    set(src ${BOARD_CORE_RTL} ${BOARD_COMMON} ${BOARD_ULX3S} ${BOARD_ULX3S_SIM})
  endif()
  verilate(${target} SOURCES ${src} TOP_MODULE ${board}_top PREFIX ${prefix}
    VERILATOR_ARGS ${files} ${BOARD_VL_ARGS} ${ARGN})
endfunction()

set(BOARDSIM_SOURCES sim/board/boardsim_main.cpp sim/board/board_harness.cpp sim/board/harness_icebreaker.cpp
  sim/board/harness_ulx3s.cpp)
# boardsim-quick: the 128 x 96 test raster of both boards (make test)
add_executable(boardsim-quick ${BOARDSIM_SOURCES})
add_dependencies(boardsim-quick rom_up5k)
target_link_libraries(boardsim-quick PRIVATE boardmodel Threads::Threads)
board_verilate(boardsim-quick icebreaker Vicebreaker_top_test 64x48 8 ${ROM_DIR} -GTEST=1)
board_verilate(boardsim-quick ulx3s Vulx3s_top_test 64x48 8 ${ROM_DIR} -GMODE=2)
board_verilate(boardsim-quick ulx3s Vulx3s_top_race 128x96 8 ${RACE_SETUP_DIR} -GMODE=3)
# boardsim: every board and mode (make board-sim)
add_executable(boardsim EXCLUDE_FROM_ALL ${BOARDSIM_SOURCES})
add_dependencies(boardsim rom_up5k)
target_compile_definitions(boardsim PRIVATE BOARDSIM_FULL=1)
target_link_libraries(boardsim PRIVATE boardmodel Threads::Threads)
board_verilate(boardsim icebreaker Vicebreaker_top_test 64x48 8 ${ROM_DIR} -GTEST=1)
board_verilate(boardsim ulx3s Vulx3s_top_test 64x48 8 ${ROM_DIR} -GMODE=2)
board_verilate(boardsim ulx3s Vulx3s_top_race 128x96 8 ${RACE_SETUP_DIR} -GMODE=3)
board_verilate(boardsim icebreaker Vicebreaker_top 320x240 8 ${ROM_DIR} -GTEST=0)
board_verilate(boardsim ulx3s Vulx3s_top 320x240 8 ${ROM_DIR} -GMODE=0)
board_verilate(boardsim ulx3s Vulx3s_top_720 1280x720 8 ${RACE_SETUP_DIR} -GMODE=1)

# The shared modules on their own, for the unit tests (tests/test_board_rtl.cpp)
add_library(vboard_modules STATIC tests/modules_stub.cpp)
set(BOARD_MOD_ARGS -Wall -I${BOARD_GEN} -O3 --x-assign fast --x-initial fast)
set(BC ${CMAKE_SOURCE_DIR}/boards/common)
verilate(vboard_modules SOURCES ${BC}/sphere_spans.v ${BC}/seq_mul.v ${BC}/isqrt.v TOP_MODULE sphere_spans
  PREFIX Vsphere_spans_small VERILATOR_ARGS ${BOARD_MOD_ARGS} -GMUL_STEPS=1 -GSQRT_STEPS=1 -GK=16
  "-GSCENE_FILE=\"${BOARD_GEN}/scene_640x480.hex\"" "-GSPLIT_FILE=\"${BOARD_GEN}/split_16.hex\"")
verilate(vboard_modules SOURCES ${BC}/sphere_spans.v ${BC}/seq_mul.v ${BC}/isqrt.v TOP_MODULE sphere_spans
  PREFIX Vsphere_spans_serial VERILATOR_ARGS ${BOARD_MOD_ARGS} -GMUL_STEPS=1 -GSQRT_STEPS=1 -GK=16 -GSERIAL=1
  "-GSCENE_FILE=\"${BOARD_GEN}/scene_640x480.hex\"" "-GSPLIT_FILE=\"${BOARD_GEN}/split_16.hex\"")
verilate(vboard_modules SOURCES ${BC}/sphere_spans.v ${BC}/seq_mul.v ${BC}/isqrt.v TOP_MODULE sphere_spans
  PREFIX Vsphere_spans_fast VERILATOR_ARGS ${BOARD_MOD_ARGS} -GMUL_STEPS=9 -GSQRT_STEPS=2 -GK=32
  "-GSCENE_FILE=\"${BOARD_GEN}/scene_1280x720.hex\"" "-GSPLIT_FILE=\"${BOARD_GEN}/split_32.hex\"")
verilate(vboard_modules SOURCES ${BC}/tmds_encoder.v TOP_MODULE tmds_encoder PREFIX Vtmds_encoder
  VERILATOR_ARGS ${BOARD_MOD_ARGS})
verilate(vboard_modules SOURCES ${BC}/tmds_serializer.v ${BC}/cdc_sync.v TOP_MODULE tmds_serializer
  PREFIX Vtmds_serializer VERILATOR_ARGS ${BOARD_MOD_ARGS})
verilate(vboard_modules SOURCES ${BC}/isqrt.v TOP_MODULE isqrt PREFIX Visqrt
  VERILATOR_ARGS ${BOARD_MOD_ARGS} -GX_W=28 -GSTEPS_PER_CLK=2)
verilate(vboard_modules SOURCES ${BC}/seq_mul.v TOP_MODULE seq_mul PREFIX Vseq_mul
  VERILATOR_ARGS ${BOARD_MOD_ARGS} -GA_W=9 -GB_W=9 -GSTEPS_PER_CLK=3)
verilate(vboard_modules SOURCES ${BC}/video_timing.v TOP_MODULE video_timing PREFIX Vvideo_timing
  VERILATOR_ARGS ${BOARD_MOD_ARGS})
verilate(vboard_modules SOURCES ${BC}/compose.v TOP_MODULE compose PREFIX Vcompose
  VERILATOR_ARGS ${BOARD_MOD_ARGS} -GOUT_BITS=4 "-GOBJ_FILE=\"${BOARD_GEN}/objects_640x480.hex\"")
verilate(vboard_modules SOURCES ${BC}/compose_seq.v ${BC}/seq_mul.v TOP_MODULE compose_seq PREFIX Vcompose_seq
  VERILATOR_ARGS ${BOARD_MOD_ARGS} -GOUT_BITS=4 -GTAG_W=17 "-GOBJ_FILE=\"${BOARD_GEN}/objects_640x480.hex\"")
verilate(vboard_modules SOURCES ${BC}/compose_seq.v ${BC}/seq_mul.v TOP_MODULE compose_seq PREFIX Vcompose_seq_hold
  VERILATOR_ARGS ${BOARD_MOD_ARGS} -GOUT_BITS=4 -GTAG_W=17 -GMUL_STEPS=1 -GHOLD=1
  "-GOBJ_FILE=\"${BOARD_GEN}/objects_640x480.hex\"")
verilate(vboard_modules SOURCES ${BC}/sync_fifo.v TOP_MODULE sync_fifo PREFIX Vsync_fifo
  VERILATOR_ARGS ${BOARD_MOD_ARGS} -GW=16 -GAW=3)
verilate(vboard_modules SOURCES ${BC}/sync_fifo.v TOP_MODULE sync_fifo PREFIX Vsync_fifo_q1
  VERILATOR_ARGS ${BOARD_MOD_ARGS} -GW=16 -GAW=3 -GQUEUE=1)
verilate(vboard_modules SOURCES ${BC}/sync_fifo.v TOP_MODULE sync_fifo PREFIX Vsync_fifo_q0
  VERILATOR_ARGS ${BOARD_MOD_ARGS} -GW=16 -GAW=3 -GQUEUE=0)
verilate(vboard_modules SOURCES ${BC}/light_gen.v TOP_MODULE light_gen PREFIX Vlight_gen
  VERILATOR_ARGS ${BOARD_MOD_ARGS} "-GLIGHT_FILE=\"${BOARD_GEN}/light_xy.hex\"")
verilate(vboard_modules SOURCES ${BC}/frame_store.v TOP_MODULE frame_store PREFIX Vframe_store
  VERILATOR_ARGS ${BOARD_MOD_ARGS} -GFB_W=64 -GFB_H=48 -GP_W=12)
verilate(vboard_modules SOURCES ${BC}/frame_store_packed.v TOP_MODULE frame_store_packed PREFIX Vframe_store_packed
  VERILATOR_ARGS ${BOARD_MOD_ARGS} -GFB_W=64 -GFB_H=48 -GP_W=12)
target_sources(spec_tests PRIVATE tests/test_board_rtl.cpp tests/test_board_units.cpp tests/test_board_model.cpp
  tests/test_board_cli.cpp tests/test_board_store.cpp)
target_link_libraries(spec_tests PRIVATE vboard_modules boardmodel)
target_compile_definitions(spec_tests PRIVATE BOARDSIM_PATH="$<TARGET_FILE:boardsim-quick>")

# The committed tables are the generator's; both boards' top levels, 128 x 96 test raster, two whole frames
# bit for bit against the model, video timing, TMDS decoding (the full-size runs: make board-sim)
add_test(NAME board_tables_match_generator
  COMMAND ${CMAKE_COMMAND} -DBOARDSIM=$<TARGET_FILE:boardsim-quick> -DGEN=${BOARD_GEN}
          -DOUT=${CMAKE_BINARY_DIR}/board_gen_check -P ${CMAKE_SOURCE_DIR}/boards/gen_check.cmake)
foreach(board icebreaker ulx3s)
  add_test(NAME board_sim_${board}_quick
    COMMAND ${CMAKE_COMMAND} -E chdir ${CMAKE_BINARY_DIR}
            $<TARGET_FILE:boardsim-quick> run --board ${board} --mode 128x96 --frames 2)
endforeach()
# the ULX3S's racing-the-beam architecture (1280 x 720's) on the test raster
add_test(NAME board_sim_ulx3s_race_quick
  COMMAND ${CMAKE_COMMAND} -E chdir ${CMAKE_BINARY_DIR}
          $<TARGET_FILE:boardsim-quick> run --board ulx3s --mode 128x96-race --frames 2)
# Icarus accepts the board RTL as Verilog-2005 (each top with its primitives' simulation models)
add_test(NAME iverilog_boards
  COMMAND ${CMAKE_COMMAND} -DIVERILOG=${IVERILOG} -DSRC=${CMAKE_SOURCE_DIR} -DOUT=${CMAKE_BINARY_DIR}/iverilog_boards
          -P ${CMAKE_SOURCE_DIR}/boards/iverilog_check.cmake)
