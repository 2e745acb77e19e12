#include "setup_sched.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace spec {

SetupLatency setup_latency(const SetupFormat& sf) {
    (void)sf;
    SetupLatency l{};
    // issue (bank read) + the unit's pipeline; rtl/spec_setup_*.v state the same numbers (LAT) and
    // spec_setup_machine stops elaboration when they differ from setup_params.vh's
    l.lat[static_cast<int>(SetupUnit::IDOT)] = 7;
    l.lat[static_cast<int>(SetupUnit::MUL)] = 7;
    l.lat[static_cast<int>(SetupUnit::ADD)] = 8;
    l.lat[static_cast<int>(SetupUnit::EFU)] = 9;
    l.lat[static_cast<int>(SetupUnit::MISC)] = 3;
    return l;
}

namespace {

int count_of(const SetupMachine& m, SetupUnit u) {
    switch (u) {
        case SetupUnit::IDOT: return m.idot;
        case SetupUnit::MUL: return m.mul;
        case SetupUnit::ADD: return m.add;
        case SetupUnit::EFU: return m.efu;
        case SetupUnit::MISC: return m.misc;
        default: break;
    }
    return 0;
}

bool commutative(const SetupNode& x) {
    switch (x.op) {
        case SetupOp::FMUL: case SetupOp::MIN: case SetupOp::MAX: return true;
        case SetupOp::FADD: return x.bscale == 0;
        default: return false;
    }
}

int bits_for(int n) {   // bits to number 0 .. n-1 (at least 1)
    int b = 1;
    while ((1 << b) < n) ++b;
    return b;
}

// The operand on port j of node x (after a swap). SEL: ports 0, 1 take the two values, port 2 the condition
// (its bank keeps one bit: not zero).
const SetupRef& port_ref(const SetupNode& x, bool swapped, int j) {
    if (x.op == SetupOp::SEL) return j == 0 ? x.b : (j == 1 ? x.c : x.a);
    if (swapped && j < 2) return j == 0 ? x.b : x.a;
    return j == 0 ? x.a : (j == 1 ? x.b : x.c);
}

struct Consumer {
    int node, port;
};

}  // namespace

constexpr int kSetupAttempts = 64;   // bindings tried at each II

SetupSchedule setup_schedule(const SetupFormat& sf, const SetupProgram& p) {
    const SetupLatency L = setup_latency(sf);
    SetupSchedule s;
    const size_t N = p.n.size();
    // ---- units and banks
    s.unit_first.assign(kSetupUnitTypes + 1, 0);
    for (int ty = 0; ty < kSetupUnitTypes; ++ty) {
        s.unit_first[ty] = static_cast<int>(s.unit.size());
        for (int i = 0; i < count_of(sf.mach, static_cast<SetupUnit>(ty)); ++i) s.unit.push_back({static_cast<SetupUnit>(ty), i});
    }
    s.units = static_cast<int>(s.unit.size());
    s.unit_first[kSetupUnitTypes] = s.units;
    s.out_unit = s.units;
    s.bank_of.assign(static_cast<size_t>(s.units + 1) * 3, -1);
    auto ports_of = [](SetupUnit u) {
        switch (u) {
            case SetupUnit::MUL: case SetupUnit::ADD: return 2;
            case SetupUnit::EFU: return 1;
            case SetupUnit::MISC: return 3;
            default: return 0;
        }
    };
    for (int u = 0; u < s.units; ++u)
        for (int j = 0; j < ports_of(s.unit[u].type); ++j) {
            s.bank_of[static_cast<size_t>(u) * 3 + j] = static_cast<int>(s.banks.size());
            SetupBank b;
            b.unit = u;
            b.port = j;
            s.banks.push_back(b);
        }
    s.bank_of[static_cast<size_t>(s.out_unit) * 3] = static_cast<int>(s.banks.size());
    {
        SetupBank b;
        b.unit = s.out_unit;
        s.banks.push_back(b);
    }
    const int out_bank = static_cast<int>(s.banks.size()) - 1;

    // ---- priorities: the longest path to the end (height); a topological order
    std::vector<int> lat(N, 0);
    for (size_t i = 0; i < N; ++i) {
        const SetupUnit ty = setup_op_unit(p.n[i].op);
        if (ty != SetupUnit::NONE) lat[i] = L.lat[static_cast<int>(ty)];
    }
    std::vector<std::vector<int>> users(N);
    for (size_t i = 0; i < N; ++i)
        for (int j = 0; j < setup_op_operands(p.n[i].op); ++j) {
            const SetupRef& r = port_ref(p.n[i], false, j);
            if (p.n[r.id].op != SetupOp::CONST) users[r.id].push_back(static_cast<int>(i));
        }
    std::vector<int> height(N, 0);
    for (size_t i = N; i-- > 0;) {
        if (setup_op_unit(p.n[i].op) == SetupUnit::NONE) continue;
        int h = 0;
        for (int c : users[i]) h = std::max(h, height[static_cast<size_t>(c)]);
        height[i] = h + lat[i] + 1;
    }
    std::vector<int> cap(kSetupUnitTypes, 0);
    int ii0 = SO_COUNT + 2;   // the finish reads SO_COUNT fields a span and keeps them two clocks more
    for (int ty = 0; ty < kSetupUnitTypes; ++ty) {
        const int n = count_of(sf.mach, static_cast<SetupUnit>(ty));
        const int ops = p.count(static_cast<SetupUnit>(ty));
        if (ops > 0 && n == 0) throw std::logic_error("setup schedule: no unit for an operation type");
        cap[ty] = n > 0 ? (ops + n - 1) / n : 0;
        ii0 = std::max(ii0, cap[ty]);
    }
    const int max_ii = sf.mach.max_ii > 0 ? sf.mach.max_ii : 4 * ii0 + 16;
    uint64_t rs = 0x9e3779b97f4a7c15ull;   // a fixed xorshift sequence: the same schedule on every host
    auto rnd = [&rs](int n) {
        rs ^= rs << 13;
        rs ^= rs >> 7;
        rs ^= rs << 17;
        return static_cast<int>(rs % static_cast<uint64_t>(n));
    };
    std::vector<std::vector<Consumer>> cons(N);
    std::vector<std::vector<int>> dest(N);
    std::vector<std::set<int>> srcset(s.banks.size());
    std::vector<int> load(static_cast<size_t>(s.units), 0);
    std::vector<int> t(N, -1);
    // Each II is tried with kSetupAttempts bindings: the first load balanced, preferring instances whose banks
    // already take the operands' producers (fewer write sources a bank), the others with random tie-breaks
    // in the binding's costs and the order of equal heights.
    for (int ii = ii0; ii <= max_ii; ++ii) {
        bool ok = false;
        for (int attempt = 0; attempt < kSetupAttempts && !ok; ++attempt) {
            const int noise = attempt == 0 ? 0 : 1 + attempt % 4;
            std::vector<int> key(N);
            for (size_t i = 0; i < N; ++i) key[i] = 8 * height[i] + (attempt == 0 ? 0 : rnd(8 + 4 * noise));
            std::vector<size_t> order(N);
            for (size_t i = 0; i < N; ++i) order[i] = i;
            std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return key[a] > key[b]; });
            // binding
            s.inst.assign(N, -1);
            s.swapped.assign(N, 0);
            load.assign(static_cast<size_t>(s.units), 0);
            for (auto& ss : srcset) ss.clear();
            for (size_t i = 0; i < N; ++i) {
                const SetupNode& x = p.n[i];
                const SetupUnit ty = setup_op_unit(x.op);
                if (ty == SetupUnit::NONE) continue;
                const int ty_i = static_cast<int>(ty);
                int best = -1, best_cost = 1 << 30;
                bool best_sw = false;
                for (int k = 0; k < count_of(sf.mach, ty); ++k) {
                    const int u = s.unit_first[ty_i] + k;
                    if (load[u] >= cap[ty_i]) continue;
                    for (int sw = 0; sw < (commutative(x) ? 2 : 1); ++sw) {
                        int cost = 4 * load[u] + (noise ? rnd(4 * noise + 1) : 0);
                        for (int j = 0; j < setup_op_operands(x.op); ++j) {
                            const SetupRef& r = port_ref(x, sw != 0, j);
                            if (p.n[r.id].op == SetupOp::CONST) continue;
                            const int bk = s.bank_of[static_cast<size_t>(u) * 3 + j];
                            if (!srcset[bk].count(s.inst[r.id])) cost += 16;
                        }
                        if (cost < best_cost) {
                            best_cost = cost;
                            best = u;
                            best_sw = sw != 0;
                        }
                    }
                }
                if (best < 0) throw std::logic_error("setup schedule: binding found no instance");
                s.inst[i] = best;
                s.swapped[i] = best_sw;
                ++load[best];
                for (int j = 0; j < setup_op_operands(x.op); ++j) {
                    const SetupRef& r = port_ref(x, best_sw, j);
                    if (p.n[r.id].op != SetupOp::CONST) srcset[s.bank_of[static_cast<size_t>(best) * 3 + j]].insert(s.inst[r.id]);
                }
            }
            for (int o = 0; o < SO_COUNT; ++o) srcset[out_bank].insert(s.inst[p.out[o]]);
            // consumers of each value: (node, port); the banks each value is written into
            for (size_t i = 0; i < N; ++i) {
                cons[i].clear();
                dest[i].clear();
            }
            for (size_t i = 0; i < N; ++i) {
                const SetupNode& x = p.n[i];
                for (int j = 0; j < setup_op_operands(x.op); ++j) {
                    const SetupRef& r = port_ref(x, s.swapped[i] != 0, j);
                    if (p.n[r.id].op == SetupOp::CONST) continue;
                    cons[r.id].push_back({static_cast<int>(i), j});
                    const int bk = s.bank_of[static_cast<size_t>(s.inst[i]) * 3 + j];
                    if (std::find(dest[r.id].begin(), dest[r.id].end(), bk) == dest[r.id].end()) dest[r.id].push_back(bk);
                }
            }
            for (int o = 0; o < SO_COUNT; ++o) {
                auto& d = dest[static_cast<size_t>(p.out[o])];
                if (std::find(d.begin(), d.end(), out_bank) == d.end()) d.push_back(out_bank);
            }
            {   // a bank takes one write a clock
                std::vector<int> writes(s.banks.size(), 0);
                bool over = false;
                for (size_t i = 0; i < N; ++i)
                    for (int bk : dest[i]) over |= ++writes[static_cast<size_t>(bk)] > ii;
                if (over) continue;
            }
            // list scheduling in that order, each operation at its earliest time with its issue slot and every
            // destination bank's write slot free
            std::vector<std::vector<char>> mrt(static_cast<size_t>(s.units), std::vector<char>(static_cast<size_t>(ii), 0));
            std::vector<std::vector<char>> wrt(s.banks.size(), std::vector<char>(static_cast<size_t>(ii), 0));
            t.assign(N, -1);
            ok = true;
            for (size_t oi = 0; oi < N && ok; ++oi) {
                const size_t i = order[oi];
                const SetupNode& x = p.n[i];
                const SetupUnit ty = setup_op_unit(x.op);
                if (ty == SetupUnit::NONE) continue;
                int est = 0;
                for (int j = 0; j < setup_op_operands(x.op); ++j) {
                    const SetupRef& r = port_ref(x, false, j);
                    if (p.n[r.id].op != SetupOp::CONST) est = std::max(est, t[r.id] + lat[r.id] + 1);
                }
                const int u = s.inst[i];
                bool placed = false;
                for (int tt = est; tt < est + ii * 4 && !placed; ++tt) {
                    if (ty == SetupUnit::IDOT && tt >= kSetupLin * ii) break;
                    if (mrt[u][tt % ii]) continue;
                    const int w = (tt + lat[i]) % ii;
                    bool free = true;
                    for (int bk : dest[i]) free &= !wrt[bk][w];
                    if (!free) continue;
                    mrt[u][tt % ii] = 1;
                    for (int bk : dest[i]) wrt[bk][w] = 1;
                    t[i] = tt;
                    placed = true;
                }
                ok = placed;
            }
        }
        if (!ok) continue;
        // the finish: after the last result, field j at t_fin + j
        int t_fin = 0;
        for (int o = 0; o < SO_COUNT; ++o) {
            const int id = p.out[o];
            t_fin = std::max(t_fin, t[id] + L.lat[static_cast<int>(setup_op_unit(p.n[id].op))] + 1 - o);
        }
        // lifetimes -> LMAX
        struct Life {
            int node, bank, w, r;
        };
        std::vector<Life> lives;
        int longest = 0;
        for (size_t i = 0; i < N; ++i) {
            const SetupUnit ty = setup_op_unit(p.n[i].op);
            if (ty == SetupUnit::NONE) continue;
            const int w = t[i] + L.lat[static_cast<int>(ty)];
            for (int b : dest[i]) {
                int r = w + 1;
                for (const Consumer& c : cons[i])
                    if (s.bank_of[static_cast<size_t>(s.inst[c.node]) * 3 + c.port] == b) r = std::max(r, t[c.node]);
                if (b == out_bank)
                    for (int o = 0; o < SO_COUNT; ++o)
                        if (p.out[o] == static_cast<int>(i)) r = std::max(r, t_fin + o);
                lives.push_back({static_cast<int>(i), b, w, r});
                longest = std::max(longest, r - w);
            }
        }
        int lg = 0;
        while ((1 << lg) * ii <= longest) ++lg;
        const int P = (1 << lg) * ii;
        // slots: circular-arc colouring per bank (period P)
        std::vector<std::vector<std::pair<int, int>>> occ(s.banks.size());   // per bank: slot -> arcs
        std::vector<std::vector<std::vector<std::pair<int, int>>>> slot_arcs(s.banks.size());
        std::map<std::pair<int, int>, int> slot_of;   // (node, bank) -> slot
        std::sort(lives.begin(), lives.end(), [](const Life& a, const Life& b) { return a.w < b.w; });
        auto overlaps = [P](int w1, int r1, int w2, int r2) {   // circular intervals [w, r] mod P
            for (int k = -2; k <= 2; ++k)
                if (!(r2 + k * P < w1 || w2 + k * P > r1)) return true;
            return false;
        };
        for (const Life& lf : lives) {
            auto& arcs = slot_arcs[lf.bank];
            int slot = -1;
            for (size_t k = 0; k < arcs.size() && slot < 0; ++k) {
                bool clash = false;
                for (const auto& a : arcs[k]) clash |= overlaps(lf.w, lf.r, a.first, a.second);
                if (!clash) slot = static_cast<int>(k);
            }
            if (slot < 0) {
                slot = static_cast<int>(arcs.size());
                arcs.emplace_back();
            }
            arcs[static_cast<size_t>(slot)].push_back({lf.w, lf.r});
            slot_of[{lf.node, lf.bank}] = slot;
        }
        // ---- the schedule
        s.ii = ii;
        s.lmax_log2 = lg;
        s.t_fin = t_fin;
        s.latency = t_fin + SO_COUNT + 4;
        s.t = t;
        s.src.assign(N, {{0, 0, 0}});
        for (size_t b = 0; b < s.banks.size(); ++b) {
            s.banks[b].sources.assign(srcset[b].begin(), srcset[b].end());
            s.banks[b].slots = std::max<int>(1, static_cast<int>(slot_arcs[b].size()));
        }
        for (size_t i = 0; i < N; ++i) {
            const SetupNode& x = p.n[i];
            if (setup_op_unit(x.op) == SetupUnit::NONE) continue;
            for (int j = 0; j < setup_op_operands(x.op); ++j) {
                const SetupRef& r = port_ref(x, s.swapped[i] != 0, j);
                const int b = s.bank_of[static_cast<size_t>(s.inst[i]) * 3 + j];
                if (p.n[r.id].op == SetupOp::CONST) {
                    auto& cs = s.banks[b].consts;
                    auto it = std::find(cs.begin(), cs.end(), p.n[r.id].k);
                    if (it == cs.end()) {
                        cs.push_back(p.n[r.id].k);
                        it = cs.end() - 1;
                    }
                    s.src[i][j] = -1 - static_cast<int>(it - cs.begin());
                } else {
                    s.src[i][j] = slot_of.at({r.id, b});
                }
            }
        }
        s.out_slot.assign(SO_COUNT, 0);
        for (int o = 0; o < SO_COUNT; ++o) s.out_slot[o] = slot_of.at({p.out[o], out_bank});
        s.ops_per_unit = load;
        for (const SetupBank& b : s.banks) {
            s.max_sources = std::max<int>(s.max_sources, static_cast<int>(b.sources.size()));
            s.max_slots = std::max(s.max_slots, b.slots);
        }
        // the write side needs the slot of every (value, bank): kept in slot_of, re-derived by the microcode
        // emitter from src (consumer ports) and out_slot; a value written into a bank no port of it reads from
        // cannot happen (dest lists only consumer banks)
        return s;
    }
    throw std::runtime_error("setup schedule: no schedule within II " + std::to_string(max_ii) + " (least bound " +
                             std::to_string(ii0) + ")");
}

std::string setup_schedule_report(const SetupFormat& sf, const SetupProgram& p, const SetupSchedule& s) {
    std::ostringstream o;
    o << "configuration " << sf.name << ": II " << s.ii << " clocks a span, latency " << s.latency << ", LMAX "
      << (1 << s.lmax_log2) << ", banks " << s.banks.size() << " (most sources " << s.max_sources << ", most slots "
      << s.max_slots << ")\n";
    for (int ty = 0; ty < kSetupUnitTypes; ++ty) {
        const SetupUnit u = static_cast<SetupUnit>(ty);
        o << "  " << setup_unit_name(u) << ": " << p.count(u) << " operations on " << (s.unit_first[ty + 1] - s.unit_first[ty])
          << " units\n";
    }
    return o.str();
}

// ---- microcode -------------------------------------------------------------------------------------------------
SetupUcodeLayout setup_ucode_layout(const SetupFormat& sf, const SetupSchedule& s) {
    (void)sf;
    SetupUcodeLayout l;
    int slots = 1, consts = 0, srcs = 1;
    for (const SetupBank& b : s.banks) {
        slots = std::max(slots, b.slots);
        consts = std::max<int>(consts, static_cast<int>(b.consts.size()));
        srcs = std::max<int>(srcs, static_cast<int>(b.sources.size()));
    }
    l.addr_w = bits_for(slots);
    l.csel_w = bits_for(consts + 1);
    l.wsrc_w = bits_for(srcs);
    // stages: enough bits for the finish's last read (the span index the finish tags its side information with);
    // a bank address takes the low lmax_log2 bits of S - stage
    l.stage_w = std::max(1, std::max(s.lmax_log2, bits_for((s.t_fin + SO_COUNT) / s.ii + 1)));
    l.op_w = 11;   // IDOT: mode 3, va 3, vb 3, comp 2; ADD: bscale 3; EFU, MISC: 2; OUT: the field (4)
    int off = 0;
    const int U = s.units + 1;   // with the OUT pseudo-unit: go = a read for the finish, op = the field, port 0
    l.go.assign(U, 0);
    l.op.assign(U, 0);
    l.scale.assign(U, 0);
    l.addr.assign(U, {{0, 0, 0}});
    l.stage = l.csel = l.neg = l.absb = l.addr;
    for (int u = 0; u < U; ++u) {
        l.go[u] = off++;
        l.op[u] = off;
        off += l.op_w;
        l.scale[u] = off;
        off += l.scale_w;
        if (u < s.units && s.unit[static_cast<size_t>(u)].type == SetupUnit::IDOT) {   // the stage of the beat it reads
            l.stage[u][0] = off;
            off += l.stage_w;
        }
        for (int j = 0; j < 3; ++j) {
            if (s.bank_of[static_cast<size_t>(u) * 3 + j] < 0) continue;
            l.addr[u][j] = off;
            off += l.addr_w;
            l.stage[u][j] = off;
            off += l.stage_w;
            l.csel[u][j] = off;
            off += l.csel_w;
            l.neg[u][j] = off++;
            l.absb[u][j] = off++;
        }
    }
    const size_t B = s.banks.size();
    l.we.assign(B, 0);
    l.wsrc.assign(B, 0);
    l.waddr.assign(B, 0);
    l.wstage.assign(B, 0);
    for (size_t b = 0; b < B; ++b) {
        l.we[b] = off++;
        l.wsrc[b] = off;
        off += l.wsrc_w;
        l.waddr[b] = off;
        off += l.addr_w;
        l.wstage[b] = off;
        off += l.stage_w;
    }
    l.w = off;
    return l;
}

namespace {
void put(std::vector<uint64_t>& w, int lsb, int width, uint64_t v) {
    for (int b = 0; b < width; ++b) {
        const int pos = lsb + b;
        const uint64_t m = uint64_t(1) << (pos % 64);
        if ((v >> b) & 1) w[static_cast<size_t>(pos / 64)] |= m;
        else w[static_cast<size_t>(pos / 64)] &= ~m;
    }
}
uint64_t get(const std::vector<uint64_t>& w, int lsb, int width) {
    uint64_t v = 0;
    for (int b = 0; b < width; ++b) {
        const int pos = lsb + b;
        v |= ((w[static_cast<size_t>(pos / 64)] >> (pos % 64)) & 1) << b;
    }
    return v;
}
int efu_code(SetupOp o) {
    switch (o) {
        case SetupOp::RSQRT: return 0;
        case SetupOp::RCP: return 1;
        case SetupOp::ATANG: return 2;
        default: return 3;   // LOG2
    }
}
int misc_code(SetupOp o) {
    switch (o) {
        case SetupOp::CMPLT: return 0;
        case SetupOp::SEL: return 1;
        case SetupOp::MIN: return 2;
        default: return 3;   // MAX
    }
}
}  // namespace

std::vector<std::vector<uint64_t>> setup_ucode(const SetupFormat& sf, const SetupProgram& p, const SetupSchedule& s,
                                               const SetupUcodeLayout& l) {
    const SetupLatency L = setup_latency(sf);
    const int ii = s.ii, lm = s.lmax_log2;
    std::vector<std::vector<uint64_t>> uc(static_cast<size_t>(ii), std::vector<uint64_t>(static_cast<size_t>((l.w + 63) / 64), 0));
    (void)lm;
    auto stage = [&](int t) { return static_cast<uint64_t>(t / ii); };
    for (size_t i = 0; i < p.n.size(); ++i) {
        const SetupNode& x = p.n[i];
        const SetupUnit ty = setup_op_unit(x.op);
        if (ty == SetupUnit::NONE) continue;
        const int u = s.inst[i], t = s.t[i];
        std::vector<uint64_t>& w = uc[static_cast<size_t>(t % ii)];
        put(w, l.go[u], 1, 1);
        uint64_t op = 0;
        switch (ty) {
            case SetupUnit::IDOT:
                op = uint64_t(static_cast<int>(x.mode)) | uint64_t(x.va) << 3 | uint64_t(x.vb) << 6 | uint64_t(x.comp) << 9;
                break;
            case SetupUnit::ADD: op = static_cast<uint64_t>(x.bscale) & 7; break;
            case SetupUnit::EFU: op = static_cast<uint64_t>(efu_code(x.op)); break;
            case SetupUnit::MISC: op = static_cast<uint64_t>(misc_code(x.op)); break;
            default: break;
        }
        put(w, l.op[u], l.op_w, op);
        put(w, l.scale[u], l.scale_w, static_cast<uint64_t>(ty == SetupUnit::IDOT ? 0 : x.scale) & 15);
        if (ty == SetupUnit::IDOT) put(w, l.stage[u][0], l.stage_w, static_cast<uint64_t>(t / ii));
        for (int j = 0; j < setup_op_operands(x.op); ++j) {
            const SetupRef& r = port_ref(x, s.swapped[i] != 0, j);
            const int src = s.src[i][static_cast<size_t>(j)];
            if (src < 0) {
                put(w, l.csel[u][j], l.csel_w, static_cast<uint64_t>(-src));   // const k -> k + 1
            } else {
                put(w, l.addr[u][j], l.addr_w, static_cast<uint64_t>(src));
                put(w, l.stage[u][j], l.stage_w, stage(t));
            }
            put(w, l.neg[u][j], 1, r.neg);
            put(w, l.absb[u][j], 1, r.abs);
        }
    }
    // writes: every value into the bank of each port that reads it, LAT clocks after its issue
    std::vector<std::vector<int>> dest_slot(p.n.size());
    for (size_t i = 0; i < p.n.size(); ++i) {
        const SetupNode& x = p.n[i];
        if (setup_op_unit(x.op) == SetupUnit::NONE) continue;
        for (int j = 0; j < setup_op_operands(x.op); ++j) {
            const int src = s.src[i][static_cast<size_t>(j)];
            if (src < 0) continue;
            const SetupRef& r = port_ref(x, s.swapped[i] != 0, j);
            const int b = s.bank_of[static_cast<size_t>(s.inst[i]) * 3 + j];
            const int tw = s.t[r.id] + L.lat[static_cast<int>(setup_op_unit(p.n[r.id].op))];
            std::vector<uint64_t>& w = uc[static_cast<size_t>(tw % ii)];
            const auto& srcs = s.banks[static_cast<size_t>(b)].sources;
            const int k = static_cast<int>(std::find(srcs.begin(), srcs.end(), s.inst[r.id]) - srcs.begin());
            put(w, l.we[b], 1, 1);
            put(w, l.wsrc[b], l.wsrc_w, static_cast<uint64_t>(k));
            put(w, l.waddr[b], l.addr_w, static_cast<uint64_t>(src));
            put(w, l.wstage[b], l.stage_w, stage(tw));
        }
    }
    const int ob = static_cast<int>(s.banks.size()) - 1;
    for (int o = 0; o < SO_COUNT; ++o) {   // the finish's reads: field o at t_fin + o
        const int t = s.t_fin + o, u = s.out_unit;
        std::vector<uint64_t>& w = uc[static_cast<size_t>(t % ii)];
        put(w, l.go[u], 1, 1);
        put(w, l.op[u], l.op_w, static_cast<uint64_t>(o));
        put(w, l.addr[u][0], l.addr_w, static_cast<uint64_t>(s.out_slot[o]));
        put(w, l.stage[u][0], l.stage_w, stage(t));
    }
    for (int o = 0; o < SO_COUNT; ++o) {
        const int id = p.out[o];
        const int tw = s.t[id] + L.lat[static_cast<int>(setup_op_unit(p.n[id].op))];
        std::vector<uint64_t>& w = uc[static_cast<size_t>(tw % ii)];
        const auto& srcs = s.banks[static_cast<size_t>(ob)].sources;
        const int k = static_cast<int>(std::find(srcs.begin(), srcs.end(), s.inst[id]) - srcs.begin());
        put(w, l.we[ob], 1, 1);
        put(w, l.wsrc[ob], l.wsrc_w, static_cast<uint64_t>(k));
        put(w, l.waddr[ob], l.addr_w, static_cast<uint64_t>(s.out_slot[o]));
        put(w, l.wstage[ob], l.stage_w, stage(tw));
    }
    return uc;
}

// ---- the machine, cycle by cycle ------------------------------------------------------------------------------
SetupMachineSim::SetupMachineSim(const SetupFormat& sf, const SetupProgram& p, const SetupTables& t,
                                 const SetupSchedule& s)
    : sf_(sf), p_(p), t_(t), s_(s), lay_(setup_ucode_layout(sf, s)), uc_(setup_ucode(sf, p, s, lay_)) {}

std::vector<std::array<Fp, SO_COUNT>> SetupMachineSim::run(const std::vector<SetupBeat>& beats) {
    const SetupLatency L = setup_latency(sf_);
    const FpFmt& f = sf_.fp;
    const int ii = s_.ii, lmax = 1 << s_.lmax_log2;
    const size_t B = s_.banks.size();
    std::vector<std::vector<Fp>> bank(B);
    for (size_t b = 0; b < B; ++b) bank[b].assign(static_cast<size_t>(s_.banks[b].slots * lmax), Fp());
    std::vector<SetupBeat> beat_buf(kSetupLin);
    const int U = s_.units;
    // results in flight: (cycle due, unit) -> value
    std::map<std::pair<long, int>, Fp> flight;
    const size_t nspans = beats.size();
    std::vector<std::array<Fp, SO_COUNT>> out(nspans);
    const long cycles = static_cast<long>(nspans + 4) * ii + s_.t_fin + SO_COUNT + 8 * ii + 16;
    SetupNode dummy;
    trace_.assign(p_.n.size(), Fp());
    const uint64_t smask = static_cast<uint64_t>(lmax - 1);
    auto addr = [&](uint64_t slot, uint64_t stg, long S) {
        return static_cast<size_t>(slot * static_cast<uint64_t>(lmax) + ((static_cast<uint64_t>(S) - stg) & smask));
    };
    for (long c = 0; c < cycles; ++c) {
        const int tau = static_cast<int>(c % ii);
        const long S = c / ii;
        if (tau == 0) beat_buf[static_cast<size_t>(S % kSetupLin)] = static_cast<size_t>(S) < nspans ? beats[static_cast<size_t>(S)] : SetupBeat();
        const std::vector<uint64_t>& w = uc_[static_cast<size_t>(tau)];
        // issue (reads before this clock's writes)
        for (int u = 0; u < U; ++u) {
            if (!get(w, lay_.go[u], 1)) continue;
            const SetupUnit ty = s_.unit[static_cast<size_t>(u)].type;
            SetupNode x;
            const uint64_t op = get(w, lay_.op[u], lay_.op_w);
            int sc = static_cast<int>(get(w, lay_.scale[u], lay_.scale_w));
            if (sc >= 8) sc -= 16;
            x.scale = sc;
            std::vector<Fp> v(3);
            switch (ty) {
                case SetupUnit::IDOT: {
                    x.op = SetupOp::IDOT;
                    x.mode = static_cast<IdotMode>(op & 7);
                    x.va = static_cast<uint8_t>((op >> 3) & 7);
                    x.vb = static_cast<uint8_t>((op >> 6) & 7);
                    x.comp = static_cast<uint8_t>((op >> 9) & 3);
                    x.scale = (x.mode == IdotMode::SCALAR && x.comp == BS_STRENGTH) ? -sf_.str_frac : 0;
                    // the beat of this operation's span: stage = S - span; the IDOT ops are in stage 0 or 1 and
                    // read the buffer entry that span filled
                    break;
                }
                case SetupUnit::MUL: x.op = SetupOp::FMUL; break;
                case SetupUnit::ADD: {
                    x.op = SetupOp::FADD;
                    int bs = static_cast<int>(op & 7);
                    if (bs >= 4) bs -= 8;
                    x.bscale = bs;
                    break;
                }
                case SetupUnit::EFU: {
                    static const SetupOp e[4] = {SetupOp::RSQRT, SetupOp::RCP, SetupOp::ATANG, SetupOp::LOG2};
                    x.op = e[op & 3];
                    break;
                }
                case SetupUnit::MISC: {
                    static const SetupOp m[4] = {SetupOp::CMPLT, SetupOp::SEL, SetupOp::MIN, SetupOp::MAX};
                    x.op = m[op & 3];
                    break;
                }
                default: break;
            }
            Fp r;
            if (ty == SetupUnit::IDOT) {
                const int stg = static_cast<int>(get(w, lay_.stage[u][0], lay_.stage_w));
                const SetupBeat& bt = beat_buf[static_cast<size_t>(((S - stg) % kSetupLin + kSetupLin) % kSetupLin)];
                r = fp_from_int(f, setup_idot(x, bt), x.scale);
            } else {
                std::vector<Fp> vals(3);
                for (int j = 0; j < 3; ++j) {
                    const int b = s_.bank_of[static_cast<size_t>(u) * 3 + j];
                    if (b < 0) continue;
                    const uint64_t cs = get(w, lay_.csel[u][j], lay_.csel_w);
                    Fp a;
                    if (cs) a = s_.banks[static_cast<size_t>(b)].consts.at(cs - 1);
                    else a = bank[static_cast<size_t>(b)][addr(get(w, lay_.addr[u][j], lay_.addr_w), get(w, lay_.stage[u][j], lay_.stage_w), S)];
                    if (get(w, lay_.absb[u][j], 1)) a = fp_abs(a);
                    if (get(w, lay_.neg[u][j], 1)) a = fp_neg(a);
                    vals[static_cast<size_t>(j)] = a;
                }
                // evaluate with the ports' operands as refs of a scratch vector (SEL: condition on port 2)
                x.a.id = x.op == SetupOp::SEL ? 2 : 0;
                x.b.id = x.op == SetupOp::SEL ? 0 : 1;
                x.c.id = x.op == SetupOp::SEL ? 1 : 2;
                r = setup_eval_node(sf_, t_, x, vals, SetupBeat());
            }
            flight[{c + L.lat[static_cast<int>(ty)], u}] = r;
            for (size_t i = 0; i < p_.n.size(); ++i)
                if (s_.inst[i] == u && s_.t[i] == c) trace_[i] = r;
        }
        // the finish's reads (the OUT pseudo-unit's fields): field o of span S - stage
        {
            const int u = s_.out_unit;
            if (get(w, lay_.go[u], 1)) {
                const int o = static_cast<int>(get(w, lay_.op[u], lay_.op_w));
                const uint64_t stg = get(w, lay_.stage[u][0], lay_.stage_w);
                const long span = S - static_cast<long>(stg);
                const Fp v = bank[B - 1][addr(get(w, lay_.addr[u][0], lay_.addr_w), stg, S)];
                if (span >= 0 && static_cast<size_t>(span) < nspans && o < SO_COUNT)
                    out[static_cast<size_t>(span)][static_cast<size_t>(o)] = v;
            }
        }
        // writes: the units' results due now
        for (size_t b = 0; b < B; ++b) {
            if (!get(w, lay_.we[b], 1)) continue;
            const auto& srcs = s_.banks[b].sources;
            const int u = srcs.at(get(w, lay_.wsrc[b], lay_.wsrc_w));
            auto it = flight.find({c, u});
            Fp v = it == flight.end() ? Fp() : it->second;   // none before the pipeline fills (the RTL: garbage)
            if (s_.banks[b].port == 2 && s_.banks[b].unit != s_.out_unit) v = v.zero() ? Fp() : fp_from_int(f, 1);
            bank[b][addr(get(w, lay_.waddr[b], lay_.addr_w), get(w, lay_.wstage[b], lay_.stage_w), S)] = v;
        }
        for (auto it = flight.begin(); it != flight.end();) it = it->first.first <= c ? flight.erase(it) : std::next(it);
    }
    (void)dummy;
    return out;
}

}  // namespace spec
