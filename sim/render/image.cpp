#include "image.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

#include <png.h>

#include "fileutil.h"

#ifdef __GNUC__
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#include <stb/stb_easy_font.h>
#ifdef __GNUC__
#pragma GCC diagnostic pop
#endif

namespace spec {
namespace render {

Image::Image(int w_, int h_, uint8_t r, uint8_t g, uint8_t b) : w(w_), h(h_), rgb(size_t(w_) * size_t(h_) * 3) {
    for (size_t i = 0; i < rgb.size(); i += 3) {
        rgb[i] = r;
        rgb[i + 1] = g;
        rgb[i + 2] = b;
    }
}

void Image::fill_rect(int x, int y, int rw, int rh, const uint8_t c[3]) {
    for (int j = std::max(0, y); j < std::min(h, y + rh); ++j) {
        for (int i = std::max(0, x); i < std::min(w, x + rw); ++i) {
            uint8_t* p = at(i, j);
            p[0] = c[0];
            p[1] = c[1];
            p[2] = c[2];
        }
    }
}

void Image::blit(const Image& src, int x, int y) {
    for (int j = 0; j < src.h; ++j) {
        if (y + j < 0 || y + j >= h) continue;
        for (int i = 0; i < src.w; ++i) {
            if (x + i < 0 || x + i >= w) continue;
            std::copy(src.at(i, j), src.at(i, j) + 3, at(x + i, y + j));
        }
    }
}

namespace {
struct PngWrite {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~PngWrite() { png_destroy_write_struct(&png, &info); }
};
struct PngRead {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~PngRead() { png_destroy_read_struct(&png, &info, nullptr); }
};
struct File {
    FILE* f;
    ~File() {
        if (f) std::fclose(f);
    }
};
}  // namespace

void write_png(const std::string& path, const Image& img) {
    if (img.w <= 0 || img.h <= 0) throw std::runtime_error("cannot write an empty image to " + path);
    write_atomic(path, [&](const std::string& tmp) {
        File f{std::fopen(tmp.c_str(), "wb")};
        if (!f.f) throw InputError("cannot write " + path);
        PngWrite p;
        p.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
        if (!p.png) throw std::runtime_error("libpng: out of memory");
        p.info = png_create_info_struct(p.png);
        if (!p.info) throw std::runtime_error("libpng: out of memory");
        if (setjmp(png_jmpbuf(p.png))) throw InputError("cannot write " + path + " (libpng)");
        png_init_io(p.png, f.f);
        png_set_IHDR(p.png, p.info, png_uint_32(img.w), png_uint_32(img.h), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                     PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_set_compression_level(p.png, 9);
        png_write_info(p.png, p.info);
        for (int y = 0; y < img.h; ++y) png_write_row(p.png, const_cast<png_bytep>(img.at(0, y)));
        png_write_end(p.png, nullptr);
        if (std::fflush(f.f) != 0 || std::ferror(f.f)) throw InputError("cannot write " + path);
    });
}

Image read_png(const std::string& path) {
    File f{std::fopen(path.c_str(), "rb")};
    if (!f.f) throw InputError("cannot read " + path);
    PngRead p;
    p.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    if (!p.png) throw std::runtime_error("libpng: out of memory");
    p.info = png_create_info_struct(p.png);
    if (!p.info) throw std::runtime_error("libpng: out of memory");
    Image img;
    if (setjmp(png_jmpbuf(p.png))) throw InputError(path + " is not a readable PNG");
    png_init_io(p.png, f.f);
    png_read_info(p.png, p.info);
    png_set_strip_16(p.png);
    png_set_palette_to_rgb(p.png);
    png_set_gray_to_rgb(p.png);
    png_set_strip_alpha(p.png);
    png_set_expand_gray_1_2_4_to_8(p.png);
    png_read_update_info(p.png, p.info);
    img = Image(int(png_get_image_width(p.png, p.info)), int(png_get_image_height(p.png, p.info)));
    if (png_get_rowbytes(p.png, p.info) != size_t(img.w) * 3) throw std::runtime_error(path + ": unexpected PNG layout");
    for (int y = 0; y < img.h; ++y) png_read_row(p.png, img.at(0, y), nullptr);
    png_read_end(p.png, nullptr);
    return img;
}

int text_width(const std::string& text, int scale) {
    std::vector<char> t(text.begin(), text.end());
    t.push_back('\0');
    return stb_easy_font_width(t.data()) * scale;
}

int text_height(int scale) {
    char t[] = "Ag";
    return stb_easy_font_height(t) * scale;
}

int draw_text(Image& img, int x, int y, const std::string& text, const uint8_t color[3], int scale) {
    std::vector<char> t(text.begin(), text.end());
    t.push_back('\0');
    std::vector<char> buf(text.size() * 300 + 1024);
    const int quads = stb_easy_font_print(0, 0, t.data(), nullptr, buf.data(), int(buf.size()));
    for (int q = 0; q < quads; ++q) {
        float xs[4], ys[4];
        for (int v = 0; v < 4; ++v) {
            const char* vert = buf.data() + (q * 4 + v) * 16;
            std::memcpy(&xs[v], vert, 4);
            std::memcpy(&ys[v], vert + 4, 4);
        }
        const int x0 = int(std::lround(*std::min_element(xs, xs + 4) * scale));
        const int x1 = int(std::lround(*std::max_element(xs, xs + 4) * scale));
        const int y0 = int(std::lround(*std::min_element(ys, ys + 4) * scale));
        const int y1 = int(std::lround(*std::max_element(ys, ys + 4) * scale));
        img.fill_rect(x + x0, y + y0, x1 - x0, y1 - y0, color);
    }
    return text_width(text, scale);
}

Image error_map(const Image& a, const Image& b, double amp) {
    if (a.w != b.w || a.h != b.h) throw std::runtime_error("error_map: images differ in size");
    Image e(a.w, a.h);
    for (int y = 0; y < a.h; ++y) {
        for (int x = 0; x < a.w; ++x) {
            int d = 0;
            for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.at(x, y)[c]) - int(b.at(x, y)[c])));
            const double v = std::min(1.0, d * amp / 255.0);  // 0 .. 1
            uint8_t* p = e.at(x, y);
            // black -> red -> yellow -> white
            p[0] = uint8_t(std::lround(255 * std::min(1.0, 3 * v)));
            p[1] = uint8_t(std::lround(255 * std::min(1.0, std::max(0.0, 3 * v - 1))));
            p[2] = uint8_t(std::lround(255 * std::min(1.0, std::max(0.0, 3 * v - 2))));
        }
    }
    return e;
}

Image make_panel(const std::vector<Tile>& tiles, const std::string& title) {
    const int gap = 6, scale = tiles.empty() || tiles[0].img->w >= 200 ? 2 : 1;
    const int th = text_height(scale);
    const int title_h = title.empty() ? 0 : th + 2 * gap;
    const int label_h = 2 * th + 3 * gap;
    int w = gap, h = 0;
    for (const auto& t : tiles) {
        w += t.img->w + gap;
        h = std::max(h, t.img->h);
    }
    Image p(w, title_h + label_h + h + gap, 24, 24, 28);
    const uint8_t white[3] = {235, 235, 235}, grey[3] = {170, 170, 175};
    if (!title.empty()) draw_text(p, gap, gap, title, white, scale);
    int x = gap;
    for (const auto& t : tiles) {
        draw_text(p, x, title_h + gap, t.label, white, scale);
        draw_text(p, x, title_h + 2 * gap + th, t.sublabel, grey, scale);
        p.blit(*t.img, x, title_h + label_h);
        x += t.img->w + gap;
    }
    return p;
}

}  // namespace render
}  // namespace spec
