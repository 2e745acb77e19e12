// board_scene.h - what the reference designs put on the monitor (docs/boards.md): the video modes with
// their VESA / CTA-861 figures, the spheres, the light's path and the span split table. One definition,
// used by the bit-exact model, the double-precision reference and boardgen, which writes the tables the
// RTL reads (boards/common/gen/).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace spec {
namespace board {

// A raster: active, front porch, sync, back porch per axis; polarity true = positive pulse.
struct VideoMode {
    std::string name;           // "640x480", "1280x720" or "128x96" (a small test raster)
    std::string standard;       // where the figures come from
    double pixel_mhz = 0;       // the standard's pixel clock
    int h_active = 0, h_fp = 0, h_sync = 0, h_bp = 0;
    int v_active = 0, v_fp = 0, v_sync = 0, v_bp = 0;
    bool h_pos = false, v_pos = false;
    int h_total() const { return h_active + h_fp + h_sync + h_bp; }
    int v_total() const { return v_active + v_fp + v_sync + v_bp; }
};
// Throws UsageError for an unknown name.
VideoMode video_mode(const std::string& name);
std::vector<std::string> video_mode_names();

struct Sphere {
    int cx = 0, cy = 0, r = 0;      // centre (whole pixels) and radius, pixels
    double color[3] = {0, 0, 0};    // diffuse and ambient colour Cd, [0, 1]
    double ka = 0, kd = 0, ks = 0;  // ambient, diffuse, specular coefficients (Is = 1, white light)
    unsigned n = 1;                 // specular exponent
};

struct BoardScene {
    VideoMode mode;
    std::vector<Sphere> spheres;
    double background[3] = {0, 0, 0};
    double elevation_deg = 40;      // the light's angle from the viewing axis
    int frames_per_turn = 256;      // the light turns 2 pi / 256 per frame
    int split_k = 16;               // sub-spans per chord (at most): table of split_k + 1 points
    std::vector<unsigned> split;    // v_j, 0 .. 256 (8 fraction bits), non-decreasing, v_0 = 0, v_K = 256
    int zf = 5;                     // fraction bits of the normals (half-pixel units)
};

// The scene for a video mode and a split table size (k: 1..64; 1 = no split). The spheres are laid out
// for 640 x 480, scaled by 1.5 for 1280 x 720 and by 1/5 for the 128 x 96 test raster. Throws UsageError for an unknown mode or k.
BoardScene make_board_scene(const std::string& mode, int k);

// The split table of k intervals: points equally spaced in the angle phi along the chord's half circle,
// u = -cos(phi), v = round(256 (u + 1) / 2) (docs/boards.md, "Splitting spans").
std::vector<unsigned> split_table(int k);

// Throws std::runtime_error naming the first rule the scene breaks: spheres inside the picture and apart,
// r in 1..255, coefficients in range, ka + kd <= 1, at most 8 spheres.
void check_scene(const BoardScene& s);

// boardgen: the tables the RTL reads, as $readmemh files, and a Verilog header of the scalar constants, into
// dir: scene_<mode>.hex, objects_<mode>.hex, shade_<mode>.hex for both modes, split_<k>.hex for each k,
// light_xy.hex, board_params.vh. Returns the file names written.
std::vector<std::string> write_rtl_tables(const std::string& dir, const std::vector<int>& ks);

}  // namespace board
}  // namespace spec
