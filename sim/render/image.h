// image.h - 8-bit RGB images: PNG through libpng, text labels (stb_easy_font), error maps, the panel.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace spec {
namespace render {

struct Image {
    int w = 0, h = 0;
    std::vector<uint8_t> rgb;  // row-major, 3 bytes a pixel

    Image() = default;
    Image(int w_, int h_, uint8_t r = 0, uint8_t g = 0, uint8_t b = 0);
    uint8_t* at(int x, int y) { return &rgb[(size_t(y) * size_t(w) + size_t(x)) * 3]; }
    const uint8_t* at(int x, int y) const { return &rgb[(size_t(y) * size_t(w) + size_t(x)) * 3]; }
    void fill_rect(int x, int y, int rw, int rh, const uint8_t c[3]);
    void blit(const Image& src, int x, int y);
};

// Writes the image as an 8-bit RGB PNG, atomically (no partial file on failure). Throws std::runtime_error.
void write_png(const std::string& path, const Image& img);
// Reads an 8-bit RGB (or gray / RGBA, converted) PNG. Throws std::runtime_error.
Image read_png(const std::string& path);

// Text in stb_easy_font's built-in font, scaled by an integer factor; returns the width in pixels.
int draw_text(Image& img, int x, int y, const std::string& text, const uint8_t color[3], int scale);
int text_width(const std::string& text, int scale);
int text_height(int scale);

// |a - b| per pixel (largest over the channels), times amp, as a black-red-yellow-white ramp.
Image error_map(const Image& a, const Image& b, double amp);

// Tiles side by side, each with a label strip above it.
struct Tile {
    const Image* img;
    std::string label;
    std::string sublabel;
};
Image make_panel(const std::vector<Tile>& tiles, const std::string& title);

}  // namespace render
}  // namespace spec
