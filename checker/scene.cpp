#include "scene.hpp"

#include "json.hpp"
#include "numbers.hpp"

#include <algorithm>
#include <set>

namespace scalecert_check {
void Scene::prepare(Context& cx) {
    for (int i = 0; i < 2; ++i) {
        mpz_lcm(Dj.get_mpz_t(), Dj.get_mpz_t(), scan[i]->D().get_mpz_t());
        for (const Q& c : s[i]) mpz_lcm(Dj.get_mpz_t(), Dj.get_mpz_t(), c.get_den_mpz_t());
    }
    cx.spend(100 + 20 * limbs(Dj));
    for (int i = 0; i < 2; ++i) {
        E[i] = Dj / scan[i]->D();
        for (int c = 0; c < 3; ++c) {
            mpz_divexact(S[i][c].get_mpz_t(), Dj.get_mpz_t(), s[i][c].get_den_mpz_t());
            S[i][c] *= s[i][c].get_num();
        }
        sdv[i] = {Q(S[i][0], E[i]), Q(S[i][1], E[i]), Q(S[i][2], E[i])};
        for (Q& q : sdv[i]) q.canonicalize();
    }
    for (int c = 0; c < 3; ++c) Delta[c] = S[1][c] - S[0][c];
}

mpz_class Scene::support_at(Context& cx, int i, const Z3& u, int k) const {
    spend_at(cx, i, k);
    mpz_class r = dotz(u, scan[i]->X(static_cast<size_t>(k))) * E[i];
    r -= dotz(u, S[i]);
    return r;
}

Q Scene::h(Context& cx, int i, const V3& n, std::vector<int>* argmax) const {
    Z3 u = ints(n);
    if (i == 1)
        for (auto& c : u) c = -c;
    std::vector<int> m = scan[i]->argmax(cx, u);
    Q r(support_at(cx, i, u, m[0]), Dj);
    r.canonicalize();
    if (argmax) *argmax = std::move(m);
    return r;
}

const Scene::Support* Scene::support(Context& cx, const V3& n, mpz_class H_out[2],
                                     const std::vector<int>* max_out[2]) const {
    mpz_class g = 0;
    for (const Q& c : n) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.get_num_mpz_t());
    Z3 p;
    std::string key;
    for (int c = 0; c < 3; ++c) {
        mpz_divexact(p[c].get_mpz_t(), n[c].get_num_mpz_t(), g.get_mpz_t());
        key += p[c].get_str(16) + ",";
    }
    auto it = cache_.find(key);
    if (it == cache_.end()) {
        Support e;
        for (int i = 0; i < 2; ++i) {
            Z3 u = p;
            if (i == 1)
                for (auto& c : u) c = -c;
            e.max[i] = scan[i]->argmax(cx, u);
            e.H[i] = support_at(cx, i, u, e.max[i][0]);
        }
        it = cache_.emplace(std::move(key), std::move(e)).first;
    }
    for (int i = 0; i < 2; ++i) {
        H_out[i] = it->second.H[i] * g;
        if (max_out) max_out[i] = &it->second.max[i];
    }
    return &it->second;
}

void Scene::spend_at(Context& cx, int i, int k) const {
    const Z3& x = scan[i]->X(static_cast<size_t>(k));
    cx.spend(20 + 4 * (limbs(x[0]) + limbs(x[1]) + limbs(x[2]) + limbs(E[i]) + limbs(S[i][0]) + limbs(S[i][1]) +
                       limbs(S[i][2])));
}

// In one pass: a vertex that does not raise the dimension lies in the hull of those before,
// which only grows. On X_k = D v_k (the same dimension).
int affine_dim(Context& cx, const Scan& s, const std::vector<int>& idx) {
    const Z3& o = s.X(static_cast<size_t>(idx[0]));
    int dim = 0;
    Z3 e1, c, v, x;
    for (int k : idx) {
        const Z3& p = s.X(static_cast<size_t>(k));
        const double l = 1 + limbs(p[0]) + limbs(p[1]) + limbs(p[2]) + limbs(o[0]) + limbs(o[1]) + limbs(o[2]);
        cx.spend(30 + 4 * l * l);
        for (int j = 0; j < 3; ++j) v[j] = p[j] - o[j];
        const bool nz = sgn(v[0]) || sgn(v[1]) || sgn(v[2]);
        if (dim == 0 && nz) {
            e1 = v;
            dim = 1;
            continue;
        }
        if (dim == 1) {
            x = {e1[1] * v[2] - e1[2] * v[1], e1[2] * v[0] - e1[0] * v[2], e1[0] * v[1] - e1[1] * v[0]};
            if (sgn(x[0]) || sgn(x[1]) || sgn(x[2])) {
                c = x;
                dim = 2;
            }
            continue;
        }
        if (dim == 2 && sgn(dotz(c, v)) != 0) return 3;
    }
    return dim;
}

char dimension_letter(Context& cx, const Scene& sc, int i, const std::vector<int>& idx) {
    return "VEFF"[affine_dim(cx, sc, i, idx)];
}

bool Vertices::is_list(Context& cx, const J& j) { return j.is_array() || captured(cx, j); }

size_t Vertices::length(Context& cx, const J& j) {
    const IntPoints* p = captured(cx, j);
    return p ? p->n : j.size();
}

Vertices::Vertices(Context& cx, const J& j, const std::string& where) {
    if (IntPoints* p = captured(cx, j)) {
        // Each vertex a list of three strings, each an integer written canonically (the reader
        // took no other): the 13 claims point() states of it hold (a point of 3 coordinates;
        // each a string, of the form p or p/q, with a nonzero denominator, in lowest terms).
        cx.held(13 * static_cast<long>(p->n));
        ints_ = std::move(*p);
        *p = IntPoints();
        return;
    }
    rational_ = true;  // a list the tree holds: every vertex as a rational
    for (size_t k = 0; k < j.size(); ++k) rat_.push_back(point(cx, j[k], where + "[" + std::to_string(k) + "]"));
}

std::shared_ptr<const Scan> Vertices::scan(Context& cx, const std::string& what) {
    if (rational_) return std::make_shared<const Scan>(cx, rat_, what);
    return std::make_shared<const Scan>(cx, std::move(ints_));
}

Scene read_scene(Context& cx, const J& j, bool radius) {
    shape(cx, j, "scene", {"P1", "P2", "I1", "I2"});
    Scene sc;
    // Objects with a radius carry it both (a scene without one is read as it always was).
    sc.rounded = radius && (at(j, "P1").contains("radius") || at(j, "P2").contains("radius"));
    for (int i = 0; i < 2; ++i) {
        const std::string w = std::string("scene.") + kPoly[i];
        const J& p = at(j, kPoly[i]);
        if (sc.rounded) {
            shape(cx, p, w, {"vertices", "seed", "radius"});
            sc.r[i] = num(cx, at(p, "radius"), w + ".radius");
            cx.claim(sgn(sc.r[i]) >= 0, w + ".radius is >= 0");
        } else {
            shape(cx, p, w, {"vertices", "seed"});
        }
        const J& vs = at(p, "vertices");
        cx.claim(Vertices::is_list(cx, vs), w + ".vertices is a list");
        Vertices v(cx, vs, w + ".vertices");
        if (sgn(sc.r[i]) > 0)  // a sphere is one point, a capsule two
            cx.claim(v.size() >= 1, w + " has at least 1 vertex");
        else
            cx.claim(v.size() >= 4, w + " has at least 4 vertices");
        sc.s[i] = point(cx, at(p, "seed"), w + ".seed");
        sc.scan[i] = v.scan(cx, kPoly[i]);
    }
    if (sc.rounded) cx.claim(sgn(sc.r[0]) > 0 || sgn(sc.r[1]) > 0, "scene: a radius is > 0 (else it carries none)");
    sc.prepare(cx);
    read_ranges(cx, sc.lo, sc.hi, j);
    return sc;
}

std::array<std::optional<Pose>, 2> claim_poses(Context& cx, const J& cl, const std::string& wc, J& bare) {
    std::array<std::optional<Pose>, 2> pose;
    bare = cl;
    for (int i = 0; i < 2; ++i) {
        const std::string key = i ? "pose2" : "pose1", w = wc + "." + key;
        if (!cl.contains(key)) continue;
        const J& m = at(cl, key.c_str());
        cx.claim(m.is_array() && m.size() == 3, w + " is 3 rows [r1, r2, r3, t]");
        Pose& p = pose[static_cast<size_t>(i)].emplace();
        for (size_t r = 0; r < 3; ++r) {
            const std::string wr = w + "[" + std::to_string(r) + "]";
            cx.claim(m[r].is_array() && m[r].size() == 4, wr + " is 4 numbers");
            for (size_t k = 0; k < 4; ++k) p[r][k] = num(cx, m[r][k], wr + "[" + std::to_string(k) + "]");
        }
        double lm = 0;
        for (const auto& row : p)
            for (const Q& e : row) lm = std::max(lm, qsize(e));
        cx.spend_ops(12, 3 * lm);
        const Q det = p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
                      p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
                      p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
        cx.claim(sgn(det) != 0, w + " has a nonsingular R");
        bare.erase(key);
    }
    return pose;
}

namespace {
// With L the lcm of the pose's denominators, x = X / D moves to R x + t = (L R X + D L t) / (D L):
// M = L R and T = D L t, integers, over the common denominator D L.
struct PoseInts {
    Z3 M[3], T;
    mpz_class DL;
};
PoseInts pose_ints(Context& cx, const mpz_class& D, const Pose& m) {
    mpz_class L = 1;
    double lm = 0;
    for (const auto& row : m)
        for (const Q& e : row) {
            mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), e.get_den_mpz_t());
            lm = std::max(lm, qsize(e));
        }
    cx.spend_ops(24, lm + limbs(L) + limbs(D));
    PoseInts p;
    p.DL = D * L;
    for (size_t r = 0; r < 3; ++r) {
        for (size_t c = 0; c < 3; ++c) p.M[r][c] = m[r][c].get_num() * (L / m[r][c].get_den());
        p.T[r] = m[r][3].get_num() * (p.DL / m[r][3].get_den());
    }
    return p;
}
}  // namespace

// Every moved vertex, M X + T, then divided by the gcd of D L and every moved coordinate (the
// least common denominator, which the 16,384-bit limit is on: the engine takes a compound part
// moved by a pose whose entries cancel its vertices' factors).
std::shared_ptr<const Scan> posed_scan(Context& cx, const std::shared_ptr<const Scan>& base, const Pose& m,
                                       const std::string& what) {
    const Scan& P = *base;
    const PoseInts p = pose_ints(cx, P.D(), m);
    double lM = 0, lT = 0;
    for (size_t r = 0; r < 3; ++r) {
        lT = std::max(lT, limbs(p.T[r]));
        for (size_t c = 0; c < 3; ++c) lM = std::max(lM, limbs(p.M[r][c]));
    }
    std::vector<Z3> out(P.size());
    for (size_t k = 0; k < P.size(); ++k) {
        const Z3 X = P.X(k);
        const double lx = std::max({limbs(X[0]), limbs(X[1]), limbs(X[2])});
        cx.spend(300 + 12 * (1 + lM) * (1 + lx) + 3 * (lT + lM + lx));
        for (size_t r = 0; r < 3; ++r) {
            mpz_class& y = out[k][r];
            y = p.T[r];
            for (size_t c = 0; c < 3; ++c) mpz_addmul(y.get_mpz_t(), p.M[r][c].get_mpz_t(), X[c].get_mpz_t());
        }
    }
    mpz_class g = p.DL;
    for (size_t k = 0; k < out.size() && g != 1; ++k)
        for (int c = 0; c < 3 && g != 1; ++c) {
            cx.spend(50 + 4 * (1 + limbs(g)) * (1 + limbs(out[k][c])));
            mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), out[k][c].get_mpz_t());
        }
    if (g != 1)
        for (Z3& y : out)
            for (mpz_class& c : y) {
                cx.spend(20 + 2 * (1 + limbs(c)) * (1 + limbs(g)));
                mpz_divexact(c.get_mpz_t(), c.get_mpz_t(), g.get_mpz_t());
            }
    return std::make_shared<const Scan>(cx, std::move(out), p.DL / g, what);
}

std::shared_ptr<const Scan> posed_view(Context& cx, const std::shared_ptr<const Scan>& base, const Pose& m,
                                       const std::string& what) {
    const PoseInts p = pose_ints(cx, base->D(), m);
    return std::make_shared<const Scan>(cx, base, p.M, p.T, p.DL, what);
}

V3 posed_point(const V3& x, const std::optional<Pose>& pose) {
    if (!pose) return x;
    const Pose& m = *pose;
    V3 y;
    for (size_t r = 0; r < 3; ++r) y[r] = m[r][0] * x[0] + m[r][1] * x[1] + m[r][2] * x[2] + m[r][3];
    return y;
}

// A polyhedron without a pose keeps its scan.
Scene posed_scene(Context& cx, const Scene& sc, const std::array<std::optional<Pose>, 2>& pose) {
    Scene out;
    for (int i = 0; i < 2; ++i) {
        out.scan[i] = pose[i] ? posed_view(cx, sc.scan[i], *pose[i], kPoly[i]) : sc.scan[i];
        out.s[i] = posed_point(sc.s[i], pose[i]);
        out.lo[i] = sc.lo[i];
        out.hi[i] = sc.hi[i];
        out.r[i] = sc.r[i];  // a pose moves the hull: the ball stays a ball of the same radius
    }
    out.rounded = sc.rounded;
    out.prepare(cx);
    return out;
}

void read_ranges(Context& cx, Q (&lo)[2], Q (&hi)[2], const J& j) {
    const char* iv[2] = {"I1", "I2"};
    for (int i = 0; i < 2; ++i) {
        const J& r = at(j, iv[i]);
        cx.claim(r.is_array() && r.size() == 2, std::string("scene.") + iv[i] + " is [lo, hi]");
        lo[i] = num(cx, r[0], std::string("scene.") + iv[i] + "[0]");
        hi[i] = num(cx, r[1], std::string("scene.") + iv[i] + "[1]");
        cx.claim(sgn(lo[i]) > 0 && lo[i] <= hi[i], std::string("scene.") + iv[i] + " has 0 < lo <= hi");
    }
}

std::array<Q, 3> combination(Context& cx, const Scan& P, const J& w, const std::string& where, std::vector<int>* used) {
    cx.claim_lazy(w.is_array() && !w.empty(), [&] { return where + " is a nonempty list of weights"; });
    std::set<size_t> seen;
    Q total = 0;
    std::array<Q, 3> x{Q(0), Q(0), Q(0)};
    for (size_t k = 0; k < w.size(); ++k) {
        auto wk = [&] { return where + "[" + std::to_string(k) + "]"; };  // (for a message only)
        cx.claim_lazy(w[k].is_array() && w[k].size() == 2, [&] { return wk() + " is [index, weight]"; });
        size_t idx = index_at(cx, w[k][0], P.size(), [&] { return wk() + " index"; });
        cx.claim_lazy(seen.insert(idx).second, [&] { return wk() + " names a distinct vertex"; });
        Q l = num_at(cx, w[k][1], [&] { return wk() + " weight"; });
        cx.claim_lazy(sgn(l) > 0, [&] { return wk() + " weight is > 0"; });
        // The running sums' denominators can grow with every term (weights over coprime
        // denominators), and each addition costs their size, gcd included: counted first.
        cx.spend(100 *
                 (limbs(total.get_den()) + limbs(x[0].get_den()) + limbs(x[1].get_den()) + limbs(x[2].get_den())));
        total += l;
        const Z3& X = P.X(idx);
        cx.spend(100 +
                 10 * (1 + limbs(l.get_num()) + limbs(l.get_den())) * (1 + limbs(X[0]) + limbs(X[1]) + limbs(X[2])));
        for (int c = 0; c < 3; ++c) x[c] += l * Q(X[c]);
        if (used) used->push_back(static_cast<int>(idx));
    }
    cx.claim_lazy(total == 1, [&] { return where + " weights sum to 1"; });
    return x;
}

void check_seed_interior(Context& cx, const Scene& sc, const J& j) {
    shape(cx, j, "seed_interior", {"P1", "P2"});
    for (int i = 0; i < 2; ++i)
        check_seed_weights(cx, sc, i, at(j, kPoly[i]), std::string("seed_interior.") + kPoly[i]);
}

void check_seed_weights(Context& cx, const Scene& sc, int i, const J& w, const std::string& where) {
    std::vector<int> used;
    cx.claim(combination(cx, *sc.scan[i], w, where, &used) == sc.sdv[i], where + " combines to the seed");
    const bool spans = affine_dim(cx, sc, i, used) == 3;
    cx.claim(spans, where + " uses vertices spanning 3 dimensions");
}

// The point is s + ρ Σ λ (v − s) on each side. With c = Σ λ X / D_i (combination()), the point
// y = s + ρ (c − s) equals p iff ρ D_i c = D_i p + (ρ − 1) D_i s: products of the file's numbers
// and the scene's.
P2 check_witness(Context& cx, const Scene& sc, const J& w, const std::string& where, std::vector<int>* used) {
    shape(cx, w, where, {"rho1", "rho1_double", "rho2", "rho2_double", "point", "point_double", "P1", "P2"});
    Q r1 = field(cx, w, "rho1", where), r2 = field(cx, w, "rho2", where);
    cx.claim_lazy(sgn(r1) >= 0 && sgn(r2) >= 0, [&] { return where + " scalings are >= 0"; });
    std::vector<Q> x = fields(cx, w, "point", 3, where);
    const Q* r[2] = {&r1, &r2};
    for (int i = 0; i < 2; ++i) {
        std::array<Q, 3> c =
            combination(cx, *sc.scan[i], at(w, kPoly[i]), where + "." + kPoly[i], used ? &used[i] : nullptr);
        const Q D(sc.scan[i]->D());
        bool on = true;
        for (int k = 0; k < 3; ++k) on = on && *r[i] * c[k] == x[k] * D + (*r[i] - 1) * sc.sdv[i][k];
        cx.claim_lazy(on, [&] { return where + ".point lies in " + kPoly[i] + "(rho" + std::to_string(i + 1) + ")"; });
    }
    return {r1, r2};
}

std::string contact_string(Context& cx, const J& j, const std::string& where) {
    cx.claim(j.is_string() && j.get_ref<const std::string&>().size() == 2, where + " is a two-letter contact");
    return j.get<std::string>();
}
}  // namespace scalecert_check
