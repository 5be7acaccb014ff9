// scalecert-check: an independent checker for scalecert certificates (partition files and query
// answers). It shares no code with the engine: GMP rationals, the standard library and a JSON
// reader. Every claim is re-derived from the scene stored in the file; see certificates/FORMAT.md.
// Exit 0: valid. Exit 1: the first claim that fails, on stderr. Exit 2: the file cannot be read.
#include <gmpxx.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {
using J = nlohmann::json;
using Q = mpq_class;
using V3 = std::array<Q, 3>;
using P2 = std::array<Q, 2>;

struct Invalid { std::string what; };
long g_claims = 0;
void claim(bool ok, const std::string& what) {
    ++g_claims;
    if (!ok) throw Invalid{what};
}

// ---- numbers -------------------------------------------------------------------------------
// An exact number: "p" or "p/q", in lowest terms, q > 0.
Q num(const J& j, const std::string& where) {
    claim(j.is_string(), where + " is an exact number string");
    const std::string s = j.get<std::string>();
    size_t slash = s.find('/');
    auto is_int = [](const std::string& t, bool sign) {
        size_t b = (sign && !t.empty() && t[0] == '-') ? 1 : 0;
        return t.size() > b && t.find_first_not_of("0123456789", b) == std::string::npos &&
               (t.size() == b + 1 || t[b] != '0');
    };
    bool ok = slash == std::string::npos ? is_int(s, true) : is_int(s.substr(0, slash), true) && is_int(s.substr(slash + 1), false);
    claim(ok, where + " = '" + s + "' is an integer or p/q");
    Q q(s, 10);
    claim(sgn(q.get_den()) > 0 && q.get_den() != 0, where + " has a nonzero denominator");
    Q c = q;
    c.canonicalize();
    claim(c.get_str() == s, where + " = '" + s + "' is in lowest terms");
    return c;
}

// The double nearest to q, ties to even (GMP only).
double nearest(const Q& q) {
    if (sgn(q) == 0) return 0.0;
    mpz_class n = abs(q.get_num()), d = q.get_den(), m, r, D;
    long e = static_cast<long>(mpz_sizeinbase(n.get_mpz_t(), 2)) - static_cast<long>(mpz_sizeinbase(d.get_mpz_t(), 2)) - 53;
    for (int it = 0; it < 4; ++it) {
        mpz_class N = n;
        D = d;
        if (e < -1074) e = -1074;
        if (e < 0) N <<= static_cast<unsigned long>(-e); else D <<= static_cast<unsigned long>(e);
        mpz_fdiv_qr(m.get_mpz_t(), r.get_mpz_t(), N.get_mpz_t(), D.get_mpz_t());
        if (m >= (mpz_class(1) << 53)) { ++e; continue; }
        if (m < (mpz_class(1) << 52) && e > -1074) { --e; continue; }
        break;
    }
    int c = cmp(mpz_class(2 * r), D);
    if (c > 0 || (c == 0 && mpz_odd_p(m.get_mpz_t()))) ++m;
    double v = std::ldexp(m.get_d(), static_cast<int>(e));
    return sgn(q) < 0 ? -v : v;
}

// An exact field `key` of o, with its neighbour `key_double` equal to the nearest double.
Q field(const J& o, const std::string& key, const std::string& where) {
    claim(o.is_object() && o.contains(key), where + "." + key + " is present");
    Q q = num(o[key], where + "." + key);
    claim(o.contains(key + "_double") && o[key + "_double"].is_number() && o[key + "_double"].get<double>() == nearest(q),
          where + "." + key + "_double is the nearest double to " + q.get_str());
    return q;
}
std::vector<Q> fields(const J& o, const std::string& key, size_t n, const std::string& where) {
    claim(o.is_object() && o.contains(key) && o[key].is_array() && o[key].size() == n, where + "." + key + " has " + std::to_string(n) + " entries");
    const J& dd = o.contains(key + "_double") ? o[key + "_double"] : J();
    claim(dd.is_array() && dd.size() == n, where + "." + key + "_double has " + std::to_string(n) + " entries");
    std::vector<Q> out;
    for (size_t i = 0; i < n; ++i) {
        std::string w = where + "." + key + "[" + std::to_string(i) + "]";
        out.push_back(num(o[key][i], w));
        claim(dd[i].is_number() && dd[i].get<double>() == nearest(out.back()), w + "_double is the nearest double");
    }
    return out;
}

Q dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 cross(const V3& a, const V3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
V3 point(const J& j, const std::string& where) {
    claim(j.is_array() && j.size() == 3, where + " is a point of 3 coordinates");
    return {num(j[0], where + "[0]"), num(j[1], where + "[1]"), num(j[2], where + "[2]")};
}

// ---- the scene ------------------------------------------------------------------------------
struct Scene {
    std::vector<V3> P[2];
    V3 s[2], d;
    Q lo[2], hi[2];
    // h(n) for polyhedron i: max over vertices of σ n·(v − s_i), σ = +1 for P1, −1 for P2.
    Q h(int i, const V3& n, std::vector<int>* argmax = nullptr) const {
        Q best;
        for (size_t k = 0; k < P[i].size(); ++k) {
            Q v = dot(n, sub(P[i][k], s[i]));
            if (i == 1) v = -v;
            if (k == 0 || v > best) { best = v; if (argmax) argmax->clear(); }
            if (argmax && v == best) argmax->push_back(static_cast<int>(k));
        }
        return best;
    }
};

Scene read_scene(const J& j) {
    claim(j.is_object(), "scene is an object");
    Scene sc;
    const char* names[2] = {"P1", "P2"};
    for (int i = 0; i < 2; ++i) {
        claim(j.contains(names[i]) && j[names[i]].contains("vertices") && j[names[i]]["vertices"].is_array(), std::string("scene.") + names[i] + ".vertices is present");
        const J& vs = j[names[i]]["vertices"];
        for (size_t k = 0; k < vs.size(); ++k) sc.P[i].push_back(point(vs[k], std::string("scene.") + names[i] + ".vertices[" + std::to_string(k) + "]"));
        claim(sc.P[i].size() >= 4, std::string("scene.") + names[i] + " has at least 4 vertices");
        claim(j[names[i]].contains("seed"), std::string("scene.") + names[i] + ".seed is present");
        sc.s[i] = point(j[names[i]]["seed"], std::string("scene.") + names[i] + ".seed");
    }
    sc.d = sub(sc.s[1], sc.s[0]);
    const char* iv[2] = {"I1", "I2"};
    for (int i = 0; i < 2; ++i) {
        claim(j.contains(iv[i]) && j[iv[i]].is_array() && j[iv[i]].size() == 2, std::string("scene.") + iv[i] + " is [lo, hi]");
        sc.lo[i] = num(j[iv[i]][0], std::string("scene.") + iv[i] + "[0]");
        sc.hi[i] = num(j[iv[i]][1], std::string("scene.") + iv[i] + "[1]");
        claim(sgn(sc.lo[i]) > 0 && sc.lo[i] <= sc.hi[i], std::string("scene.") + iv[i] + " has 0 < lo <= hi");
    }
    return sc;
}

// Weights [[index, "w"], ...] over polyhedron i: distinct indices, w > 0, sum 1. Returns Σ w v.
V3 combination(const Scene& sc, int i, const J& w, const std::string& where, std::vector<int>* used = nullptr) {
    claim(w.is_array() && !w.empty(), where + " is a nonempty list of weights");
    std::set<long> seen;
    Q total = 0;
    V3 x{0, 0, 0};
    for (size_t k = 0; k < w.size(); ++k) {
        std::string wk = where + "[" + std::to_string(k) + "]";
        claim(w[k].is_array() && w[k].size() == 2 && w[k][0].is_number_integer(), wk + " is [index, weight]");
        long idx = w[k][0].get<long>();
        claim(idx >= 0 && idx < static_cast<long>(sc.P[i].size()) && seen.insert(idx).second, wk + " names a distinct vertex");
        Q l = num(w[k][1], wk + " weight");
        claim(sgn(l) > 0, wk + " weight is > 0");
        total += l;
        for (int c = 0; c < 3; ++c) x[c] += l * sc.P[i][idx][c];
        if (used) used->push_back(static_cast<int>(idx));
    }
    claim(total == 1, where + " weights sum to 1");
    return x;
}

// The seed is a strictly positive combination of vertices that span 3 dimensions: interior.
void check_seed_interior(const Scene& sc, const J& j) {
    const char* names[2] = {"P1", "P2"};
    for (int i = 0; i < 2; ++i) {
        std::string w = std::string("seed_interior.") + names[i];
        claim(j.is_object() && j.contains(names[i]), w + " is present");
        std::vector<int> used;
        claim(combination(sc, i, j[names[i]], w, &used) == sc.s[i], w + " combines to the seed");
        const V3& o = sc.P[i][used[0]];
        bool spans = false;
        for (size_t a = 1; a < used.size() && !spans; ++a)
            for (size_t b = a + 1; b < used.size() && !spans; ++b) {
                V3 c = cross(sub(sc.P[i][used[a]], o), sub(sc.P[i][used[b]], o));
                for (size_t e = b + 1; e < used.size() && !spans; ++e) spans = sgn(dot(c, sub(sc.P[i][used[e]], o))) != 0;
            }
        claim(spans, w + " uses vertices spanning 3 dimensions");
    }
}

// A witness: a common point of P1(ρ1) and P2(ρ2), s + ρ Σ λ (v − s) on each side.
P2 check_witness(const Scene& sc, const J& w, const std::string& where) {
    Q r1 = field(w, "rho1", where), r2 = field(w, "rho2", where);
    claim(sgn(r1) >= 0 && sgn(r2) >= 0, where + " scalings are >= 0");
    std::vector<Q> x = fields(w, "point", 3, where);
    V3 p{x[0], x[1], x[2]};
    const Q* r[2] = {&r1, &r2};
    const char* names[2] = {"P1", "P2"};
    for (int i = 0; i < 2; ++i) {
        claim(w.contains(names[i]), where + "." + names[i] + " is present");
        V3 c = combination(sc, i, w[names[i]], where + "." + names[i]);
        V3 y;
        for (int k = 0; k < 3; ++k) y[k] = sc.s[i][k] + *r[i] * (c[k] - sc.s[i][k]);
        claim(y == p, where + ".point lies in " + names[i] + "(rho" + std::to_string(i + 1) + ")");
    }
    return {r1, r2};
}

V3 normal(const J& j, const std::string& where) {
    claim(j.is_array() && j.size() == 3, where + " is a normal of 3 integers");
    V3 n = point(j, where);
    for (const Q& c : n) claim(c.get_den() == 1, where + " has integer components");
    claim(sgn(n[0]) || sgn(n[1]) || sgn(n[2]), where + " is nonzero");
    return n;
}

// Feature lists: every listed vertex attains the support value; the letter is the dimension of
// the set of all maximisers (V: one point, E: a segment, F: a polygon).
char dimension_letter(const Scene& sc, int i, const std::vector<int>& idx) {
    const V3& o = sc.P[i][idx[0]];
    int dim = 0;
    V3 e1, c;
    for (int k : idx) {
        V3 v = sub(sc.P[i][k], o);
        if (dim == 0 && (sgn(v[0]) || sgn(v[1]) || sgn(v[2]))) { e1 = v; dim = 1; }
        else if (dim == 1) { c = cross(e1, v); if (sgn(c[0]) || sgn(c[1]) || sgn(c[2])) dim = 2; }
    }
    return "VEF"[dim];
}

// ---- the partition ----------------------------------------------------------------------------
struct Line { Q a, b; Q at(const Q& x) const { return a * x + b; } };

std::vector<P2> normalize(std::vector<P2> p) {
    auto cr = [](const P2& o, const P2& a, const P2& b) -> Q { return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]); };
    std::vector<P2> q;
    for (const P2& v : p) if (q.empty() || q.back() != v) q.push_back(v);
    while (q.size() > 1 && q.front() == q.back()) q.pop_back();
    for (size_t i = 0; q.size() > 2 && i < q.size();) {
        if (sgn(cr(q[(i + q.size() - 1) % q.size()], q[i], q[(i + 1) % q.size()])) == 0) { q.erase(q.begin() + static_cast<long>(i)); i = 0; }
        else ++i;
    }
    if (q.size() == 2 && q[1] < q[0]) std::swap(q[0], q[1]);
    if (q.size() > 2) std::rotate(q.begin(), std::min_element(q.begin(), q.end(), [](const P2& a, const P2& b) { return a[1] != b[1] ? a[1] < b[1] : a[0] < b[0]; }), q.end());
    return q;
}

std::vector<P2> clip(const std::vector<P2>& p, const Line& L, bool above) {
    std::vector<P2> out;
    for (size_t i = 0; i < p.size(); ++i) {
        const P2 &u = p[i], &v = p[(i + 1) % p.size()];
        Q fu = u[1] - L.at(u[0]), fv = v[1] - L.at(v[0]);
        if (!above) { fu = -fu; fv = -fv; }
        if (sgn(fu) >= 0) out.push_back(u);
        if (sgn(fu) * sgn(fv) < 0) { Q t = fu / (fu - fv); out.push_back({u[0] + t * (v[0] - u[0]), u[1] + t * (v[1] - u[1])}); }
    }
    return normalize(out);
}

std::vector<P2> polygon(const J& j, const std::string& where) {
    claim(j.is_object() && j.contains("vertices") && j["vertices"].is_array() && j.contains("vertices_double") && j["vertices_double"].size() == j["vertices"].size(), where + ".vertices is present");
    std::vector<P2> out;
    for (size_t k = 0; k < j["vertices"].size(); ++k) {
        std::string w = where + ".vertices[" + std::to_string(k) + "]";
        const J& v = j["vertices"][k];
        const J& dv = j["vertices_double"][k];
        claim(v.is_array() && v.size() == 2 && dv.is_array() && dv.size() == 2, w + " is a point");
        P2 p{num(v[0], w), num(v[1], w)};
        claim(dv[0].is_number() && dv[1].is_number() && dv[0].get<double>() == nearest(p[0]) && dv[1].get<double>() == nearest(p[1]), w + "_double is the nearest double");
        out.push_back(p);
    }
    return out;
}

void check_partition(const J& c) {
    const Scene sc = read_scene(c.at("scene"));
    check_seed_interior(sc, c.at("seed_interior"));
    const J& pieces = c.at("pieces");
    claim(pieces.is_array() && !pieces.empty(), "pieces is a nonempty list");
    std::vector<Line> lines;
    std::vector<std::array<Q, 2>> ranges;
    std::vector<std::array<std::vector<int>, 2>> maxi;  // each piece's maximisers on P1, P2
    for (size_t k = 0; k < pieces.size(); ++k) {
        const J& p = pieces[k];
        std::string w = "pieces[" + std::to_string(k) + "]";
        V3 n = normal(p.at("normal"), w + ".normal");
        std::vector<int> f1, f2;
        Q h1 = sc.h(0, n, &f1), h2 = sc.h(1, n, &f2);
        claim(field(p, "h1", w) == h1 && sgn(h1) > 0, w + ".h1 = max n.(v - s1) over P1, recomputed: " + h1.get_str());
        claim(field(p, "h2", w) == h2 && sgn(h2) > 0, w + ".h2 = max -n.(w - s2) over P2, recomputed: " + h2.get_str());
        Line L{-h1 / h2, dot(n, sc.d) / h2};
        claim(field(p, "slope", w) == L.a, w + ".slope = -h1/h2");
        claim(field(p, "intercept", w) == L.b, w + ".intercept = n.d/h2");
        std::vector<Q> r = fields(p, "rho1", 2, w);
        claim(r[0] < r[1] || (pieces.size() == 1 && r[0] == r[1]), w + ".rho1 is a nonempty range");
        const J& feats = p.at("features");
        const std::vector<int>* all[2] = {&f1, &f2};
        for (int i = 0; i < 2; ++i) {
            std::vector<int> listed = feats.at(i == 0 ? "P1" : "P2").get<std::vector<int>>();
            for (int v : listed) claim(std::count(all[i]->begin(), all[i]->end(), v) == 1, w + ".features lists only maximisers");
            claim(p.at("contact").get<std::string>() == std::string{dimension_letter(sc, 0, f1), dimension_letter(sc, 1, f2)}, w + ".contact is the dimension of the contact features");
        }
        const J& sv = p.at("support_vertices");
        for (int i = 0; i < 2; ++i) {
            long v = sv.at(i == 0 ? "P1" : "P2").get<long>();
            claim(std::count(all[i]->begin(), all[i]->end(), v) == 1, w + ".support_vertices attain the support values");
        }
        if (p.contains("same_line_normals"))
            for (const J& o : p["same_line_normals"]) {
                V3 m = normal(o, w + ".same_line_normals[]");
                Q g1 = sc.h(0, m), g2 = sc.h(1, m);
                claim(sgn(g2) > 0 && -g1 / g2 == L.a && dot(m, sc.d) / g2 == L.b, w + ".same_line_normals give the same line");
            }
        lines.push_back(L);
        maxi.push_back({f1, f2});
        ranges.push_back({r[0], r[1]});
    }
    claim(ranges.front()[0] == sc.lo[0] && ranges.back()[1] == sc.hi[0], "the pieces cover I1 from end to end");
    const J& sw = c.at("switch_points");
    claim(sw.is_array() && sw.size() + 1 == pieces.size(), "one switch point between each two pieces");
    for (size_t k = 0; k + 1 < pieces.size(); ++k) {
        std::string w = "switch_points[" + std::to_string(k) + "]";
        claim(ranges[k][1] == ranges[k + 1][0], "pieces " + std::to_string(k) + " and " + std::to_string(k + 1) + " are contiguous");
        claim(lines[k].a < lines[k + 1].a, "the curve is convex: slopes increase at " + w);
        Q x = field(sw[k], "rho1", w), y = field(sw[k], "rho2", w);
        claim(x == ranges[k][1] && y == lines[k].at(x) && y == lines[k + 1].at(x), w + " is where the neighbouring lines meet");
        if (sgn(y) <= 0) continue;
        claim(sw[k].contains("witness") && check_witness(sc, sw[k]["witness"], w + ".witness") == P2{x, y}, w + " is touching (witness at the switch point)");
        // The contact label: listed features are maximisers on both sides of the switch, and the
        // letters are the dimensions of the listed sets.
        std::string label;
        for (int i = 0; i < 2; ++i) {
            std::vector<int> listed = sw[k].at("features").at(i == 0 ? "P1" : "P2").get<std::vector<int>>();
            claim(!listed.empty(), w + ".features are nonempty");
            for (int v : listed)
                claim(std::count(maxi[k][i].begin(), maxi[k][i].end(), v) && std::count(maxi[k + 1][i].begin(), maxi[k + 1][i].end(), v), w + ".features touch on both neighbouring pieces");
            label += dimension_letter(sc, i, listed);
        }
        claim(sw[k].at("contact").get<std::string>() == label, w + ".contact is the dimension of its features");
    }
    const J& ends = c.at("curve_ends");
    claim(ends.is_array() && ends.size() == 2, "curve_ends has the two ends");
    for (int e = 0; e < 2; ++e) {
        std::string w = "curve_ends[" + std::to_string(e) + "]";
        Q x = field(ends[e], "rho1", w), y = field(ends[e], "rho2", w);
        const Line& L = e == 0 ? lines.front() : lines.back();
        claim(x == (e == 0 ? sc.lo[0] : sc.hi[0]) && y == L.at(x), w + " is the curve at the end of I1");
        if (sgn(y) > 0) claim(ends[e].contains("witness") && check_witness(sc, ends[e]["witness"], w + ".witness") == P2{x, y}, w + " is touching");
    }
    // Growth distance: (ρ*, ρ*) touches — the plane of n has n.d = ρ*(h1 + h2) and a witness — or
    // the seeds coincide and ρ* = 0.
    Q g = field(c, "growth_distance", "");
    const J& gc = c.at("growth_distance_certificate");
    if (gc.contains("seeds_coincide")) {
        claim(sc.d == V3{0, 0, 0} && sgn(g) == 0, "growth distance 0: the seeds coincide");
    } else {
        V3 n = normal(gc.at("normal"), "growth_distance_certificate.normal");
        Q h1 = sc.h(0, n), h2 = sc.h(1, n);
        claim(field(gc, "h1", "growth_distance_certificate") == h1 && field(gc, "h2", "growth_distance_certificate") == h2, "growth_distance_certificate support values recomputed");
        claim(sgn(h1) > 0 && sgn(h2) > 0 && dot(n, sc.d) == g * (h1 + h2), "the growth distance's plane touches at (rho*, rho*)");
        claim(check_witness(sc, gc.at("witness"), "growth_distance_certificate.witness") == P2{g, g}, "growth distance witness is at (rho*, rho*)");
    }
    bool inside = g >= sc.lo[0] && g <= sc.hi[0] && g >= sc.lo[1] && g <= sc.hi[1];
    claim(c.at("growth_distance_in_rectangle").get<bool>() == inside, "growth_distance_in_rectangle is right");
    for (size_t k = 0; k < lines.size(); ++k)
        if (g >= ranges[k][0] && g <= ranges[k][1]) claim(lines[k].at(g) == g, "the growth distance lies on piece " + std::to_string(k));
    // Regions: the rectangle cut along the curve, recomputed here and compared vertex by vertex.
    const J& reg = c.at("regions");
    std::vector<P2> rect = normalize({{sc.lo[0], sc.lo[1]}, {sc.hi[0], sc.lo[1]}, {sc.hi[0], sc.hi[1]}, {sc.lo[0], sc.hi[1]}});
    std::vector<P2> over = rect;
    for (const Line& L : lines) if (!over.empty()) over = clip(over, L, true);
    std::vector<P2> claimed = polygon(reg.at("overlap"), "regions.overlap");
    claim(claimed == over, "regions.overlap is the rectangle on and above the curve");
    const J& wit = reg["overlap"].at("witnesses");
    claim(wit.is_array() && wit.size() == over.size(), "every vertex of the overlap polygon has a witness");
    for (size_t k = 0; k < over.size(); ++k)
        claim(check_witness(sc, wit[k], "regions.overlap.witnesses[" + std::to_string(k) + "]") == over[k], "overlap witness " + std::to_string(k) + " is at its vertex");
    std::vector<std::vector<P2>> seps;
    std::vector<size_t> owners;
    for (size_t k = 0; k < lines.size(); ++k) {
        std::vector<P2> box = normalize({{ranges[k][0], sc.lo[1]}, {ranges[k][1], sc.lo[1]}, {ranges[k][1], sc.hi[1]}, {ranges[k][0], sc.hi[1]}});
        if (box.size() < 3) continue;
        std::vector<P2> s = clip(box, lines[k], false);
        Q area = 0;
        for (size_t i = 0; i < s.size(); ++i) area += s[i][0] * s[(i + 1) % s.size()][1] - s[i][1] * s[(i + 1) % s.size()][0];
        if (s.size() >= 3 && sgn(area) > 0) { seps.push_back(s); owners.push_back(k); }
    }
    const J& sr = reg.at("separated");
    claim(sr.is_array() && sr.size() == seps.size(), "regions.separated has one polygon per piece with area below the curve");
    for (size_t k = 0; k < seps.size(); ++k) {
        std::string w = "regions.separated[" + std::to_string(k) + "]";
        claim(sr[k].at("piece").is_number_integer() && sr[k]["piece"].get<long>() == static_cast<long>(owners[k]), w + ".piece names its piece");
        claim(polygon(sr[k], w) == seps[k], w + " is the rectangle strictly below its piece");
    }
}

// ---- a query answer ----------------------------------------------------------------------------
void check_query(const J& c) {
    const Scene sc = read_scene(c.at("scene"));
    check_seed_interior(sc, c.at("seed_interior"));
    const std::string v = c.at("verdict").get<std::string>();
    Q r1 = field(c, "rho1", ""), r2 = field(c, "rho2", "");
    claim(sgn(r1) > 0 && sgn(r2) > 0, "the scalings are > 0");
    const J& cert = c.at("certificate");
    if (v == "separated" || v == "touching") {
        const J& pl = cert.at("plane");
        V3 n = normal(pl.at("normal"), "plane.normal");
        std::vector<int> f1, f2;
        Q c1 = dot(n, sc.s[0]) + r1 * sc.h(0, n, &f1), c2 = dot(n, sc.s[1]) - r2 * sc.h(1, n, &f2);
        claim(std::count(f1.begin(), f1.end(), pl.at("support_vertices").at("P1").get<long>()) == 1 &&
              std::count(f2.begin(), f2.end(), pl.at("support_vertices").at("P2").get<long>()) == 1, "plane.support_vertices attain the extremes");
        claim(pl.at("contact").get<std::string>() == std::string{dimension_letter(sc, 0, f1), dimension_letter(sc, 1, f2)}, "plane.contact is the dimension of the extreme sets");
        claim(field(pl, "P1_max", "plane") == c1 && field(pl, "P2_min", "plane") == c2, "plane.P1_max and P2_min recomputed from the vertices");
        claim(field(pl, "offset", "plane") == (c1 + c2) / 2, "plane.offset is midway");
        claim(v == "separated" ? c1 < c2 : c1 == c2, v == "separated" ? "the plane separates strictly" : "the plane supports both");
    }
    if (v == "touching") claim(check_witness(sc, cert.at("witness"), "witness") == P2{r1, r2}, "the witness is at the queried pair");
    if (v == "overlapping") {
        P2 w = check_witness(sc, cert.at("witness"), "witness");
        claim(w[0] < r1 && w[1] < r2, "the witness is at a smaller pair, hence interior to both");
    }
    claim(v == "separated" || v == "touching" || v == "overlapping", "the verdict is a known word");
}
}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: scalecert-check CERTIFICATE.json\n";
        return 2;
    }
    J c;
    {
        std::ifstream in(argv[1], std::ios::binary);
        if (!in) { std::cerr << "scalecert-check: error: cannot open " << argv[1] << "\n"; return 2; }
        std::stringstream ss;
        ss << in.rdbuf();
        try { c = J::parse(ss.str()); } catch (const J::exception&) {
            std::cerr << "scalecert-check: error: " << argv[1] << " is not JSON\n";
            return 2;
        }
    }
    try {
        claim(c.is_object() && c.value("format", "") == "scalecert-1", "format is scalecert-1");
        if (c.contains("verdict")) check_query(c); else check_partition(c);
    } catch (const Invalid& e) {
        std::cerr << "scalecert-check: invalid: " << e.what << "\n";
        return 1;
    } catch (const J::exception& e) {
        std::cerr << "scalecert-check: invalid: missing or mistyped field (" << e.what() << ")\n";
        return 1;
    }
    std::cout << "valid: " << g_claims << " claims checked\n";
    return 0;
}
