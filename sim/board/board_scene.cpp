// board_scene.cpp - video modes, the reference designs' scene and the tables boardgen writes.
#include "board_scene.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "board_model.h"
#include "board_quant.h"
#include "cli.h"
#include "fileutil.h"

namespace spec {
namespace board {

VideoMode video_mode(const std::string& name) {
    VideoMode m;
    m.name = name;
    if (name == "640x480") {
        // VESA DMT (Display Monitor Timing standard, v1.0 rev. 13), 640 x 480 at 60 Hz, DMT ID 04h
        m.standard = "VESA DMT 640x480@60 (DMT ID 04h)";
        m.pixel_mhz = 25.175;
        m.h_active = 640, m.h_fp = 16, m.h_sync = 96, m.h_bp = 48;
        m.v_active = 480, m.v_fp = 10, m.v_sync = 2, m.v_bp = 33;
        m.h_pos = false, m.v_pos = false;
    } else if (name == "1280x720") {
        // CTA-861 video format 4 (1280 x 720p at 59.94 / 60 Hz); the same raster is VESA DMT ID 55h
        m.standard = "CTA-861 VIC 4, 1280x720p@60";
        m.pixel_mhz = 74.25;
        m.h_active = 1280, m.h_fp = 110, m.h_sync = 40, m.h_bp = 220;
        m.v_active = 720, m.v_fp = 5, m.v_sync = 5, m.v_bp = 20;
        m.h_pos = true, m.v_pos = true;
    } else if (name == "128x96") {
        // not a standard: a small raster for the quick board simulation in make test (the 640 x 480 PLL clock),
        // with 800-pixel lines so that the renderer has the time per line it has at 640 x 480
        m.standard = "test raster, no standard";
        m.pixel_mhz = 25.0;
        m.h_active = 128, m.h_fp = 8, m.h_sync = 16, m.h_bp = 648;
        m.v_active = 96, m.v_fp = 2, m.v_sync = 2, m.v_bp = 4;
        m.h_pos = false, m.v_pos = false;
    } else if (name == "320x240" || name == "64x48") {
        // not a raster: the frame buffer of a display mode of twice the size (the iCEBreaker shows it pixel-
        // doubled, docs/boards.md); only the active size matters
        m.standard = "frame buffer, shown pixel-doubled";
        m.pixel_mhz = 0;
        m.h_active = (name == "320x240") ? 320 : 64, m.h_fp = 1, m.h_sync = 1, m.h_bp = 1;
        m.v_active = (name == "320x240") ? 240 : 48, m.v_fp = 1, m.v_sync = 1, m.v_bp = 1;
    } else {
        throw UsageError("unknown video mode '" + name + "' (640x480, 1280x720, 128x96)");
    }
    return m;
}

std::vector<std::string> video_mode_names() { return {"640x480", "1280x720", "128x96", "320x240", "64x48"}; }

std::vector<unsigned> split_table(int k) {
    if (k < 1 || k > 64) throw UsageError("split table: k must be 1..64");
    std::vector<unsigned> v(size_t(k) + 1);
    for (int j = 0; j <= k; ++j) {
        const double u = -std::cos(M_PI * j / k);
        v[size_t(j)] = unsigned(std::lround(128.0 * (u + 1.0)));
    }
    v.front() = 0;
    v.back() = 256;
    return v;
}

BoardScene make_board_scene(const std::string& mode, int k) {
    BoardScene s;
    s.mode = video_mode(mode);
    s.split_k = k;
    s.split = split_table(k);
    // five spheres, one per range of the patent's Fig. 10 and both ends of the last (n = 1, 3, 10, 100, 1000,
    // as in the default scene of specsim render); at most three on any scanline
    struct Layout {
        int cx, cy, r;
        double c0, c1, c2, ka, kd, ks;
        unsigned n;
    };
    const Layout base[] = {
        {110, 130, 80, 0.85, 0.30, 0.22, 0.12, 0.70, 0.50, 1},
        {320, 140, 90, 0.30, 0.72, 0.35, 0.12, 0.68, 0.55, 3},
        {530, 130, 80, 0.28, 0.42, 0.88, 0.12, 0.66, 0.60, 10},
        {200, 345, 100, 0.88, 0.66, 0.22, 0.10, 0.62, 0.70, 100},
        {440, 345, 100, 0.78, 0.78, 0.82, 0.10, 0.55, 0.80, 1000},
    };
    // 1280 x 720: 1.5 times larger, centred (960 x 720 of 1280 x 720); 128 x 96: a fifth; the frame buffers
    // 320 x 240 and 64 x 48: half of 640 x 480 and of 128 x 96
    const bool big = (mode == "1280x720");
    const int div = (mode == "128x96") ? 5 : (mode == "320x240") ? 2 : (mode == "64x48") ? 10 : 1;
    for (const Layout& b : base) {
        Sphere sp;
        sp.cx = big ? 160 + b.cx * 3 / 2 : b.cx / div;
        sp.cy = big ? b.cy * 3 / 2 : b.cy / div;
        sp.r = big ? b.r * 3 / 2 : b.r / div;
        sp.color[0] = b.c0, sp.color[1] = b.c1, sp.color[2] = b.c2;
        sp.ka = b.ka, sp.kd = b.kd, sp.ks = b.ks, sp.n = b.n;
        s.spheres.push_back(sp);
    }
    s.background[0] = 0.05, s.background[1] = 0.06, s.background[2] = 0.09;
    check_scene(s);
    return s;
}

void check_scene(const BoardScene& s) {
    auto bad = [](const std::string& m) { throw std::runtime_error("board scene: " + m); };
    if (s.spheres.empty() || s.spheres.size() > 8) bad("1 to 8 spheres");
    if (s.split.size() != size_t(s.split_k) + 1 || s.split.front() != 0 || s.split.back() != 256) {
        bad("the split table must run from 0 to 256 in split_k intervals");
    }
    for (size_t j = 1; j < s.split.size(); ++j) {
        if (s.split[j] < s.split[j - 1]) bad("the split table must not decrease");
    }
    for (size_t i = 0; i < s.spheres.size(); ++i) {
        const Sphere& a = s.spheres[i];
        const std::string id = "sphere " + std::to_string(i);
        if (a.r < 1 || a.r > 255) bad(id + ": r must be 1..255");
        if (a.cx - a.r < 0 || a.cx + a.r > s.mode.h_active || a.cy - a.r < 0 || a.cy + a.r > s.mode.v_active) {
            bad(id + " leaves the picture");
        }
        for (double c : a.color) {
            if (!(c >= 0 && c <= 1)) bad(id + ": colour outside [0, 1]");
        }
        if (!(a.ka >= 0 && a.kd >= 0 && a.ks >= 0 && a.ka + a.kd <= 1 && a.ks < 1)) {
            bad(id + ": need ka, kd, ks >= 0, ka + kd <= 1, ks < 1");
        }
        if (a.n > 1023) bad(id + ": n must be 0..1023");
        for (size_t j = 0; j < i; ++j) {
            const Sphere& b = s.spheres[j];
            const double d = std::hypot(double(a.cx - b.cx), double(a.cy - b.cy));
            if (d < a.r + b.r + 1) bad(id + " overlaps sphere " + std::to_string(j));
        }
    }
    for (double c : s.background) {
        if (!(c >= 0 && c <= 1)) bad("background colour outside [0, 1]");
    }
}

namespace {

std::string hex(uint64_t v, int digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%0*llx", digits, static_cast<unsigned long long>(v));
    return buf;
}

void write_text(const std::string& path, const std::string& text) {
    render::write_atomic(path, [&](const std::string& tmp) {
        std::ofstream f(tmp, std::ios::binary);
        f << text;
        if (!f.good()) throw std::runtime_error("cannot write " + path);
    });
}

}  // namespace

std::vector<std::string> write_rtl_tables(const std::string& dir, const std::vector<int>& ks) {
    std::vector<std::string> names;
    auto emit = [&](const std::string& name, const std::string& text) {
        write_text(dir + "/" + name, text);
        names.push_back(name);
    };
    std::ostringstream vh;
    vh << "// board_params.vh - generated by boardsim gen from sim/board/board_scene.cpp; do not edit.\n"
       << "// The reference designs' scalar constants (docs/boards.md); the tables are the .hex files beside it.\n"
       << "`ifndef BOARD_PARAMS_VH\n`define BOARD_PARAMS_VH\n";
    BoardScene any;
    for (const std::string& mode : video_mode_names()) {
        const BoardScene s = make_board_scene(mode, 1);
        any = s;
        const Quant q = quantize(s);
        const VideoMode& m = s.mode;
        const std::string p = "`define BOARD" + std::to_string(m.h_active) + "_";
        if (m.pixel_mhz > 0) vh << "// " << m.standard << ", " << m.pixel_mhz << " MHz\n"
           << p << "H_ACTIVE " << m.h_active << "\n" << p << "H_FP " << m.h_fp << "\n" << p << "H_SYNC " << m.h_sync
           << "\n" << p << "H_BP " << m.h_bp << "\n" << p << "V_ACTIVE " << m.v_active << "\n" << p << "V_FP "
           << m.v_fp << "\n" << p << "V_SYNC " << m.v_sync << "\n" << p << "V_BP " << m.v_bp << "\n" << p
           << "H_POL " << (m.h_pos ? 1 : 0) << "\n" << p << "V_POL " << (m.v_pos ? 1 : 0) << "\n";
        else vh << "// frame buffer " << mode << ": tables only\n";
        std::ostringstream sc, ob, sh;
        sc << "// " << mode << ": {cx[10:0], cy[9:0], r2sq[17:0], r2[8:0]} per sphere (boardsim gen)\n";
        ob << "// " << mode << ": {ka[15:0], cd_r[8:0], cd_g[8:0], cd_b[8:0]} per sphere (boardsim gen)\n";
        sh << "// " << mode << ": {n[9:0], kd[15:0], ks[15:0]} per sphere, strengths UQ1.15 (boardsim gen)\n";
        for (size_t i = 0; i < s.spheres.size(); ++i) {
            const Sphere& sp = s.spheres[i];
            const ObjQuant& oq = q.obj[i];
            const uint64_t r2 = uint64_t(2 * sp.r);
            sc << hex((uint64_t(sp.cx) << 37) | (uint64_t(sp.cy) << 27) | ((r2 * r2) << 9) | r2, 12) << "\n";
            ob << hex((uint64_t(oq.ka) << 27) | (uint64_t(oq.cd[0]) << 18) | (uint64_t(oq.cd[1]) << 9) |
                          uint64_t(oq.cd[2]), 11) << "\n";
            sh << hex((uint64_t(oq.n) << 32) | (uint64_t(oq.kd) << 16) | uint64_t(oq.ks), 11) << "\n";
        }
        emit("scene_" + mode + ".hex", sc.str());
        emit("objects_" + mode + ".hex", ob.str());
        emit("shade_" + mode + ".hex", sh.str());
    }
    const Quant q = quantize(any);
    uint32_t bg4 = 0, bg8 = 0;
    const std::array<uint32_t, 3> b4 = background(q, 4), b8 = background(q, 8);
    for (int c = 0; c < 3; ++c) {
        bg4 = (bg4 << 4) | b4[size_t(c)];
        bg8 = (bg8 << 8) | b8[size_t(c)];
    }
    vh << "// the scene: spheres, light, background\n"
       << "`define BOARD_N_OBJ " << any.spheres.size() << "\n"
       << "// the light's z components (x and y: light_xy.hex)\n"
       << "`define BOARD_COS_E " << q.cos_e << "\n`define BOARD_COS_HALF_E " << q.cos_half_e << "\n"
       << "`define BOARD_BG_RGB4 12'h" << hex(bg4, 3) << "\n`define BOARD_BG_RGB8 24'h" << hex(bg8, 6) << "\n"
       << "`endif\n";
    for (int k : ks) {
        std::ostringstream o;
        o << "// split points v_j = round(128 (1 - cos(pi j / " << k << "))), 8 fraction bits (boardsim gen)\n";
        for (unsigned v : split_table(k)) o << hex(v, 3) << "\n";
        emit("split_" + std::to_string(k) + ".hex", o.str());
    }
    {
        std::ostringstream o;
        o << "// light_gen.v's table: word i = round(s_i sin E), word 128 + i = round(s_i sin(E/2)), s_i =\n"
          << "// round(16384 sin(pi i / 128)), i = 0..64, Q1.14, rounded half up; the other words 0 (boardsim gen)\n";
        for (uint32_t v : light_table(q)) o << hex(v, 4) << "\n";
        emit("light_xy.hex", o.str());
    }
    emit("board_params.vh", vh.str());
    return names;
}

}  // namespace board
}  // namespace spec

namespace spec {
namespace board {

Quant quantize(const BoardScene& s) {
    Quant q;
    for (const Sphere& sp : s.spheres) {
        ObjQuant o;
        o.ka = q16(sp.ka);
        for (int c = 0; c < 3; ++c) o.cd[c] = uint32_t(std::lround(sp.color[c] * 256.0));
        o.kd = q15(sp.kd);
        o.ks = q15(sp.ks);
        o.n = sp.n;
        q.obj.push_back(o);
    }
    for (int i = 0; i <= 64; ++i) q.quarter_sin.push_back(uint32_t(std::lround(16384.0 * std::sin(M_PI * i / 128.0))));
    const double e = s.elevation_deg * M_PI / 180.0;
    q.sin_e = q14(std::sin(e));
    q.cos_e = q14(std::cos(e));
    q.sin_half_e = q14(std::sin(e / 2));
    q.cos_half_e = q14(std::cos(e / 2));
    for (int c = 0; c < 3; ++c) q.bg8[c] = uint32_t(std::lround(s.background[c] * 255.0));
    return q;
}

}  // namespace board
}  // namespace spec
