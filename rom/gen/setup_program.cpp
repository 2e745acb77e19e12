#include "setup_program.h"

#include <cmath>
#include <stdexcept>

namespace spec {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

Fp fp_from_double(const FpFmt& f, double v) {
    if (v == 0.0) return Fp();
    int ex = 0;
    const double fr = std::frexp(std::fabs(v), &ex);   // v = fr 2^ex, fr in [0.5, 1)
    const uint64_t X = static_cast<uint64_t>(std::ldexp(fr, 53));
    return fp_round(f, v < 0, X, ex - 53);
}

double fp_value(const FpFmt& f, const Fp& a) {
    if (a.zero()) return 0.0;
    return (a.s ? -1.0 : 1.0) * std::ldexp(static_cast<double>(a.m), a.e - (f.m - 1));
}

SetupUnit setup_op_unit(SetupOp o) {
    switch (o) {
        case SetupOp::IDOT: return SetupUnit::IDOT;
        case SetupOp::FMUL: return SetupUnit::MUL;
        case SetupOp::FADD: return SetupUnit::ADD;
        case SetupOp::RSQRT: case SetupOp::RCP: case SetupOp::ATANG: case SetupOp::LOG2: return SetupUnit::EFU;
        case SetupOp::CMPLT: case SetupOp::SEL: case SetupOp::MIN: case SetupOp::MAX: return SetupUnit::MISC;
        case SetupOp::CONST: break;
    }
    return SetupUnit::NONE;
}

const char* setup_op_name(SetupOp o) {
    switch (o) {
        case SetupOp::CONST: return "const";
        case SetupOp::IDOT: return "idot";
        case SetupOp::FMUL: return "fmul";
        case SetupOp::FADD: return "fadd";
        case SetupOp::RSQRT: return "rsqrt";
        case SetupOp::RCP: return "rcp";
        case SetupOp::ATANG: return "atang";
        case SetupOp::LOG2: return "log2";
        case SetupOp::CMPLT: return "cmplt";
        case SetupOp::SEL: return "sel";
        case SetupOp::MIN: return "min";
        case SetupOp::MAX: return "max";
    }
    return "?";
}

const char* setup_unit_name(SetupUnit u) {
    switch (u) {
        case SetupUnit::IDOT: return "idot";
        case SetupUnit::MUL: return "mul";
        case SetupUnit::ADD: return "add";
        case SetupUnit::EFU: return "efu";
        case SetupUnit::MISC: return "misc";
        default: break;
    }
    return "?";
}

int setup_op_operands(SetupOp o) {
    switch (o) {
        case SetupOp::CONST: case SetupOp::IDOT: return 0;
        case SetupOp::RSQRT: case SetupOp::RCP: case SetupOp::ATANG: case SetupOp::LOG2: return 1;
        case SetupOp::SEL: return 3;
        default: return 2;
    }
}

const char* setup_out_name(int o) {
    static const char* names[SO_COUNT] = {"gamma_p", "gamma", "lambda", "dzeta", "p_nf", "p_f", "c1", "opc", "ok"};
    return o >= 0 && o < SO_COUNT ? names[o] : "?";
}

int SetupProgram::count(SetupUnit u) const {
    int k = 0;
    for (const SetupNode& x : n) k += setup_op_unit(x.op) == u;
    return k;
}

// ---- the algorithm -------------------------------------------------------------------------------------------
namespace {

struct V3 {
    SetupRef x, y, z;
};

SetupRef neg(SetupRef r) {
    r.neg = !r.neg;
    return r;
}
SetupRef absr(SetupRef r) {
    r.abs = true;
    r.neg = false;
    return r;
}

class Builder {
public:
    explicit Builder(const SetupFormat& sf) : sf_(sf) {}
    std::vector<SetupNode> n;

    SetupRef push(const SetupNode& x) {
        n.push_back(x);
        SetupRef r;
        r.id = static_cast<int>(n.size()) - 1;
        return r;
    }
    SetupRef K(double v) {
        SetupNode x;
        x.op = SetupOp::CONST;
        x.k = fp_from_double(sf_.fp, v);
        return push(x);
    }
    SetupRef op(SetupOp o, SetupRef a, SetupRef b = SetupRef(), SetupRef c = SetupRef(), int scale = 0) {
        SetupNode x;
        x.op = o;
        x.a = a;
        x.b = b;
        x.c = c;
        x.scale = scale;
        return push(x);
    }
    // ---- the exact front end
    SetupRef idot(IdotMode m, int va, int vb, int comp = 0, int scale = 0) {
        SetupNode x;
        x.op = SetupOp::IDOT;
        x.mode = m;
        x.va = static_cast<uint8_t>(va);
        x.vb = static_cast<uint8_t>(vb);
        x.comp = static_cast<uint8_t>(comp);
        x.scale = scale;
        return push(x);
    }
    SetupRef dot_i(int va, int vb) { return idot(IdotMode::DOT, va, vb); }
    V3 cross_i(int va, int vb) {
        return {idot(IdotMode::CRX, va, vb), idot(IdotMode::CRY, va, vb), idot(IdotMode::CRZ, va, vb)};
    }
    V3 vec_i(int va) { return {idot(IdotMode::COMP, va, 0, 0), idot(IdotMode::COMP, va, 0, 1), idot(IdotMode::COMP, va, 0, 2)}; }
    SetupRef scalar_i(int field, int scale = 0) { return idot(IdotMode::SCALAR, 0, 0, field, scale); }
    // ---- floating point
    SetupRef mul(SetupRef a, SetupRef b, int s = 0) { return op(SetupOp::FMUL, a, b, SetupRef(), s); }
    SetupRef add(SetupRef a, SetupRef b, int s = 0, int bs = 0) {
        SetupRef r = op(SetupOp::FADD, a, b, SetupRef(), s);
        n[r.id].bscale = bs;
        return r;
    }
    SetupRef sub(SetupRef a, SetupRef b, int s = 0, int bs = 0) { return add(a, neg(b), s, bs); }
    SetupRef efu(SetupOp o, SetupRef a, int s = 0) { return op(o, a, SetupRef(), SetupRef(), s); }
    SetupRef lt(SetupRef a, SetupRef b) { return op(SetupOp::CMPLT, a, b); }
    SetupRef sel(SetupRef c, SetupRef a, SetupRef b) { return op(SetupOp::SEL, c, a, b); }
    SetupRef mn(SetupRef a, SetupRef b) { return op(SetupOp::MIN, a, b); }
    SetupRef mx(SetupRef a, SetupRef b) { return op(SetupOp::MAX, a, b); }
    SetupRef dot(const V3& a, const V3& b) { return add(add(mul(a.x, b.x), mul(a.y, b.y)), mul(a.z, b.z)); }
    V3 scl(const V3& a, SetupRef s, int e = 0) { return {mul(a.x, s, e), mul(a.y, s, e), mul(a.z, s, e)}; }
    V3 vadd(const V3& a, const V3& b) { return {add(a.x, b.x), add(a.y, b.y), add(a.z, b.z)}; }
    V3 vsub(const V3& a, const V3& b) { return {sub(a.x, b.x), sub(a.y, b.y), sub(a.z, b.z)}; }
    V3 vsel(SetupRef c, const V3& a, const V3& b) { return {sel(c, a.x, b.x), sel(c, a.y, b.y), sel(c, a.z, b.z)}; }
    V3 cross(const V3& a, const V3& b) {
        return {sub(mul(a.y, b.z), mul(a.z, b.y)), sub(mul(a.z, b.x), mul(a.x, b.z)), sub(mul(a.x, b.y), mul(a.y, b.x))};
    }
    // The first-quadrant angle of (y, x) for y, x >= 0: atan(min / max), pi/2 minus it when y > x.
    SetupRef atan_q1(SetupRef y, SetupRef x) {
        const SetupRef sw = lt(x, y);
        const SetupRef r = mul(mn(y, x), efu(SetupOp::RCP, mx(y, x)));
        const SetupRef t = mul(r, efu(SetupOp::ATANG, r));
        return sel(sw, sub(K(kPi / 2), t), t);
    }

private:
    const SetupFormat& sf_;
};

// Dead operations out, constants shared, ids renumbered in order.
SetupProgram finalize(const std::vector<SetupNode>& n, const std::array<int, SO_COUNT>& out,
                      const std::vector<std::pair<std::string, int>>& probes) {
    std::vector<char> live(n.size(), 0);
    for (int o : out) live[static_cast<size_t>(o)] = 1;
    for (const auto& pr : probes) live[static_cast<size_t>(pr.second)] = 1;
    for (size_t i = n.size(); i-- > 0;) {
        if (!live[i]) continue;
        for (const SetupRef* r : {&n[i].a, &n[i].b, &n[i].c})
            if (r->id >= 0) live[static_cast<size_t>(r->id)] = 1;
    }
    SetupProgram p;
    std::vector<int> map(n.size(), -1);
    for (size_t i = 0; i < n.size(); ++i) {
        if (!live[i]) continue;
        SetupNode x = n[i];
        if (x.op == SetupOp::CONST) {   // one node per constant value
            for (size_t j = 0; j < p.n.size(); ++j) {
                if (p.n[j].op == SetupOp::CONST && p.n[j].k == x.k) {
                    map[i] = static_cast<int>(j);
                    break;
                }
            }
            if (map[i] >= 0) continue;
        }
        for (SetupRef* r : {&x.a, &x.b, &x.c})
            if (r->id >= 0) r->id = map[static_cast<size_t>(r->id)];
        map[i] = static_cast<int>(p.n.size());
        p.n.push_back(x);
    }
    for (int o = 0; o < SO_COUNT; ++o) p.out[o] = map[static_cast<size_t>(out[o])];
    for (const auto& pr : probes) p.probes.push_back({pr.first, map[static_cast<size_t>(pr.second)]});
    return p;
}

}  // namespace

SetupProgram build_setup_program(const SetupFormat& sf) {
    Builder b(sf);
    const SetupRef one = b.K(1.0), zero = b.K(0.0);
    // ---- the exact front end: squared lengths, cross and dot products of the 16-bit span ends
    const SetupRef n1s = b.dot_i(BV_N1, BV_N1), n2s = b.dot_i(BV_N2, BV_N2);
    const SetupRef h1s = b.dot_i(BV_H1, BV_H1), h2s = b.dot_i(BV_H2, BV_H2);
    const V3 vN = b.cross_i(BV_N1, BV_N2), kH = b.cross_i(BV_H1, BV_H2);
    const SetupRef cN = b.dot_i(BV_N1, BV_N2), cH = b.dot_i(BV_H1, BV_H2), g11 = b.dot_i(BV_N1, BV_H1);
    const SetupRef g22 = b.dot_i(BV_N2, BV_H2);
    const SetupRef pns = b.dot_i(BV_PN, BV_PN);
    const V3 UN = b.cross_i(BV_N1, BV_PN);   // N1 x perpendicular(N1): the host's axis for exactly opposite normals
    const V3 N1 = b.vec_i(BV_N1), H1 = b.vec_i(BV_H1), H2 = b.vec_i(BV_H2), PN = b.vec_i(BV_PN);
    const SetupRef rule = b.scalar_i(BS_RULE), strength = b.scalar_i(BS_STRENGTH, -sf.str_frac);
    const SetupRef nn = b.scalar_i(BS_N), ll = b.scalar_i(BS_L);

    // ---- unit vectors a = N1/|N1|, p = H1/|H1|, q = H2/|H2|; v = a x b, k = p x q, c = a.b, pq = p.q
    const SetupRef r1 = b.efu(SetupOp::RSQRT, n1s), r2 = b.efu(SetupOp::RSQRT, n2s);
    const SetupRef rh1 = b.efu(SetupOp::RSQRT, h1s), rh2 = b.efu(SetupOp::RSQRT, h2s);
    const SetupRef r12 = b.mul(r1, r2), rh12 = b.mul(rh1, rh2);
    const V3 v = b.scl(vN, r12), k = b.scl(kH, rh12);
    const SetupRef cc = b.mul(cN, r12), pq = b.mul(cH, rh12);
    const V3 a = b.scl(N1, r1), pp = b.scl(H1, rh1), q = b.scl(H2, rh2);
    const SetupRef c1 = b.mul(g11, b.mul(r1, rh1));   // cos theta1 = N1.H1 / (|N1| |H1|)
    const SetupRef f1 = b.mul(g22, b.mul(r2, rh2));   // cos theta2 = N2.H2 / (|N2| |H2|)
    const SetupRef vv = b.dot(v, v), kk = b.dot(k, k);
    // 1 + c, 1 - c, 1 + pq, 1 - pq with relative precision: |v|^2 = (1 - c)(1 + c), |k|^2 = (1 - pq)(1 + pq)
    const SetupRef cneg = b.lt(cc, zero), qneg = b.lt(pq, zero);
    const SetupRef rmc = b.efu(SetupOp::RCP, b.sub(one, cc)), rpc = b.efu(SetupOp::RCP, b.add(one, cc));
    const SetupRef opc = b.sel(cneg, b.mul(vv, rmc), b.add(one, cc));
    const SetupRef omc = b.sel(cneg, b.sub(one, cc), b.mul(vv, rpc));
    const SetupRef rmq = b.efu(SetupOp::RCP, b.sub(one, pq)), rpq = b.efu(SetupOp::RCP, b.add(one, pq));
    const SetupRef opq = b.sel(qneg, b.mul(kk, rmq), b.add(one, pq));
    const SetupRef omq = b.sel(qneg, b.sub(one, pq), b.mul(kk, rpq));
    const SetupRef ex = b.mn(cneg, b.lt(vv, b.K(1e-30)));   // exactly opposite normals: v = 0, c < 0

    // ---- H2 carried into N1's frame by the rotation R taking b onto a (axis v). c >= 0: the host's Rodrigues
    // formula, Rq - q = rho = G (v (v.q) - q |v|^2) - v x q, G = 1/(1 + c). c < 0: R = (half turn about v) o R',
    // R' the small rotation taking -b onto a: Rq = eta + rho_s - q with eta = 2 (v.q) v / |v|^2 and rho_s =
    // -(R'q - q) = -G (v (v.q) - q |v|^2) - v x q, G = 1/(1 - c). Exactly opposite normals: the half turn about
    // the host's axis U. So base = eta + rho_s with rho_s = sign(c) G (...) - v x q, eta = 0 for c >= 0.
    const V3 Uf = UN;
    const SetupRef vq = b.dot(v, q);
    const SetupRef Gs = b.sel(cneg, neg(rmc), rpc);
    const V3 rho = b.vsub(b.vsub(b.scl(v, b.mul(Gs, vq)), b.scl(q, b.mul(Gs, vv))), b.cross(v, q));
    const V3 vx = b.vsel(ex, Uf, v);
    const SetupRef vxq = b.sel(ex, b.dot(Uf, q), vq), vxx = b.sel(ex, b.dot(Uf, Uf), vv);
    const SetupRef keta = b.sel(cneg, b.mul(vxq, b.efu(SetupOp::RCP, vxx), 1), zero);
    const V3 base = b.vadd(b.scl(vx, keta), rho);
    // The half sums and differences, doubled, with relative precision: 2m = a + b = a (1 + c) + v x a,
    // 2e = a - b = a (1 - c) - v x a, 2h = p + q = p (1 + pq) + k x p, 2f = p - q = p (1 - pq) - k x p
    const V3 va = b.cross(v, a), kp = b.cross(k, pp);
    const V3 m2 = b.vadd(b.scl(a, opc), va), e2 = b.vsub(b.scl(a, omc), va);
    const V3 h2 = b.vadd(b.scl(pp, opq), kp), f2 = b.vsub(b.scl(pp, omq), kp);

    // ---- the patent's gamma (eq. 4): d = H2' - H1 = base - (c >= 0 ? 2f : 2h), s = H2' + H1 = base +
    // (c >= 0 ? 2h : 2f); |d| = 2 sin(g/2), |s| = 2 cos(g/2)
    const V3 d = b.vsub(base, b.vsel(cneg, h2, f2));
    const V3 sv = b.vadd(base, b.vsel(cneg, f2, h2));
    const SetupRef dd = b.dot(d, d), ss = b.dot(sv, sv), ad = b.dot(a, d), as = b.dot(a, sv);
    // 2 sin(g) A sin(lambda) = c1 dd + 2 a.d = 2 a.s - c1 ss: the first where g < pi/2, the second above
    const SetupRef y0 = b.add(b.mul(c1, dd), ad, 0, 1), ypi = b.sub(as, b.mul(c1, ss), 1, -1);
    const SetupRef yy = b.sel(b.lt(dd, ss), y0, ypi);
    const SetupRef P = b.mul(dd, ss);
    const SetupRef rP = b.efu(SetupOp::RSQRT, P);
    const SetupRef sp_p = b.mul(yy, rP);                 // A sin(lambda)
    const SetupRef sq = b.mul(P, rP, 1);                 // 2 |d| |s| = 4 sin g
    const SetupRef cg = b.sub(ss, dd);                   // 4 cos g
    const SetupRef g1 = b.atan_q1(sq, absr(cg));
    const SetupRef gp = b.sel(b.lt(cg, zero), b.sub(b.K(kPi), g1), g1);

    // ---- the midpoint rule: f(0) + f(1) = 2 cos(g/2) f(1/2) with R = f(0) + f(1) = 2 (m.h + e.f),
    // F = f(1) - f(0) = -2 (m.f + e.h), S = 2 f(1/2) = 2 m.h / (|m| |h|), S - R = 2 (m.h w - e.f),
    // w = 1/(|m||h|) - 1 from 1 - |m|^2 |h|^2 = |e|^2 + |f|^2 - |e|^2 |f|^2
    const SetupRef mh4 = b.dot(m2, h2), ef4 = b.dot(e2, f2), mf4 = b.dot(m2, f2), eh4 = b.dot(e2, h2);
    const SetupRef Fn = neg(b.add(mf4, eh4, -1));        // F
    const SetupRef R = b.add(c1, f1);   // absolute precision suffices (the half differences carry S - R and F)
    const SetupRef mh2 = b.mul(opc, opq, -2);            // |m|^2 |h|^2
    const SetupRef om = b.sub(b.add(omc, omq, -1), b.mul(omc, omq, -2));   // |e|^2 + |f|^2 - |e|^2 |f|^2
    const SetupRef rs = b.efu(SetupOp::RSQRT, mh2);
    const SetupRef w = b.mul(b.mul(om, b.efu(SetupOp::RCP, b.add(one, b.mul(mh2, rs)))), rs);
    const SetupRef Dm0 = b.sub(b.mul(mh4, w), ef4, -1);
    // exactly opposite normals: the host's middle normal is perpendicular(N1) = PN/|PN|: S = 2 PN.h / (|PN| |h|)
    const SetupRef Sx = b.mul(b.dot(PN, h2), b.efu(SetupOp::RSQRT, b.mul(pns, opq, 1)), 1);
    const SetupRef Dm = b.sel(ex, b.sub(Sx, R), Dm0);    // S - R
    const SetupRef S = b.add(R, Dm);
    const SetupRef D = b.mul(Dm, b.add(S, R));           // S^2 - R^2
    const SetupRef rD = b.efu(SetupOp::RSQRT, D);
    const SetupRef sqD = b.mul(D, rD);
    const SetupRef gm = b.atan_q1(sqD, absr(R));         // g/2
    // A sin(lambda) = (F S^2 + 2 c1 D) / (2 R sqrt D) for small g, (S^2 - 2 c1 R) / (2 sqrt D) near pi
    const SetupRef sp_m0 = b.mul(b.add(b.mul(Fn, b.mul(S, S)), b.mul(c1, D, 1)), b.efu(SetupOp::RCP, b.mul(R, sqD, 1)));
    const SetupRef sp_m1 = b.mul(b.sub(b.mul(S, S), b.mul(c1, R, 1)), rD, -1);
    const SetupRef sp_m = b.sel(b.lt(D, b.mul(R, R)), sp_m0, sp_m1);
    const SetupRef c12 = b.mul(c1, c1);
    const SetupRef A2m = b.add(c12, b.mul(sp_m, sp_m));
    (void)mh4;
    // the host's conditions: f(1/2) > 1e-3, 0 <= R / S <= 1, g >= 1e-6, an amplitude <= 1, H2 != -H1
    SetupRef ok = b.mn(rule, b.lt(b.K(2e-3), S));
    ok = b.mn(ok, b.lt(b.K(-1e-300), R));
    ok = b.mn(ok, b.lt(b.K(-1e-300), Dm));
    ok = b.mn(ok, b.lt(b.K(0.5e-6), gm));
    ok = b.mn(ok, b.lt(A2m, b.K(1.0 + std::ldexp(1.0, sf.a_tol_log2))));
    ok = b.mn(ok, b.lt(b.K(1e-30), opq));
    const SetupRef gam = b.sel(ok, b.mul(gm, one, 1), gp);
    const SetupRef sp = b.sel(ok, sp_m, sp_p);

    // ---- lambda = atan2(A sin(lambda), cos theta1), A^2 = c1^2 + (A sin(lambda))^2, C = Is A^n as 2^-p
    const SetupRef lq = b.atan_q1(absr(sp), absr(c1));
    const SetupRef l2 = b.sel(b.lt(c1, zero), b.sub(b.K(kPi), lq), lq);
    const SetupRef lam = b.sel(b.lt(sp, zero), neg(l2), l2);
    const SetupRef A2 = b.mn(b.add(c12, b.mul(sp, sp)), one);
    const SetupRef LS = b.efu(SetupOp::LOG2, strength);
    const SetupRef p_nf = b.sub(b.mul(nn, neg(b.efu(SetupOp::LOG2, A2)), -1), LS);
    const SetupRef p_f = b.sub(b.mul(nn, neg(b.efu(SetupOp::LOG2, c12)), -1), LS);
    const SetupRef dz = b.mul(gam, b.efu(SetupOp::RCP, ll));

    std::array<int, SO_COUNT> out{};
    out[SO_GAMMA_P] = gp.id;
    out[SO_GAMMA] = gam.id;
    out[SO_LAMBDA] = lam.id;
    out[SO_DZETA] = dz.id;
    out[SO_P_NF] = p_nf.id;
    out[SO_P_F] = p_f.id;
    out[SO_C1] = c1.id;
    out[SO_OPC] = opc.id;
    out[SO_OK] = ok.id;
    const std::vector<std::pair<std::string, int>> probes = {
        {"c", cc.id}, {"pq", pq.id}, {"c1", c1.id}, {"dd", dd.id}, {"ss", ss.id}, {"A sin(lambda) patent", sp_p.id},
        {"gamma patent", gp.id}, {"R", R.id}, {"S", S.id}, {"S-R", Dm.id}, {"F", Fn.id}, {"gamma/2 midpoint", gm.id},
        {"A sin(lambda) midpoint", sp_m.id}, {"A^2 midpoint", A2m.id}, {"A^2", A2.id}};
    return finalize(b.n, out, probes);
}

// ---- evaluation ----------------------------------------------------------------------------------------------
int64_t SetupTable::at(uint64_t pos) const {
    const uint64_t i = pos >> r, fr = pos & ((uint64_t(1) << r) - 1);
    const int64_t a = w.at(i), b = w.at(i + 1);
    const int64_t d = (b - a) * static_cast<int64_t>(fr) + (int64_t(1) << (r - 1));
    return a + (d >> r);   // arithmetic shift: the floor of the interpolated step
}

namespace {
template <class F>
SetupTable table(F fn, double x0, double x1, int t, int r, int f) {
    SetupTable tb;
    tb.t = t;
    tb.r = r;
    tb.f = f;
    const size_t n = (size_t(1) << t) + 2;   // the last word repeats the end point (the position 2^(t+r))
    tb.w.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const double x = x0 + (x1 - x0) * static_cast<double>(std::min<size_t>(i, size_t(1) << t)) /
                                  static_cast<double>(size_t(1) << t);
        tb.w[i] = static_cast<int64_t>(std::llround(std::ldexp(fn(x), f)));
    }
    return tb;
}

// The mantissa below its leading one as a position with `bits` fraction bits.
uint64_t mant_pos(const FpFmt& f, const Fp& x, int bits) {
    const uint64_t mm = x.m - (uint64_t(1) << (f.m - 1));
    const int sh = (f.m - 1) - bits;
    return sh >= 0 ? mm >> sh : mm << -sh;
}
}  // namespace

SetupTables make_setup_tables(const SetupFormat& sf) {
    SetupTables t;
    const int r = sf.tab_r, f = sf.tab_f;
    t.rsqrt_lo = table([](double x) { return 1.0 / std::sqrt(x); }, 1.0, 2.0, sf.tab_t, r, f);
    t.rsqrt_hi = table([](double x) { return 1.0 / std::sqrt(x); }, 2.0, 4.0, sf.tab_t, r, f);
    t.rcp = table([](double x) { return 1.0 / x; }, 1.0, 2.0, sf.tab_t, r, f);
    t.atang = table([](double x) { return x == 0.0 ? 1.0 : std::atan(x) / x; }, 0.0, 1.0, sf.tab_t, r, f);
    t.log2 = table([](double x) { return std::log2(x); }, 1.0, 2.0, sf.tab_t, r, f);
    t.exp2 = table([](double x) { return std::exp2(-x); }, 0.0, 1.0, sf.exp_t, sf.exp_r, sf.exp_f);
    // the EFU multiplies the step between neighbouring words as TAB_F - TAB_T + 2 bits (rtl/spec_setup_efu.v)
    for (const SetupTable* tb : {&t.rsqrt_lo, &t.rsqrt_hi, &t.rcp, &t.atang, &t.log2})
        for (size_t i = 0; i + 1 < tb->w.size(); ++i)
            if (std::llabs(tb->w[i + 1] - tb->w[i]) >= (int64_t(1) << (sf.tab_f - sf.tab_t + 1)))
                throw std::logic_error("setup tables: a step exceeds the EFU's multiplier");
    return t;
}

Fp setup_efu(const SetupFormat& sf, const SetupTables& t, SetupOp op, const Fp& x, int k) {
    const FpFmt& f = sf.fp;
    switch (op) {
        case SetupOp::RSQRT: {
            if (x.zero() || x.s) return Fp();
            const int odd = x.e & 1;   // [2, 4) for an odd exponent: sqrt of an even power
            const SetupTable& tb = odd ? t.rsqrt_hi : t.rsqrt_lo;
            const int64_t v = tb.at(mant_pos(f, x, tb.t + tb.r));
            return fp_round(f, false, static_cast<setup_u128>(v), -tb.f - (x.e - odd) / 2 + k);
        }
        case SetupOp::RCP: {
            if (x.zero()) return Fp();
            const int64_t v = t.rcp.at(mant_pos(f, x, t.rcp.t + t.rcp.r));
            return fp_round(f, x.s, static_cast<setup_u128>(v), -t.rcp.f - x.e + k);
        }
        case SetupOp::ATANG: {
            const int tr = t.atang.t + t.atang.r;
            uint64_t q = 0;   // |x| in [0, 1] with tr fraction bits, 1 for |x| >= 1
            if (!x.zero()) {
                if (x.e >= 0) {
                    q = uint64_t(1) << tr;
                } else {
                    const int sh = (f.m - 1) - tr - x.e;   // right shift of the mantissa
                    q = sh <= 0 ? x.m << -sh : (sh >= 64 ? 0 : x.m >> sh);
                }
            }
            return fp_round(f, false, static_cast<setup_u128>(t.atang.at(q)), -t.atang.f + k);
        }
        case SetupOp::LOG2: {
            if (x.zero() || x.s) return fp_from_int(f, -1024, k);
            const int64_t v = t.log2.at(mant_pos(f, x, t.log2.t + t.log2.r));
            const int64_t s = (static_cast<int64_t>(x.e) << t.log2.f) + v;
            return fp_round(f, s < 0, static_cast<setup_u128>(s < 0 ? -s : s), -t.log2.f + k);
        }
        default: break;
    }
    throw std::logic_error("setup: not an EFU operation");
}

int64_t setup_idot(const SetupNode& n, const SetupBeat& b) {
    const int32_t* x = b.v[n.va];
    const int32_t* y = b.v[n.vb];
    switch (n.mode) {
        case IdotMode::DOT: return int64_t(x[0]) * y[0] + int64_t(x[1]) * y[1] + int64_t(x[2]) * y[2];
        case IdotMode::CRX: return int64_t(x[1]) * y[2] - int64_t(x[2]) * y[1];
        case IdotMode::CRY: return int64_t(x[2]) * y[0] - int64_t(x[0]) * y[2];
        case IdotMode::CRZ: return int64_t(x[0]) * y[1] - int64_t(x[1]) * y[0];
        case IdotMode::COMP: return x[n.comp];
        case IdotMode::SCALAR: return b.s[n.comp];
    }
    return 0;
}

Fp setup_eval_node(const SetupFormat& sf, const SetupTables& t, const SetupNode& x, const std::vector<Fp>& v,
                   const SetupBeat& beat) {
    const FpFmt& f = sf.fp;
    auto get = [&](const SetupRef& r) {
        Fp a = v[static_cast<size_t>(r.id)];
        if (r.abs) a = fp_abs(a);
        if (r.neg) a = fp_neg(a);
        return a;
    };
    switch (x.op) {
        case SetupOp::CONST: return x.k;
        case SetupOp::IDOT: return fp_from_int(f, setup_idot(x, beat), x.scale);
        case SetupOp::FMUL: return fp_mul(f, get(x.a), get(x.b), x.scale);
        case SetupOp::FADD: return fp_add(f, get(x.a), fp_scale(f, get(x.b), x.bscale), x.scale);
        case SetupOp::RSQRT: case SetupOp::RCP: case SetupOp::ATANG: case SetupOp::LOG2:
            return setup_efu(sf, t, x.op, get(x.a), x.scale);
        case SetupOp::CMPLT: return fp_scale(f, fp_less(get(x.a), get(x.b)) ? fp_from_int(f, 1) : Fp(), x.scale);
        case SetupOp::SEL: return fp_scale(f, get(x.a).zero() ? get(x.c) : get(x.b), x.scale);
        case SetupOp::MIN: {   // one comparison: a < b ? a : b (equal values are equal words)
            const Fp a = get(x.a), b = get(x.b);
            return fp_scale(f, fp_less(a, b) ? a : b, x.scale);
        }
        case SetupOp::MAX: {
            const Fp a = get(x.a), b = get(x.b);
            return fp_scale(f, fp_less(a, b) ? b : a, x.scale);
        }
    }
    return Fp();
}

std::vector<Fp> setup_eval(const SetupFormat& sf, const SetupTables& t, const SetupProgram& p, const SetupBeat& beat) {
    std::vector<Fp> v(p.n.size());
    for (size_t i = 0; i < p.n.size(); ++i) v[i] = setup_eval_node(sf, t, p.n[i], v, beat);
    return v;
}

}  // namespace spec
