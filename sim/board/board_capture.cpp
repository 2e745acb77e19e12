// board_capture.cpp - frames and raster timing from the pixel stream at the pins (see board_capture.h).
#include "board_capture.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace spec {
namespace board {

void VideoCapture::push(const PixelSample& s) {
    s_.push_back(s);
    if (vs_init_ && s.vs != vs_prev_) ++vs_edges_;
    vs_prev_ = s.vs;
    vs_init_ = true;
}

namespace {

struct Lines {
    bool h_pos = false, v_pos = false;
    std::vector<size_t> start;   // sample index of each hsync leading edge (a line runs to the next)
};

Lines cut_lines(const std::vector<PixelSample>& s) {
    Lines L;
    size_t hs1 = 0, vs1 = 0;
    for (const PixelSample& p : s) {
        hs1 += p.hs;
        vs1 += p.vs;
    }
    L.h_pos = hs1 * 2 < s.size();
    L.v_pos = vs1 * 2 < s.size();
    for (size_t i = 1; i < s.size(); ++i) {
        const bool a = (s[i].hs == L.h_pos), b = (s[i - 1].hs == L.h_pos);
        if (a && !b) L.start.push_back(i);
    }
    return L;
}

}  // namespace

MeasuredTiming VideoCapture::measure() const {
    MeasuredTiming m;
    auto problem = [&](const std::string& p) {
        if (m.problems.size() < 20) m.problems.push_back(p);
    };
    const Lines L = cut_lines(s_);
    m.h_pos = L.h_pos;
    m.v_pos = L.v_pos;
    if (L.start.size() < 3) {
        problem("fewer than two whole lines captured");
        return m;
    }
    // horizontal: every whole line alike
    struct LineInfo {
        bool vs = false, has_de = false;
    };
    std::vector<LineInfo> info;
    bool first = true;
    for (size_t k = 0; k + 1 < L.start.size(); ++k) {
        const size_t a = L.start[k], b = L.start[k + 1];
        const int total = int(b - a);
        int sync = 0;
        while (a + size_t(sync) < b && (s_[a + size_t(sync)].hs == L.h_pos)) ++sync;
        LineInfo li;
        li.vs = (s_[a].vs == L.v_pos);
        int de_first = -1, de_n = 0;
        for (size_t i = a; i < b; ++i) {
            if (s_[i].vs != s_[a].vs) problem("vsync changes inside line " + std::to_string(k));
            if (s_[i].de) {
                if (de_first < 0) de_first = int(i - a);
                else if (!s_[i - 1].de) problem("two runs of data enable in line " + std::to_string(k));
                ++de_n;
            }
        }
        li.has_de = de_n > 0;
        info.push_back(li);
        if (first) {
            m.h_total = total;
            m.h_sync = sync;
            first = false;
        } else if (total != m.h_total || sync != m.h_sync) {
            problem("line " + std::to_string(k) + ": " + std::to_string(total) + " pixels, sync " +
                    std::to_string(sync));
        }
        if (li.has_de) {
            const int bp = de_first - sync, fp = total - de_first - de_n;
            if (m.h_active == 0) {
                m.h_active = de_n, m.h_bp = bp, m.h_fp = fp;
            } else if (de_n != m.h_active || bp != m.h_bp || fp != m.h_fp) {
                problem("line " + std::to_string(k) + ": active " + std::to_string(de_n) + ", back porch " +
                        std::to_string(bp) + ", front porch " + std::to_string(fp));
            }
        }
    }
    // vertical: from each vsync leading edge, sync lines, back porch, active, front porch
    std::vector<size_t> vstart;
    for (size_t k = 1; k < info.size(); ++k) {
        if (info[k].vs && !info[k - 1].vs) vstart.push_back(k);
    }
    for (size_t f = 0; f + 1 < vstart.size(); ++f) {
        size_t k = vstart[f];
        const size_t end = vstart[f + 1];
        int sync = 0, bp = 0, act = 0, fp = 0;
        while (k < end && info[k].vs) ++sync, ++k;
        while (k < end && !info[k].has_de) ++bp, ++k;
        while (k < end && info[k].has_de) ++act, ++k;
        while (k < end && !info[k].has_de) ++fp, ++k;
        if (k != end) problem("frame " + std::to_string(f) + ": active lines in two runs");
        const int total = int(end - vstart[f]);
        if (f == 0) {
            m.v_sync = sync, m.v_bp = bp, m.v_active = act, m.v_fp = fp, m.v_total = total;
        } else if (sync != m.v_sync || bp != m.v_bp || act != m.v_active || fp != m.v_fp) {
            problem("frame " + std::to_string(f) + " differs from frame 0");
        }
        const double us = double(s_[L.start[end]].t_ps - s_[L.start[vstart[f]]].t_ps) * 1e-6;
        if (f == 0) m.frame_us = us;
    }
    if (vstart.size() < 2) problem("fewer than one whole frame captured");
    const size_t a = L.start.front(), b = L.start.back();
    if (b > a) m.pixel_mhz = double(b - a) / (double(s_[b].t_ps - s_[a].t_ps) * 1e-6);
    if (m.frame_us > 0) m.refresh_hz = 1e6 / m.frame_us;
    return m;
}

std::vector<Frame> VideoCapture::all_frames(std::vector<bool>* tags) const {
    const Lines L = cut_lines(s_);
    std::vector<Frame> out;
    if (tags) tags->clear();
    // frame k: the active lines following the k-th vsync leading edge, until the next one
    bool in_vs = false, collecting = false, tag = false;
    Frame cur;
    for (size_t k = 0; k + 1 < L.start.size(); ++k) {
        const size_t a = L.start[k], b = L.start[k + 1];
        const bool vs = (s_[a].vs == L.v_pos);
        if (vs && !in_vs) {
            if (collecting && cur.h > 0) {
                out.push_back(cur);
                if (tags) tags->push_back(tag);
            }
            cur = Frame();
            cur.out_bits = out_bits_;
            collecting = true;
        }
        in_vs = vs;
        if (!collecting) continue;
        std::vector<std::array<uint32_t, 3>> row;
        for (size_t i = a; i < b; ++i) {
            if (!s_[i].de) continue;
            if (cur.h == 0 && row.empty()) tag = s_[i].tag;
            row.push_back({s_[i].rgb[0], s_[i].rgb[1], s_[i].rgb[2]});
        }
        if (row.empty()) continue;
        if (cur.w == 0) cur.w = int(row.size());
        if (int(row.size()) != cur.w) throw std::runtime_error("capture: lines of different widths");
        cur.px.insert(cur.px.end(), row.begin(), row.end());
        ++cur.h;
    }
    // the last frame counts only if the next vsync has begun (it is whole)
    return out;
}

std::vector<Frame> VideoCapture::frames(int n) const {
    std::vector<Frame> all = all_frames(nullptr);
    if (int(all.size()) < n) throw std::runtime_error("capture: fewer than " + std::to_string(n) + " whole frames");
    all.resize(size_t(n));
    return all;
}

TimingCheck check_timing(const MeasuredTiming& m, const VideoMode& mode, double pll_mhz) {
    TimingCheck c;
    char buf[160];
    auto row = [&](const char* what, int got, int want) {
        const bool ok = got == want;
        std::snprintf(buf, sizeof buf, "%-14s %8d %8d  %s", what, got, want, ok ? "ok" : "DIFFERS");
        c.rows.push_back(buf);
        c.ok = c.ok && ok;
    };
    row("h_active", m.h_active, mode.h_active);
    row("h_front_porch", m.h_fp, mode.h_fp);
    row("h_sync", m.h_sync, mode.h_sync);
    row("h_back_porch", m.h_bp, mode.h_bp);
    row("h_total", m.h_total, mode.h_total());
    row("v_active", m.v_active, mode.v_active);
    row("v_front_porch", m.v_fp, mode.v_fp);
    row("v_sync", m.v_sync, mode.v_sync);
    row("v_back_porch", m.v_bp, mode.v_bp);
    row("v_total", m.v_total, mode.v_total());
    row("h_sync_pos", m.h_pos, mode.h_pos);
    row("v_sync_pos", m.v_pos, mode.v_pos);
    // the clock: the PLL's frequency (what the design promises), within 10 ppm; the standard's for reference
    const bool clk_ok = std::fabs(m.pixel_mhz - pll_mhz) <= pll_mhz * 1e-5;
    std::snprintf(buf, sizeof buf, "%-14s %8.4f %8.4f  %s (standard %.3f MHz, %+.2f %%)", "pixel_MHz", m.pixel_mhz,
                  pll_mhz, clk_ok ? "ok" : "DIFFERS", mode.pixel_mhz, 100.0 * (m.pixel_mhz / mode.pixel_mhz - 1.0));
    c.rows.push_back(buf);
    c.ok = c.ok && clk_ok;
    const double want_us = 1.0 * mode.h_total() * mode.v_total() / pll_mhz;
    const bool f_ok = std::fabs(m.frame_us - want_us) <= want_us * 1e-5;
    std::snprintf(buf, sizeof buf, "%-14s %8.2f %8.2f  %s (%.3f Hz)", "frame_us", m.frame_us, want_us,
                  f_ok ? "ok" : "DIFFERS", m.refresh_hz);
    c.rows.push_back(buf);
    c.ok = c.ok && f_ok;
    for (const std::string& p : m.problems) {
        c.rows.push_back("problem: " + p);
        c.ok = false;
    }
    return c;
}

}  // namespace board
}  // namespace spec
