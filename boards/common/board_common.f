# The shared RTL of the reference designs (docs/boards.md), in dependency order; paths from the repository
# root. Each board adds its own list (boards/<board>/<board>.f) and the core's (spec_stream and its modules;
# spec_shader once issue 13 lands). Read by boards/boards.cmake, boards/flow.py and make lint-boards.
boards/common/cdc_sync.v
boards/common/video_timing.v
boards/common/isqrt.v
boards/common/seq_mul.v
boards/common/sphere_spans.v
boards/common/light_gen.v
boards/common/sync_fifo.v
boards/common/board_shader.v
boards/common/shade_passes.v
boards/common/compose.v
boards/common/compose_seq.v
boards/common/line_buffer.v
boards/common/board_core.v
boards/common/frame_store.v
boards/common/frame_store_packed.v
boards/common/board_core_fb.v
boards/common/tmds_encoder.v
boards/common/tmds_serializer.v
