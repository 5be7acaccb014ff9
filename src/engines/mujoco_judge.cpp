// The MuJoCo front end's judge (mujoco_judge.hpp): the pairs MuJoCo's pipeline considers, each
// judged at every state by the claim rules (signed distances and depth directions at the geoms'
// poses) on a scene of the two geoms as MuJoCo held them.
#include "engines/mujoco_judge.hpp"

#include "campaign/campaign.hpp"
#include "certify/certificate.hpp"
#include "geometry/measures.hpp"
#include "io/files.hpp"
#include "io/mesh.hpp"
#include "numeric/predicates.hpp"
#include "session/engine.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>

namespace scalecert::internal::mj {

namespace {
constexpr int kDisableFilterParent = 1 << 9;  // mjDSBL_FILTERPARENT
constexpr int kDisableContact = 1 << 4;       // mjDSBL_CONTACT
constexpr int kDisableConstraint = 1 << 0;    // mjDSBL_CONSTRAINT: mj_collision runs no collision either
constexpr int kEnableOverride = 1 << 0;       // mjENBL_OVERRIDE

bool judged_type(int type) { return type == kBox || type == kMesh || type == kSphere || type == kCapsule; }
// A sphere's and a capsule's radius (size[0]); 0 for a polyhedron.
double geom_radius(const Geom& g) { return g.type == kSphere || g.type == kCapsule ? g.size[0] : 0; }

// A number written so that a JSON reader reading doubles (the default) gets d exactly.
Json number(double d) { return std::isfinite(d) ? Json(d) : Json(nullptr); }
// A double (or a float's value) as a hex float in a JSON string: exact under every reading.
Json hex(double d) {
    if (!std::isfinite(d)) return Json(nullptr);  // no answer, as a claims file writes it
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", d);
    return Json(std::string(buf));
}

std::string geom_label(const ModelInfo& m, int g) {
    const std::string& n = m.geoms[static_cast<size_t>(g)].name;
    return n.empty() ? "geom " + std::to_string(g) : "'" + n + "'";
}
}  // namespace

// posed_box_side (mujoco_judge.hpp): inside when v =
// M⁻¹(p − t) lies in the box, |v_k| <= size_k, that is (M⁻¹ = adj(M)/det(M)) |adj(M)_k·(p − t)|
// <= size_k·|det M| for each k; farther than `len` when, for some k, p is outside the slab between
// the box's two faces across axis k by more than len: the slab is {x : |adj_k·(x − t)| <= size_k
// |det M|}, so p's distance to it is (|adj_k·(p − t)| − size_k |det M|) / |adj_k|, and the box
// lies in the slab. Within len when the box's point x = M·clamp(v) + t (v clamped into the box)
// is within len of p: the box's distance to p is at most |p − x|. Else unsure (the claim rules
// decide).
ExactPosedBox exact_posed_box(const Geom& g, const Pose& M) {
    ExactPosedBox b;
    auto at = [&](int r, int c) -> const Q& { return M[static_cast<size_t>(r)][static_cast<size_t>(c)]; };
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            // adj(M)[r][c] = the cofactor of M at (c, r).
            const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
            b.adj[r][c] = at(r1, c1) * at(r2, c2) - at(r1, c2) * at(r2, c1);
        }
    Q det = at(0, 0) * b.adj[0][0] + at(0, 1) * b.adj[1][0] + at(0, 2) * b.adj[2][0];
    b.singular = sgn(det) == 0;
    b.det = det;
    b.M = M;
    if (sgn(det) < 0) det = -det;
    for (size_t k = 0; k < 3; ++k) {
        b.size[k] = exact_from_double(g.size[k]);
        b.half[k] = b.size[k] * det;
        b.norm2[k] = b.adj[k][0] * b.adj[k][0] + b.adj[k][1] * b.adj[k][1] + b.adj[k][2] * b.adj[k][2];
        b.t[k] = M[k][3];
    }
    return b;
}
BoxSide posed_box_side(const ExactPosedBox& b, const Vec3q& p, const Q& len) {
    if (b.singular) return BoxSide::Unsure;
    const Q d[3] = {p[0] - b.t[0], p[1] - b.t[1], p[2] - b.t[2]};
    bool inside = true;
    for (size_t k = 0; k < 3; ++k) {
        const Q excess = abs(b.adj[k][0] * d[0] + b.adj[k][1] * d[1] + b.adj[k][2] * d[2]) - b.half[k];
        if (sgn(excess) <= 0) continue;
        inside = false;
        if (excess * excess > len * len * b.norm2[k]) return BoxSide::Farther;
    }
    if (inside) return BoxSide::Inside;
    Vec3q v;
    for (size_t k = 0; k < 3; ++k) {
        v[k] = (b.adj[k][0] * d[0] + b.adj[k][1] * d[1] + b.adj[k][2] * d[2]) / b.det;
        if (v[k] > b.size[k]) v[k] = b.size[k];
        if (v[k] < -b.size[k]) v[k] = -b.size[k];
    }
    Q dist2 = 0;
    for (size_t r = 0; r < 3; ++r) {
        const Q x = b.M[r][0] * v[0] + b.M[r][1] * v[1] + b.M[r][2] * v[2] + b.t[r];
        dist2 += (p[r] - x) * (p[r] - x);
    }
    return dist2 <= len * len ? BoxSide::Within : BoxSide::Unsure;
}

std::vector<Considered> considered_pairs(const ModelInfo& m) {
    std::map<std::pair<int, int>, Considered> out;
    if (m.disableflags & (kDisableContact | kDisableConstraint)) return {};
    const bool override_margin = (m.enableflags & kEnableOverride) != 0;
    // An explicit <pair> replaces the pair the filters would give (MuJoCo 2.2.2 collides it once,
    // at the <pair>'s margin: two boxes 4 mm apart, a geom margin of 5 mm and a <pair> margin of 3 mm
    // give no contact), so pairs are added first.
    auto add = [&](int a, int b, double margin, double gap, bool expl) {
        if (a > b) std::swap(a, b);
        out.try_emplace({a, b}, Considered{a, b, margin, gap, expl});
    };
    // <option collision=...>: "predefined" tests the <pair>s only, "dynamic" the filters' pairs only.
    if (m.collision != 2)
        for (const Pair& p : m.pairs) add(p.g1, p.g2, override_margin ? m.o_margin : p.margin, p.gap, true);
    if (m.collision == 1) {
        std::vector<Considered> v;
        for (auto& [k, c] : out) v.push_back(c);
        return v;
    }
    const std::set<int> excluded(m.excludes.begin(), m.excludes.end());
    const int n = static_cast<int>(m.geoms.size());
    for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b) {
            const Geom &ga = m.geoms[static_cast<size_t>(a)], &gb = m.geoms[static_cast<size_t>(b)];
            if (!(ga.contype & gb.conaffinity) && !(gb.contype & ga.conaffinity)) continue;
            const int w1 = m.body_weld[static_cast<size_t>(ga.body)], w2 = m.body_weld[static_cast<size_t>(gb.body)];
            if (w1 == w2) continue;  // welded together (static geoms of the world among them)
            const int p1 = m.body_weld[static_cast<size_t>(m.body_parent[static_cast<size_t>(w1)])],
                      p2 = m.body_weld[static_cast<size_t>(m.body_parent[static_cast<size_t>(w2)])];
            if (!(m.disableflags & kDisableFilterParent) && w1 != 0 && w2 != 0 && (w1 == p2 || w2 == p1)) continue;
            const int b1 = std::min(ga.body, gb.body), b2 = std::max(ga.body, gb.body);
            if (excluded.count(((b1 + 1) << 16) | (b2 + 1)) || excluded.count(((b2 + 1) << 16) | (b1 + 1))) continue;
            add(a, b, override_margin ? m.o_margin : std::max(ga.margin, gb.margin), std::max(ga.gap, gb.gap), false);
            if (out.size() > kMaxConsideredPairs)
                throw InputError("more than " + std::to_string(kMaxConsideredPairs) +
                                 " geom pairs to consider (the limit)");
        }
    std::vector<Considered> v;
    for (auto& [k, c] : out) v.push_back(c);
    return v;
}

std::vector<std::vector<double>> choose_states(const ModelInfo& m, std::vector<std::vector<double>> qpos,
                                               std::vector<std::string>& labels, int key) {
    if (!qpos.empty() && key >= 0) throw InputError("give states or a keyframe, not both");
    if (qpos.empty() && key >= 0) {
        if (key >= static_cast<int>(m.keys.size()))
            throw InputError("keyframe " + std::to_string(key) + ": the model has " + std::to_string(m.keys.size()) +
                             (m.keys.size() == 1 ? " keyframe" : " keyframes"));
        labels = {"key " + std::to_string(key)};
        return {m.keys[static_cast<size_t>(key)]};
    }
    if (qpos.empty()) {
        labels = {"qpos0"};
        return {m.qpos0};
    }
    labels.resize(qpos.size());
    for (size_t i = 0; i < qpos.size(); ++i) {
        if (labels[i].empty()) labels[i] = "qpos[" + std::to_string(i) + "]";
        if (static_cast<int>(qpos[i].size()) != m.nq)
            throw InputError(labels[i] + ": " + std::to_string(qpos[i].size()) + " numbers; the model's qpos has " +
                             std::to_string(m.nq));
        for (double x : qpos[i])
            if (!std::isfinite(x)) throw InputError(labels[i] + ": a qpos of finite numbers only");
    }
    return qpos;
}

namespace {
// The geom's points in its own frame, exactly as MuJoCo held them.
PolyInput geom_points(const Geom& g) {
    PolyInput in;
    if (g.type == kSphere || g.type == kCapsule) {
        // The centre, or the axis from (0, 0, −h) to (0, 0, h), with the radius (CLAIMS.md,
        // "Objects with a radius").
        in.radius = exact_from_double(g.size[0]);
        in.radius_given = true;
        const Q h = g.type == kCapsule ? exact_from_double(g.size[1]) : Q(0);
        in.points.push_back({Q(0), Q(0), Q(-h)});
        if (sgn(h) > 0) in.points.push_back({Q(0), Q(0), h});
    } else if (g.type == kBox) {
        for (int sx : {-1, 1})
            for (int sy : {-1, 1})
                for (int sz : {-1, 1})
                    in.points.push_back({exact_from_double(sx * g.size[0]), exact_from_double(sy * g.size[1]),
                                         exact_from_double(sz * g.size[2])});
    } else {
        for (size_t k = 0; k + 2 < g.vertices.size(); k += 3)
            in.points.push_back({exact_from_double(g.vertices[k]), exact_from_double(g.vertices[k + 1]),
                                 exact_from_double(g.vertices[k + 2])});
    }
    return in;
}
Json geom_vertices_json(const Geom& g) {
    Json v = Json::array();
    if (g.type == kSphere || g.type == kCapsule) {
        const double h = g.type == kCapsule ? g.size[1] : 0;
        v.push_back(Json::array({hex(0), hex(0), hex(-h)}));
        if (h > 0) v.push_back(Json::array({hex(0), hex(0), hex(h)}));
    } else if (g.type == kBox) {
        for (int sx : {-1, 1})
            for (int sy : {-1, 1})
                for (int sz : {-1, 1})
                    v.push_back(Json::array({hex(sx * g.size[0]), hex(sy * g.size[1]), hex(sz * g.size[2])}));
    } else {
        for (size_t k = 0; k + 2 < g.vertices.size(); k += 3)
            v.push_back(Json::array({hex(g.vertices[k]), hex(g.vertices[k + 1]), hex(g.vertices[k + 2])}));
    }
    return v;
}
Pose pose_of(const State& s, int g) {
    Pose p;
    for (size_t r = 0; r < 3; ++r) {
        for (size_t k = 0; k < 3; ++k) p[r][k] = exact_from_double(s.xmat[9 * static_cast<size_t>(g) + 3 * r + k]);
        p[r][3] = exact_from_double(s.xpos[3 * static_cast<size_t>(g) + r]);
    }
    return p;
}
Json pose_json(const State& s, int g) {
    Json m = Json::array();
    const size_t G = static_cast<size_t>(g);
    for (size_t r = 0; r < 3; ++r)
        m.push_back(Json::array({hex(s.xmat[9 * G + 3 * r]), hex(s.xmat[9 * G + 3 * r + 1]),
                                 hex(s.xmat[9 * G + 3 * r + 2]), hex(s.xpos[3 * G + r])}));
    return m;
}
bool finite_state(const State& s, int g) {
    for (size_t k = 0; k < 9; ++k)
        if (!std::isfinite(s.xmat[9 * static_cast<size_t>(g) + k])) return false;
    for (size_t k = 0; k < 3; ++k)
        if (!std::isfinite(s.xpos[3 * static_cast<size_t>(g) + k])) return false;
    return true;
}

// The geom as the model wrote it (--intended), in the geom's frame: a box as held (its sizes are
// the written doubles); a mesh from its file, each number the double it reads as, scaled and moved
// into MuJoCo's mesh frame exactly: Rᵀ(scale·v − pos), R the rotation of MuJoCo's quat by
// mju_quat2Mat's formula, in rationals. `box` bounds the points, rounded outward to doubles.
struct Intended {
    std::optional<PolyInput> points;
    std::array<double, 6> box{};
    std::string why_not;
};
Intended intended_geom(const Geom& g, const std::vector<MeshSource>& sources) {
    Intended out;
    if (g.type == kBox || g.type == kSphere || g.type == kCapsule) {
        out.points = geom_points(g);  // their sizes are the doubles written
    } else if (g.type == kMesh) {
        if (g.mesh < 0 || static_cast<size_t>(g.mesh) >= sources.size()) {
            out.why_not = "its mesh is not among the model's";
            return out;
        }
        const MeshSource& src = sources[static_cast<size_t>(g.mesh)];
        if (!src.why_not.empty()) {
            out.why_not = "mesh '" + src.name + "': " + src.why_not;
            return out;
        }
        std::vector<Vec3q> file;
        try {
            file = read_mesh(src.file);
        } catch (const InputError& e) {
            out.why_not = "mesh '" + src.name + "': " + e.what();
            return out;
        }
        // MuJoCo keeps the vertices its faces use (each once per face corner): a file with more
        // distinct vertices than MuJoCo holds has ones MuJoCo dropped, and is not the geometry
        // it collides.
        std::vector<Vec3q> distinct = file;
        std::sort(distinct.begin(), distinct.end());
        distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
        if (static_cast<long>(distinct.size()) != src.vertices) {
            out.why_not = "mesh '" + src.name + "': its file has " + std::to_string(distinct.size()) +
                          " distinct vertices, MuJoCo holds " + std::to_string(src.vertices) +
                          " (it drops vertices no face uses)";
            return out;
        }
        const Q w = exact_from_double(src.quat[0]), x = exact_from_double(src.quat[1]),
                y = exact_from_double(src.quat[2]), z = exact_from_double(src.quat[3]);
        const Q R[3][3] = {{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
                           {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
                           {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}};
        PolyInput in;
        for (const Vec3q& v : file) {
            Q d[3];
            for (size_t k = 0; k < 3; ++k)
                d[k] = exact_from_double(src.scale[k]) * v[k] - exact_from_double(src.pos[k]);
            Vec3q u;
            for (size_t r = 0; r < 3; ++r) u[r] = R[0][r] * d[0] + R[1][r] * d[1] + R[2][r] * d[2];  // Rᵀ·d
            in.points.push_back(u);
        }
        out.points = std::move(in);
    } else {
        out.why_not = std::string(geom_type_name(g.type)) + ": not judged";
        return out;
    }
    for (size_t k = 0; k < 3; ++k) {
        Q lo = out.points->points.front()[k], hi = lo;
        for (const Vec3q& p : out.points->points) {
            if (p[k] < lo) lo = p[k];
            if (p[k] > hi) hi = p[k];
        }
        double l = lo.get_d(), h = hi.get_d();
        if (exact_from_double(l) > lo) l = std::nextafter(l, -INFINITY);
        if (exact_from_double(h) < hi) h = std::nextafter(h, INFINITY);
        out.box[k] = l, out.box[k + 3] = h;
    }
    return out;
}

// A contact's normal, frame[0..2], exactly; none when MuJoCo gave no answer there (a NaN, an
// infinity, or the zero vector): a penetrating contact's normal is then judged wrong.
std::optional<Vec3q> normal_of(const Contact& c) {
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(c.frame[k])) return std::nullopt;
    if (c.frame[0] == 0 && c.frame[1] == 0 && c.frame[2] == 0) return std::nullopt;
    return Vec3q{exact_from_double(c.frame[0]), exact_from_double(c.frame[1]), exact_from_double(c.frame[2])};
}

// One ordered geom pair's engine: the scene of the two geoms in their own frames, and its rules.
struct PairEngine {
    std::unique_ptr<SceneEngine> engine;
    std::unique_ptr<ClaimRules> rules;
    std::string why_not;  // why the pair cannot be judged ("" when it can)
};
// Opens e on the scene of the two geoms' points (scaling ranges [1, 1]), `label` naming it in
// messages; e.why_not says why when the engine refuses the scene.
void open_pair(PairEngine& e, const PolyInput& p1, const PolyInput& p2, const std::string& label,
               const Tolerance& tolerance) {
    auto sc = std::make_shared<ExactScene>();
    sc->P[0] = p1;
    sc->P[1] = p2;
    sc->lo[0] = sc->hi[0] = sc->lo[1] = sc->hi[1] = 1;
    try {
        finish_scene(*sc, label);
        e.engine = open_engine(std::shared_ptr<const ExactScene>(sc), label);
        e.engine->check();
        e.rules = e.engine->rules(tolerance);
    } catch (const InputError& x) {
        e.engine.reset();
        e.why_not = x.what();
    }
}

// A rational r >= 0 as a decimal, exactly, where its denominator is 2^a 5^b (every dyadic number:
// what doubles and floats make); else as p/q.
std::string exact_decimal(const Q& r) {
    Z d = r.get_den();
    unsigned long twos = 0, fives = 0;
    while (mpz_divisible_ui_p(d.get_mpz_t(), 2)) d /= 2, ++twos;
    while (mpz_divisible_ui_p(d.get_mpz_t(), 5)) d /= 5, ++fives;
    if (d != 1) return to_exact_string(r);
    const unsigned long k = std::max(twos, fives);  // r·10^k is an integer
    Z p10;
    mpz_ui_pow_ui(p10.get_mpz_t(), 10, k);
    const Z n = r.get_num() * p10 / r.get_den();
    std::string digits = n.get_str(10);
    if (k == 0) return digits;
    if (digits.size() <= k) digits = std::string(k - digits.size() + 1, '0') + digits;
    digits.insert(digits.size() - k, ".");
    return digits;
}

// An exact signed distance s·√E + k: the hulls' s·√E less the radii (k = −R; 0 for polyhedra).
struct Signed {
    int s = 0;
    Q E, k;
};
Signed signed_of(const Judged& j) {
    const SignedDistanceJudged& x = *j.get<SignedDistanceJudged>();
    return {x.root(), x.exact_squared, j.radii ? Q(-((*j.radii)[0] + (*j.radii)[1])) : Q(0)};
}
// The sign of s·√E + k.
int value_sign(const Signed& v) { return sign_minus_sqrt(v.k, Q(-v.s), v.E); }
// s·√E + k − d as the nearest double (MPFR).
double minus_rn(const Signed& v, const Q& d) {
    if (v.s == 0 || sgn(v.E) == 0) return to_double_rn(v.k - d);
    return v.s > 0 ? sqrt_minus_rn(v.E, Q(d - v.k)) : -sqrt_minus_rn(v.E, Q(v.k - d));
}
// The value as a decimal string: exact where √E is rational (a finite decimal where the
// denominator allows, else p/q), else 17 significant digits.
std::string signed_text(const Signed& v) {
    if (v.s == 0) return sgn(v.k) == 0 ? "0" : (v.k < 0 ? "-" + exact_decimal(-v.k) : exact_decimal(v.k));
    Z n = v.E.get_num(), d = v.E.get_den(), rn, rd;
    if (mpz_perfect_square_p(n.get_mpz_t()) && mpz_perfect_square_p(d.get_mpz_t())) {
        mpz_sqrt(rn.get_mpz_t(), n.get_mpz_t());
        mpz_sqrt(rd.get_mpz_t(), d.get_mpz_t());
        Q r(rn, rd);
        r.canonicalize();
        const Q x = v.s * r + v.k;
        return (x < 0 ? "-" : "") + exact_decimal(abs(x));
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", minus_rn(v, Q(0)));
    return buf;
}
double signed_double(const Signed& v) { return minus_rn(v, Q(0)); }
// |d − (s√E + k)|, correctly rounded (MPFR), for a finite d.
double signed_error(double d, const Signed& v) { return std::fabs(minus_rn(v, exact_from_double(d))); }
}  // namespace

MujocoResult judge_states(Loaded& model, const std::vector<std::vector<double>>& states,
                          const std::vector<std::string>& labels, const MujocoOptions& opt) {
    const ModelInfo& m = model.info();
    const std::vector<Considered> pairs = [&] {
        try {
            return considered_pairs(m);
        } catch (const InputError& e) {
            throw InputError(opt.model + ": " + e.what());
        }
    }();
    size_t judged_pairs = 0;
    for (const Considered& p : pairs)
        judged_pairs += judged_type(m.geoms[static_cast<size_t>(p.g1)].type) &&
                        judged_type(m.geoms[static_cast<size_t>(p.g2)].type);
    if (states.size() * std::max<size_t>(pairs.size(), 1) > kMaxPairStates)
        throw InputError(opt.model + ": " + std::to_string(states.size()) + " states of " +
                         std::to_string(pairs.size()) + " geom pairs, more than " + std::to_string(kMaxPairStates) +
                         " pair states in one report (the limit): judge the states in parts");
    if (judged_pairs > kMaxJudgedGeomPairs)
        throw InputError(opt.model + ": " + std::to_string(judged_pairs) +
                         " geom pairs of boxes and meshes to judge, "
                         "more than " +
                         std::to_string(kMaxJudgedGeomPairs) + " (the limit)");
    MujocoResult res;
    std::map<std::pair<int, int>, PairEngine> engines;
    auto engine_for = [&](int a, int b) -> PairEngine& {
        PairEngine& e = engines[{a, b}];
        if (e.engine || !e.why_not.empty()) return e;
        auto sc = std::make_shared<ExactScene>();
        open_pair(e, geom_points(m.geoms[static_cast<size_t>(a)]), geom_points(m.geoms[static_cast<size_t>(b)]),
                  geom_label(m, a) + " and " + geom_label(m, b), opt.tolerance);
        return e;
    };
    // --intended: each judged geom as the model wrote it, its pair engines, and their counts.
    std::vector<Intended> written;
    if (opt.intended) {
        const std::vector<MeshSource> sources = mesh_sources(opt.model);
        for (const Geom& g : m.geoms) written.push_back(judged_type(g.type) ? intended_geom(g, sources) : Intended{});
    }
    std::map<std::pair<int, int>, PairEngine> written_engines;
    long written_wrong = 0, written_unjudged = 0;
    double written_worst_dist = 0;
    auto written_engine_for = [&](int a, int b) -> PairEngine& {
        PairEngine& e = written_engines[{a, b}];
        if (e.engine || !e.why_not.empty()) return e;
        const Intended &ia = written[static_cast<size_t>(a)], &ib = written[static_cast<size_t>(b)];
        if (!ia.points || !ib.points) {
            e.why_not = geom_label(m, ia.points ? b : a) + ": " + (ia.points ? ib.why_not : ia.why_not);
            return e;
        }
        open_pair(e, *ia.points, *ib.points, geom_label(m, a) + " and " + geom_label(m, b) + " as written",
                  opt.tolerance);
        return e;
    };
    if (!opt.failures.empty()) make_output_dir(opt.failures);
    // Each judged geom's box in its own frame (exact doubles: a box's half-sizes, a mesh's float
    // extremes), for filter 12.
    std::vector<std::array<double, 6>> local(m.geoms.size());
    for (size_t g = 0; g < m.geoms.size(); ++g) {
        const Geom& geom = m.geoms[g];
        std::array<double, 6>& b = local[g];
        for (int k = 0; k < 3; ++k) b[static_cast<size_t>(k)] = INFINITY, b[static_cast<size_t>(k) + 3] = -INFINITY;
        if (geom.type == kBox)
            for (int k = 0; k < 3; ++k)
                b[static_cast<size_t>(k)] = -geom.size[k], b[static_cast<size_t>(k) + 3] = geom.size[k];
        if (geom.type == kSphere || geom.type == kCapsule) {
            // The centre or the axis alone: the ball around it stays a ball of radius r in the world
            // whatever the frame (a box posed through the frame need not hold it), so each test
            // below widens its margin by the radii instead (round_margin).
            const double h = geom.type == kCapsule ? geom.size[1] : 0;
            for (size_t k = 0; k < 3; ++k) b[k] = k == 2 ? -h : 0, b[k + 3] = k == 2 ? h : 0;
        }
        for (size_t v = 0; v + 2 < geom.vertices.size(); v += 3)
            for (size_t k = 0; k < 3; ++k) {
                b[k] = std::min(b[k], static_cast<double>(geom.vertices[v + k]));
                b[k + 3] = std::max(b[k + 3], static_cast<double>(geom.vertices[v + k]));
            }
    }
    // The margin that two boxes of centres or axes (`local`) must clear for two geoms to clear m:
    // m plus both radii, rounded up (two ulps cover the two additions' roundings).
    auto round_margin = [&](int a, int b, double margin) {
        const double r = geom_radius(m.geoms[static_cast<size_t>(a)]) + geom_radius(m.geoms[static_cast<size_t>(b)]);
        return r == 0 ? margin : std::nextafter(std::nextafter(margin + r, INFINITY), INFINITY);
    };
    long decided_by_boxes = 0;
    std::vector<std::optional<std::vector<Vec3q>>> object_points(m.geoms.size());  // for planes
    long positions_unjudged = 0;

    Json frames = Json::array(), unjudged = Json::array();
    std::map<std::pair<int, int>, std::string> unjudged_why;
    long judgements = 0, contacts_total = 0, contacts_unjudged = 0, wrong_verdicts = 0;
    double worst_dist = 0;
    Json wrong_list = Json::array();
    std::string text;
    std::set<std::pair<int, int>> considered_set;
    for (const Considered& c : pairs) considered_set.insert({c.g1, c.g2});
    long contacts_outside = 0, verdicts_unjudged = 0;

    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    for (size_t f = 0; f < states.size(); ++f) {
        const Clock::time_point before = Clock::now();
        const State s = model.forward(states[f]);
        res.forward_seconds += std::chrono::duration<double>(Clock::now() - before).count();
        if (!s.error.empty()) {
            std::string e = s.error;
            for (char& c : e)
                if (c == '\n' || c == '\r') c = ' ';
            throw InputError(labels[f] + ": MuJoCo failed in mj_forward: " + e);
        }
        // MuJoCo drops contacts past its buffer (and warns): in such a state no contact says nothing.
        bool buffer_full = false;
        for (const std::string& w : s.warnings) {
            buffer_full = buffer_full || w.find("contact buffer is full") != std::string::npos;
            res.warnings.push_back(labels[f] + ": " + w);
            res.warning_texts.push_back(w);
        }
        // The contacts of each pair, by their own order of the geoms.
        std::map<std::pair<int, int>, std::vector<const Contact*>> of;
        for (const Contact& c : s.contacts) {
            ++contacts_total;
            of[{std::min(c.g1, c.g2), std::max(c.g1, c.g2)}].push_back(&c);
            if (!considered_set.count({std::min(c.g1, c.g2), std::max(c.g1, c.g2)})) ++contacts_outside;
        }
        // Each geom's box at this state (filter 12), made when a pair first asks for it.
        std::vector<std::optional<filter::PosedBox>> posed(m.geoms.size());
        auto box_of = [&](int g) -> const filter::PosedBox& {
            std::optional<filter::PosedBox>& b = posed[static_cast<size_t>(g)];
            if (!b) {
                double M[9], t[3], lo[3], hi[3];
                for (size_t k = 0; k < 9; ++k) M[k] = s.xmat[9 * static_cast<size_t>(g) + k];
                for (size_t k = 0; k < 3; ++k) {
                    t[k] = s.xpos[3 * static_cast<size_t>(g) + k];
                    lo[k] = local[static_cast<size_t>(g)][k];
                    hi[k] = local[static_cast<size_t>(g)][k + 3];
                }
                b = filter::posed_box(M, t, lo, hi);
            }
            return *b;
        };
        // The same outputs against the model as written (--intended): the verdict within the
        // margin and, for a contact, its dist and (penetrating) its normal, as the held geometry's
        // are judged; said in the pair's "intended". Informative: the exit status is the held's.
        auto judge_written = [&](int a, int b, const Considered& p, const Contact* deepest) -> Json {
            PairEngine& we = written_engine_for(a, b);
            if (!we.why_not.empty()) {
                ++written_unjudged;
                return Json{{"why", we.why_not}};
            }
            if (!deepest) {
                filter::PosedBox pb[2];
                for (int i = 0; i < 2; ++i) {
                    const size_t g = static_cast<size_t>(i ? b : a);
                    double M[9], t[3], lo[3], hi[3];
                    for (size_t k = 0; k < 9; ++k) M[k] = s.xmat[9 * g + k];
                    for (size_t k = 0; k < 3; ++k) {
                        t[k] = s.xpos[3 * g + k];
                        lo[k] = written[g].box[k];
                        hi[k] = written[g].box[k + 3];
                    }
                    pb[i] = filter::posed_box(M, t, lo, hi);
                }
                if (filter::boxes_certainly_apart(pb[0], pb[1], round_margin(a, b, p.margin)))
                    return Json{{"verdict", Json{{"exact", "separated"}, {"right", true}}},
                                {"signed_distance", Json{{"decided_by", "their boxes, more than the margin apart"}}}};
            }
            TypedClaim base;
            base.type = ClaimType::SignedDistance;
            base.pose = {pose_of(s, a), pose_of(s, b)};
            TypedClaim verdict = base;
            verdict.bound = deepest ? TypedClaim::Bound::AtMost : TypedClaim::Bound::AtLeast;
            verdict.value = exact_from_double(p.margin);
            const Judged vj = judge_claim(*we.rules, verdict, 0, opt.model, nullptr);
            const SignedDistanceJudged& ex = *vj.get<SignedDistanceJudged>();
            const Signed S = signed_of(vj);
            const bool verdict_judged = deepest || !buffer_full;
            Json out{{"verdict", Json{{"exact", verdict_name(ex.exact)},
                                      {"right", verdict_judged ? Json(vj.right) : Json(nullptr)}}},
                     {"signed_distance", Json{{"exact", signed_text(S)}}}};
            std::vector<std::string> wrong;
            if (verdict_judged && !vj.right)
                wrong.push_back(std::string(deepest ? "a contact" : "no contact") + " within the margin " +
                                to_shortest(p.margin) + ", but the signed distance is ~" +
                                to_shortest(signed_double(S)) + " m");
            if (deepest && std::isfinite(deepest->dist)) {
                TypedClaim dist = base;
                dist.value = exact_from_double(deepest->dist);
                const Judged dj = judge_claim(*we.rules, dist, 1, opt.model, nullptr);
                const double err = signed_error(deepest->dist, S);
                written_worst_dist = std::max(written_worst_dist, err);
                out["dist"] = Json{{"exact", signed_text(S)}, {"error_m", number(err)}, {"right", dj.right}};
                if (!dj.right)
                    wrong.push_back("dist " + to_shortest(deepest->dist) + ", exact ~" + to_shortest(signed_double(S)) +
                                    " m (off by " + to_shortest(err) + " m)");
                if (std::isfinite(deepest->dist) && deepest->dist < 0 && ex.sign() < 0) {
                    const std::optional<Vec3q> n = normal_of(*deepest);
                    bool right = false;
                    if (n) {
                        TypedClaim d = base;
                        d.type = ClaimType::Depth;
                        d.value = exact_from_double(-deepest->dist);
                        d.direction = *n;
                        right = judge_claim(*we.rules, d, 2, opt.model, nullptr)
                                    .get<DepthJudged>()
                                    ->direction_right.value_or(false);
                    }
                    out["normal"] = Json{{"right", right}};
                    if (!right) wrong.push_back(n ? "the normal does not attain the depth" : "the normal is no answer");
                }
            } else if (deepest) {
                out["dist"] = Json{{"right", false}};
                wrong.push_back("dist is not a number");
            }
            if (!wrong.empty()) {
                ++written_wrong;
                for (const std::string& w : wrong)
                    text += "AS WRITTEN  state " + std::to_string(f) + " (" + labels[f] + "): " + geom_label(m, a) +
                            " and " + geom_label(m, b) + ": " + w + "\n";
            }
            return out;
        };
        // Each box geom's exact pose for contact points (posed_box_side), made when first asked.
        std::vector<std::optional<ExactPosedBox>> exact_boxes(m.geoms.size());
        auto exact_box_of = [&](int g, const Pose& pose) -> const ExactPosedBox& {
            std::optional<ExactPosedBox>& e = exact_boxes[static_cast<size_t>(g)];
            if (!e) e = exact_posed_box(m.geoms[static_cast<size_t>(g)], pose);
            return *e;
        };
        // Whether the point q is within r of geom g: 1 yes, 0 no, −1 unsure (a mesh, or a box
        // near an edge: posed_box_side); a plane is its half-space (CLAIMS.md, MuJoCo's planes).
        auto near_geom = [&](int g, const Vec3q& q, const Q& r) -> int {
            const Geom& geom = m.geoms[static_cast<size_t>(g)];
            const size_t G = static_cast<size_t>(g);
            if (geom.type == kBox) {
                const BoxSide bs = posed_box_side(exact_box_of(g, pose_of(s, g)), q, r);
                return bs == BoxSide::Farther ? 0 : bs == BoxSide::Unsure ? -1 : 1;
            }
            if (geom.type == kSphere || geom.type == kCapsule) {
                // Within r + rad of the centre or the axis: the axis is the frame's z column
                // (x = t + M·(0, 0, z), |z| <= h); the point-segment distance in rationals.
                const Q rad = exact_from_double(geom.size[0]) + r;
                const Q h = geom.type == kCapsule ? exact_from_double(geom.size[1]) : Q(0);
                Vec3q a, u;
                for (size_t k = 0; k < 3; ++k) {
                    u[k] = exact_from_double(s.xmat[9 * G + 3 * k + 2]) * h;
                    a[k] = exact_from_double(s.xpos[3 * G + k]) - u[k];
                    u[k] *= 2;  // the segment from t − h·z to t + h·z
                }
                const Vec3q w{q[0] - a[0], q[1] - a[1], q[2] - a[2]};
                const Q uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
                Q f = sgn(uu) == 0 ? Q(0) : Q((w[0] * u[0] + w[1] * u[1] + w[2] * u[2]) / uu);
                if (f < 0) f = 0;
                if (f > 1) f = 1;
                Q d2 = 0;
                for (size_t k = 0; k < 3; ++k) d2 += (w[k] - f * u[k]) * (w[k] - f * u[k]);
                return d2 <= rad * rad ? 1 : 0;
            }
            if (geom.type == kPlane) {
                Q h = 0, N = 0;
                for (size_t j = 0; j < 3; ++j) {
                    const Q n = exact_from_double(s.xmat[9 * G + 3 * j + 2]);
                    h += n * (q[j] - exact_from_double(s.xpos[3 * G + j]));
                    N += n * n;
                }
                if (sgn(N) == 0) return -1;
                return sign_minus_sqrt(h, r, N) <= 0 ? 1 : 0;
            }
            return -1;
        };
        // Why geom g's frame at this state cannot be judged ("" when it can): a NaN or an infinity
        // in it, a plane without a z-axis, a box's or mesh's singular frame (its geom flattened).
        std::vector<std::optional<std::string>> frame_problems(m.geoms.size());
        auto frame_problem = [&](int g) -> const std::string& {
            const size_t G = static_cast<size_t>(g);
            std::optional<std::string>& why = frame_problems[G];
            if (why) return *why;
            if (!finite_state(s, g))
                why = "the geoms' poses are not finite at this state";
            else if (m.geoms[G].type == kPlane)
                why = s.xmat[9 * G + 2] == 0 && s.xmat[9 * G + 5] == 0 && s.xmat[9 * G + 8] == 0
                          ? geom_label(m, g) + "'s frame has a zero z-axis at this state"
                          : "";
            else
                why = judged_type(m.geoms[G].type) && pose_singular(pose_of(s, g))
                          ? geom_label(m, g) + "'s frame is singular at this state"
                          : "";
            return *why;
        };
        // A contact's pos: within |dist|/2 + LEN of both geoms (1), not (0), or unjudged (−1).
        auto position_near_both = [&](int a, int b, const Contact& c) -> int {
            if (!std::isfinite(c.dist)) return -1;  // the dist is judged wrong already
            if (!std::isfinite(c.pos[0]) || !std::isfinite(c.pos[1]) || !std::isfinite(c.pos[2])) return 0;
            const Vec3q q{exact_from_double(c.pos[0]), exact_from_double(c.pos[1]), exact_from_double(c.pos[2])};
            const Q r = abs(exact_from_double(c.dist)) / 2 + opt.tolerance.abs;
            const int na = near_geom(a, q, r);
            if (na == 0) return 0;
            const int nb = near_geom(b, q, r);
            if (nb == 0) return 0;
            if (na < 0 || nb < 0) {
                ++positions_unjudged;
                return -1;
            }
            return 1;
        };
        // A contact's own dist: no contact is deeper than the pair (S <= d + LEN + tol·|S|), and
        // each is within the margin (d <= margin + LEN). A contact failing it is wrong, and its pos
        // is not judged against that dist.
        auto contact_dist_right = [&](const Contact& c, const Signed& v, double margin) {
            if (!std::isfinite(c.dist)) return false;
            const Q d = exact_from_double(c.dist);
            // S = s√E + k, |S| = σS: (k − d − LEN − rel·σ·k) + s(1 − rel·σ)√E <= 0.
            const Q rs = opt.tolerance.rel * value_sign(v);
            return sign_minus_sqrt(v.k - d - opt.tolerance.abs - rs * v.k, Q(-v.s * (1 - rs)), v.E) <= 0 &&
                   d <= exact_from_double(margin) + opt.tolerance.abs;
        };
        // Every contact of a pair: its dist (contact_dist_right), then its pos (position_near_both);
        // the report's "contacts" entry and the text's lines. Returns whether all are right.
        auto judge_contacts = [&](int a, int b, const std::vector<const Contact*>& cons, const Signed& v, double margin,
                                  Json& pj, const std::string& who) {
            Json all_said = Json::array(), wrong_pos = Json::array(), wrong_dist = Json::array();
            long judged_pos = 0;
            for (size_t k = 0; k < cons.size(); ++k) {
                const Contact& c = *cons[k];
                all_said.push_back(Json::array({number(c.pos[0]), number(c.pos[1]), number(c.pos[2])}));
                ++judgements;
                if (!contact_dist_right(c, v, margin)) {
                    wrong_dist.push_back(k);
                    text += who + "contact " + std::to_string(k) + "'s dist " + to_shortest(c.dist) +
                            " is not between the signed distance ~" + to_shortest(signed_double(v)) +
                            " m and the margin " + to_shortest(margin) + "\n";
                    continue;
                }
                const int verdict_of = position_near_both(a, b, c);
                if (verdict_of < 0) continue;
                ++judgements, ++judged_pos;
                if (verdict_of == 1) continue;
                wrong_pos.push_back(k);
                text += who + "contact " + std::to_string(k) + "'s pos (" + to_shortest(c.pos[0]) + ", " +
                        to_shortest(c.pos[1]) + ", " + to_shortest(c.pos[2]) +
                        ") is farther than |dist|/2 from a geom\n";
            }
            pj["pos"]["all_said"] = std::move(all_said);
            const bool dists_right = wrong_dist.empty(), pos_right = wrong_pos.empty();
            pj["contact_dists"] = Json{{"right", dists_right}};
            if (!dists_right) pj["contact_dists"]["wrong_contacts"] = std::move(wrong_dist);
            if (judged_pos) {
                pj["pos"]["right"] = pos_right;
                if (!pos_right) pj["pos"]["wrong_contacts"] = std::move(wrong_pos);
            }
            return dists_right && (judged_pos == 0 || pos_right);
        };
        // A plane geom and a box or mesh geom (CLAIMS.md, "Engines' conventions", MuJoCo's planes):
        // the plane is the half-space n·(x − p0) <= 0, n its z-axis (column 2 of its frame), p0 its
        // origin; with m the least n·(v − p0) over the other geom's posed vertices v and N = |n|²,
        // the signed distance is S = m/√N, and a penetration's only direction is n (from the
        // plane). Each comparison squares with signs; the same claims as a pair of polyhedra.
        auto judge_plane = [&](int a, int b, const Considered& p, const std::vector<const Contact*>* cons,
                               const Contact* deepest) -> Json {
            const bool plane_first = m.geoms[static_cast<size_t>(a)].type == kPlane;
            const int pl = plane_first ? a : b, ob = plane_first ? b : a;
            const size_t P = static_cast<size_t>(pl), O = static_cast<size_t>(ob);
            Vec3q n, w;
            for (size_t k = 0; k < 3; ++k) n[k] = exact_from_double(s.xmat[9 * P + 3 * k + 2]);
            Q c0 = 0, N = 0;
            for (size_t k = 0; k < 3; ++k) {
                w[k] = 0;
                for (size_t r = 0; r < 3; ++r) w[k] += exact_from_double(s.xmat[9 * O + 3 * r + k]) * n[r];
                c0 += n[k] * (exact_from_double(s.xpos[3 * O + k]) - exact_from_double(s.xpos[3 * P + k]));
                N += n[k] * n[k];
            }
            const Q margin = exact_from_double(p.margin);
            Json pj{
                {"geom1", a},
                {"geom2", b},
                {"names", Json::array({m.geoms[static_cast<size_t>(a)].name, m.geoms[static_cast<size_t>(b)].name})},
                {"margin", p.margin},
                {"contacts", cons ? cons->size() : 0}};
            // No contact, and the object's box (its local box's corners, posed exactly) beyond the
            // plane by at least the margin: right, without its vertices (with --intended, judged
            // below so that the pair is judged as written too).
            if (!deepest && !opt.intended) {
                Q lower;
                for (int k = 0; k < 8; ++k) {
                    Q x = c0;
                    for (size_t j = 0; j < 3; ++j) x += w[j] * exact_from_double(local[O][(k >> j) & 1 ? j + 3 : j]);
                    if (k == 0 || x < lower) lower = x;
                }
                // (A ball reaches r·√N past its centre or axis along n: the margin widens by r.)
                if (sign_minus_sqrt(lower, margin - opt.tolerance.abs + exact_from_double(geom_radius(m.geoms[O])),
                                    N) >= 0) {
                    ++judgements;
                    ++decided_by_boxes;
                    pj["verdict"] = Json{{"said", "no contact"}, {"exact", "separated"}, {"right", true}};
                    pj["signed_distance"] = Json{{"decided_by", "its box, beyond the plane by the margin"}};
                    return pj;
                }
            }
            if (!object_points[O]) object_points[O] = geom_points(m.geoms[O]).points;
            Q least;
            bool first = true;
            for (const Vec3q& v : *object_points[O]) {
                const Q x = w[0] * v[0] + w[1] * v[1] + w[2] * v[2] + c0;
                if (first || x < least) least = x, first = false;
            }
            // S = m/√N − r, r the object's radius (a sphere's, a capsule's; 0 for a polyhedron).
            const int sign = sgn(least);
            const Q rad = exact_from_double(geom_radius(m.geoms[O]));
            const Signed S{sign, least * least / N, Q(-rad)};
            const int vs = value_sign(S);
            const Verdict exact = vs > 0 ? Verdict::Separated : vs == 0 ? Verdict::Touching : Verdict::Overlapping;
            // A contact claims S <= margin (+ LEN), none S >= margin (− LEN), as for two polyhedra.
            const bool verdict_judged = deepest || !buffer_full;
            const bool vright = deepest ? sign_minus_sqrt(least, margin + opt.tolerance.abs + rad, N) <= 0
                                        : sign_minus_sqrt(least, margin - opt.tolerance.abs + rad, N) >= 0;
            judgements += verdict_judged;
            pj["verdict"] = Json{{"said", deepest ? "contact" : "no contact"},
                                 {"exact", verdict_name(exact)},
                                 {"right", verdict_judged ? Json(vright) : Json(nullptr)}};
            pj["signed_distance"] = Json{{"exact", signed_text(S)}};
            put_exact(pj["signed_distance"], "exact_squared", S.E);
            if (sgn(rad) != 0) put_exact(pj["signed_distance"], "radii", rad);  // S = m/√N − radii
            if (!verdict_judged) {
                pj["verdict"]["why"] = "MuJoCo's contact buffer was full at this state: its contacts were dropped";
                ++verdicts_unjudged;
            }
            bool all_right = vright || !verdict_judged;
            const std::string who = "WRONG  state " + std::to_string(f) + " (" + labels[f] + "): " + geom_label(m, a) +
                                    " and " + geom_label(m, b) + ": ";
            if (!all_right) {
                ++wrong_verdicts;
                wrong_list.push_back(Json{{"frame", f},
                                          {"geom1", a},
                                          {"geom2", b},
                                          {"said", deepest ? "contact" : "no contact"},
                                          {"exact", verdict_name(exact)},
                                          {"signed_distance_m", signed_double(S)},
                                          {"margin", p.margin}});
                text += who + (deepest ? "a contact" : "no contact") + " within the margin " + to_shortest(p.margin) +
                        ", but the signed distance is ~" + to_shortest(signed_double(S)) + " m (" +
                        verdict_name(exact) + ")\n";
            }
            if (deepest) {
                const bool finite = std::isfinite(deepest->dist);
                const bool dright =
                    finite && opt.tolerance.close_value(exact_from_double(deepest->dist), sign, S.E, S.k);
                const double err = finite ? signed_error(deepest->dist, S) : INFINITY;
                worst_dist = std::max(worst_dist, err);
                ++judgements;
                pj["dist"] = Json{{"said", number(deepest->dist)},
                                  {"exact", signed_text(S)},
                                  {"error_m", number(err)},
                                  {"right", dright}};
                all_right = all_right && dright;
                if (!dright)
                    text += who + "dist " + to_shortest(deepest->dist) + ", exact ~" + to_shortest(signed_double(S)) +
                            " m (off by " + to_shortest(err) + " m)\n";
                Json said =
                    Json::array({number(deepest->frame[0]), number(deepest->frame[1]), number(deepest->frame[2])});
                if (deepest->dist < 0 && vs < 0) {
                    // Moving geom2 along the normal by the depth separates them only along +n from
                    // the plane (the plane geom1) or −n (the plane geom2): the normal must be a
                    // positive multiple of it, exactly.
                    Vec3q u, d = n;
                    bool known = true;
                    for (size_t k = 0; k < 3; ++k) {
                        known = known && std::isfinite(deepest->frame[k]);
                        u[k] = known ? exact_from_double(deepest->frame[k]) : Q(0);
                        if (!plane_first) d[k] = -d[k];
                    }
                    const bool parallel = known && u[1] * d[2] == u[2] * d[1] && u[2] * d[0] == u[0] * d[2] &&
                                          u[0] * d[1] == u[1] * d[0] &&
                                          sgn(u[0] * d[0] + u[1] * d[1] + u[2] * d[2]) > 0;
                    ++judgements;
                    pj["normal"] = Json{{"said", said}, {"right", parallel}};
                    all_right = all_right && parallel;
                    if (!parallel) text += who + "the normal is not the plane's\n";
                } else {
                    pj["normal"] = Json{{"said", said}};
                }
                pj["pos"] = Json{
                    {"said", Json::array({number(deepest->pos[0]), number(deepest->pos[1]), number(deepest->pos[2])})}};
                // Each contact's dist and pos (judge_contacts), the half-space as a geom.
                all_right = judge_contacts(a, b, *cons, S, p.margin, pj, who) && all_right;
            }
            if (!all_right) res.wrong += 1;
            if (opt.intended) {
                // As written: the same half-space against the geom as written (a plane is its frame).
                const Intended& iw = written[O];
                if (!iw.points) {
                    ++written_unjudged;
                    pj["intended"] = Json{{"why", geom_label(m, ob) + ": " + iw.why_not}};
                    return pj;
                }
                Q lw;
                bool firstw = true;
                for (const Vec3q& v : iw.points->points) {
                    const Q x = w[0] * v[0] + w[1] * v[1] + w[2] * v[2] + c0;
                    if (firstw || x < lw) lw = x, firstw = false;
                }
                const Q& radw = iw.points->radius;
                const Signed Sw{sgn(lw), lw * lw / N, Q(-radw)};
                const int sw = value_sign(Sw);
                const bool vw = deepest ? sign_minus_sqrt(lw, margin + opt.tolerance.abs + radw, N) <= 0
                                        : sign_minus_sqrt(lw, margin - opt.tolerance.abs + radw, N) >= 0;
                const bool vjudged = deepest || !buffer_full;
                Json iwj{{"verdict", Json{{"exact", verdict_name(sw > 0    ? Verdict::Separated
                                                                 : sw == 0 ? Verdict::Touching
                                                                           : Verdict::Overlapping)},
                                          {"right", vjudged ? Json(vw) : Json(nullptr)}}},
                         {"signed_distance", Json{{"exact", signed_text(Sw)}}}};
                std::vector<std::string> wrong;
                if (vjudged && !vw)
                    wrong.push_back(std::string(deepest ? "a contact" : "no contact") + " within the margin " +
                                    to_shortest(p.margin) + ", but the signed distance is ~" +
                                    to_shortest(signed_double(Sw)) + " m");
                if (deepest) {
                    const bool finite = std::isfinite(deepest->dist);
                    const bool dright =
                        finite && opt.tolerance.close_value(exact_from_double(deepest->dist), Sw.s, Sw.E, Sw.k);
                    const double err = finite ? signed_error(deepest->dist, Sw) : INFINITY;
                    written_worst_dist = std::max(written_worst_dist, err);
                    iwj["dist"] = Json{{"exact", signed_text(Sw)}, {"error_m", number(err)}, {"right", dright}};
                    if (!dright)
                        wrong.push_back("dist " + to_shortest(deepest->dist) + ", exact ~" +
                                        to_shortest(signed_double(Sw)) + " m (off by " + to_shortest(err) + " m)");
                }
                if (!wrong.empty()) {
                    ++written_wrong;
                    for (const std::string& x : wrong)
                        text += "AS WRITTEN  state " + std::to_string(f) + " (" + labels[f] + "): " + geom_label(m, a) +
                                " and " + geom_label(m, b) + ": " + x + "\n";
                }
                pj["intended"] = std::move(iwj);
            }
            return pj;
        };
        Json fp = Json::array();
        for (const Considered& p : pairs) {
            const Geom &ga = m.geoms[static_cast<size_t>(p.g1)], &gb = m.geoms[static_cast<size_t>(p.g2)];
            const auto cs = of.find({p.g1, p.g2});
            const size_t ncon = cs == of.end() ? 0 : cs->second.size();
            std::string why;
            // A plane against a box or a mesh: a half-space, judged below (plane_pair).
            const bool plane_pair =
                (ga.type == kPlane && judged_type(gb.type)) || (gb.type == kPlane && judged_type(ga.type));
            if (ga.type == kPlane && gb.type == kPlane)
                why = "two planes: MuJoCo 2.2.2 has no plane-plane collision";
            else if (!plane_pair && (!judged_type(ga.type) || !judged_type(gb.type))) {
                const Geom& g = judged_type(ga.type) || ga.type == kPlane ? gb : ga;
                why = std::string(geom_type_name(g.type)) +
                      ": not judged (judged: box, mesh, sphere, capsule and plane geoms)";
            }
            // The deepest contact speaks for the pair (a box's manifold holds a point per corner);
            // its geoms' order is the claim's: P1 = its geom1, its normal from geom1 to geom2.
            const Contact* deepest = nullptr;
            if (ncon)
                for (const Contact* c : cs->second)
                    if (!deepest || c->dist < deepest->dist || std::isnan(c->dist)) deepest = c;
            const int a = deepest ? deepest->g1 : p.g1, b = deepest ? deepest->g2 : p.g2;
            if (why.empty()) why = frame_problem(a);
            if (why.empty()) why = frame_problem(b);
            if (plane_pair && why.empty()) {
                fp.push_back(judge_plane(a, b, p, cs == of.end() ? nullptr : &cs->second, deepest));
                continue;
            }
            PairEngine* pe = nullptr;
            if (why.empty()) {
                pe = &engine_for(a, b);
                if (!pe->why_not.empty()) why = pe->why_not;
            }
            // No contact, and the geoms' boxes more than the margin apart: right, without the
            // exact distance (filter 12).
            if (why.empty() && !deepest && finite_state(s, a) && finite_state(s, b) &&
                filter::boxes_certainly_apart(box_of(a), box_of(b), round_margin(a, b, p.margin))) {
                ++judgements;
                ++decided_by_boxes;
                fp.push_back(
                    Json{{"geom1", a},
                         {"geom2", b},
                         {"names",
                          Json::array({m.geoms[static_cast<size_t>(a)].name, m.geoms[static_cast<size_t>(b)].name})},
                         {"margin", p.margin},
                         {"contacts", 0},
                         {"verdict", Json{{"said", "no contact"}, {"exact", "separated"}, {"right", true}}},
                         {"signed_distance", Json{{"decided_by", "their boxes, more than the margin apart"}}}});
                if (opt.intended) fp.back()["intended"] = judge_written(a, b, p, nullptr);
                continue;
            }
            if (!why.empty()) {
                contacts_unjudged += static_cast<long>(ncon);
                if (unjudged_why.emplace(std::make_pair(p.g1, p.g2), why).second)
                    unjudged.push_back(Json{{"geom1", p.g1},
                                            {"geom2", p.g2},
                                            {"names", Json::array({ga.name, gb.name})},
                                            {"types", Json::array({geom_type_name(ga.type), geom_type_name(gb.type)})},
                                            {"why", why}});
                continue;
            }
            // The claims: the verdict within the margin, and for a contact its dist and (within
            // the bodies) its normal.
            TypedClaim base;
            base.type = ClaimType::SignedDistance;
            base.pose = {pose_of(s, a), pose_of(s, b)};
            TypedClaim verdict = base;
            verdict.bound = deepest ? TypedClaim::Bound::AtMost : TypedClaim::Bound::AtLeast;
            verdict.value = exact_from_double(p.margin);
            const Judged vj = judge_claim(*pe->rules, verdict, 0, opt.model, nullptr);
            const SignedDistanceJudged& ex = *vj.get<SignedDistanceJudged>();
            const Signed S = signed_of(vj);
            const bool verdict_judged = deepest || !buffer_full;
            const bool verdict_right = vj.right || !verdict_judged;
            judgements += verdict_judged;
            Json pj{
                {"geom1", a},
                {"geom2", b},
                {"names", Json::array({m.geoms[static_cast<size_t>(a)].name, m.geoms[static_cast<size_t>(b)].name})},
                {"margin", p.margin},
                {"contacts", ncon},
                {"verdict", Json{{"said", deepest ? "contact" : "no contact"},
                                 {"exact", verdict_name(ex.exact)},
                                 {"right", verdict_judged ? Json(vj.right) : Json(nullptr)}}},
                {"signed_distance", Json{{"exact", signed_text(S)}}}};
            put_exact(pj["signed_distance"], "exact_squared", ex.exact_squared);
            if (sgn(S.k) != 0) put_exact(pj["signed_distance"], "radii", Q(-S.k));  // S = s√E − radii
            if (!verdict_judged) {
                pj["verdict"]["why"] = "MuJoCo's contact buffer was full at this state: its contacts were dropped";
                ++verdicts_unjudged;
            }
            bool all_right = verdict_right;
            // Whether a claim the reproducer holds (the verdict, dist, normal) is wrong: a pair
            // state wrong only in its contacts' positions or secondary dists writes none.
            bool claim_wrong = !verdict_right;
            // The reproducer's claims: a contact's verdict there is "below" the margin, which a
            // claims file holds (at_most is not one of its bounds), so it is kept only when it was
            // judged wrong (S > margin: then below it is wrong too).
            std::vector<TypedClaim> claims;
            if (!vj.right || verdict.bound != TypedClaim::Bound::AtMost) claims.push_back(verdict);
            if (!verdict_right) {
                ++wrong_verdicts;
                wrong_list.push_back(Json{{"frame", f},
                                          {"geom1", a},
                                          {"geom2", b},
                                          {"said", deepest ? "contact" : "no contact"},
                                          {"exact", verdict_name(ex.exact)},
                                          {"signed_distance_m", signed_double(S)},
                                          {"margin", p.margin}});
                text += "WRONG  state " + std::to_string(f) + " (" + labels[f] + "): " + geom_label(m, a) + " and " +
                        geom_label(m, b) + ": " + (deepest ? "a contact" : "no contact") + " within the margin " +
                        to_shortest(p.margin) + ", but the signed distance is ~" + to_shortest(signed_double(S)) +
                        " m (" + verdict_name(ex.exact) + ")\n";
            }
            if (deepest) {
                TypedClaim dist = base;
                dist.bound = TypedClaim::Bound::Value;
                if (std::isfinite(deepest->dist))
                    dist.value = exact_from_double(deepest->dist);
                else
                    dist.no_answer = "value", dist.no_answer_reason = "not a number";
                const Judged dj = judge_claim(*pe->rules, dist, 1, opt.model, nullptr);
                ++judgements;
                const double err = std::isfinite(deepest->dist) ? signed_error(deepest->dist, S) : INFINITY;
                worst_dist = std::max(worst_dist, err);
                pj["dist"] = Json{{"said", number(deepest->dist)},
                                  {"exact", signed_text(S)},
                                  {"error_m", number(err)},
                                  {"right", dj.right}};
                all_right = all_right && dj.right;
                claim_wrong = claim_wrong || !dj.right;
                claims.push_back(dist);
                if (!dj.right)
                    text += "WRONG  state " + std::to_string(f) + " (" + labels[f] + "): " + geom_label(m, a) +
                            " and " + geom_label(m, b) + ": dist " + to_shortest(deepest->dist) + ", exact ~" +
                            to_shortest(signed_double(S)) + " m (off by " + to_shortest(err) + " m)\n";
                Json said =
                    Json::array({number(deepest->frame[0]), number(deepest->frame[1]), number(deepest->frame[2])});
                if (std::isfinite(deepest->dist) && deepest->dist < 0 && ex.sign() < 0) {
                    // The normal of a penetrating contact: moving geom2 by the depth along it
                    // separates the geoms (CLAIMS.md, penetration_depth's direction); a NaN or
                    // zero normal is no answer, wrong.
                    const std::optional<Vec3q> n = normal_of(*deepest);
                    TypedClaim d = base;
                    d.type = ClaimType::Depth;
                    d.value = exact_from_double(-deepest->dist);
                    if (n)
                        d.direction = *n;
                    else
                        d.no_answer = "direction", d.no_answer_reason = "not a number, or the zero vector";
                    bool right = false;
                    if (n)
                        right = judge_claim(*pe->rules, d, 2, opt.model, nullptr)
                                    .get<DepthJudged>()
                                    ->direction_right.value_or(false);
                    ++judgements;
                    pj["normal"] = Json{{"said", said}, {"right", right}};
                    all_right = all_right && right;
                    claim_wrong = claim_wrong || !right;
                    claims.push_back(d);
                    if (!right)
                        text += "WRONG  state " + std::to_string(f) + " (" + labels[f] + "): " + geom_label(m, a) +
                                " and " + geom_label(m, b) + ": the normal does not attain the depth\n";
                } else {
                    pj["normal"] = Json{{"said", said}};  // judged for penetrating contacts only
                }
                pj["pos"] = Json{
                    {"said", Json::array({number(deepest->pos[0]), number(deepest->pos[1]), number(deepest->pos[2])})}};
                // Each contact's dist and pos (judge_contacts).
                all_right = judge_contacts(a, b, cs->second, S, p.margin, pj,
                                           "WRONG  state " + std::to_string(f) + " (" + labels[f] +
                                               "): " + geom_label(m, a) + " and " + geom_label(m, b) + ": ") &&
                            all_right;
            }
            if (!all_right) {
                res.wrong += 1;
                if (!opt.failures.empty() && claim_wrong) {
                    // A reproducer: the two geoms as MuJoCo held them (a mesh's float32 vertices),
                    // and the claims at their poses, which certify-fp replays; every number a hex
                    // float in a JSON string, exact under every reading.
                    const std::string stem = opt.failures + "/frame" + std::to_string(f) + "_g" + std::to_string(a) +
                                             "_g" + std::to_string(b);
                    Json scene;
                    for (int i = 0; i < 2; ++i) {
                        const Geom& g = m.geoms[static_cast<size_t>(i ? b : a)];
                        scene[i ? "P2" : "P1"] = Json{{"vertices", geom_vertices_json(g)}};
                        if (geom_radius(g) > 0) scene[i ? "P2" : "P1"]["radius"] = hex(geom_radius(g));
                    }
                    Json cl = Json::array();
                    for (const TypedClaim& c : claims) {
                        Json j{{"kind", type_name(c.type)}, {"rho1", 1}, {"rho2", 1}};
                        if (c.type == ClaimType::SignedDistance) {
                            const char* key = c.bound == TypedClaim::Bound::Value     ? "value"
                                              : c.bound == TypedClaim::Bound::AtLeast ? "at_least"
                                                                                      : "below";  // (AtMost too)
                            j[key] = c.bound == TypedClaim::Bound::Value ? hex(deepest->dist) : hex(p.margin);
                        } else if (c.type == ClaimType::Witness) {
                            // The point's rationals are doubles' exact values: get_d is exact.
                            j["point"] = Json::array(
                                {hex(c.point[0].get_d()), hex(c.point[1].get_d()), hex(c.point[2].get_d())});
                        } else {
                            j["value"] = hex(-deepest->dist);
                            j["direction"] =
                                Json::array({hex(deepest->frame[0]), hex(deepest->frame[1]), hex(deepest->frame[2])});
                        }
                        j["pose1"] = pose_json(s, a);
                        j["pose2"] = pose_json(s, b);
                        cl.push_back(std::move(j));
                    }
                    // How to replay it: the same tolerances.
                    std::string replay = "scalecert certify-fp " + stem + ".scene.json " + stem + ".claims.json";
                    if (sgn(opt.tolerance.rel) > 0) replay += " --tolerance " + to_exact_string(opt.tolerance.rel);
                    if (sgn(opt.tolerance.abs) > 0) replay += " --abs-tolerance " + to_exact_string(opt.tolerance.abs);
                    Json about{{"model", opt.model},
                               {"frame", f},
                               {"state", labels[f]},
                               {"geom1", a},
                               {"geom2", b},
                               {"names", pj["names"]},
                               {"tolerance", to_exact_string(opt.tolerance.rel)},
                               {"abs_tolerance", to_exact_string(opt.tolerance.abs)},
                               {"replay", replay}};
                    Json q = Json::array();
                    for (double x : states[f]) q.push_back(x);
                    about["qpos"] = std::move(q);
                    ++res.reproducers;
                    write_files_atomically({{stem + ".scene.json", dump(scene)},
                                            {stem + ".claims.json",
                                             dump(Json{{"format", "scalecert-claims-1"}, {"claims", std::move(cl)}})},
                                            {stem + ".about.json", dump(about)}});
                }
            }
            if (opt.intended) pj["intended"] = judge_written(a, b, p, deepest);
            fp.push_back(std::move(pj));
        }
        Json fr{{"frame", f}, {"state", labels[f]}, {"pairs", std::move(fp)}};
        if (!s.warnings.empty()) fr["mujoco_warnings"] = s.warnings;
        frames.push_back(std::move(fr));
    }
    Json summary{{"states", states.size()},
                 {"pairs_considered", pairs.size()},
                 {"pairs_unjudged", unjudged.size()},
                 {"judgements", judgements},
                 {"wrong_pairs", res.wrong},
                 {"contacts", contacts_total},
                 {"contacts_unjudged", contacts_unjudged},
                 {"contacts_outside_considered_pairs", contacts_outside},
                 {"verdicts_unjudged_buffer_full", verdicts_unjudged},
                 {"decided_by_boxes", decided_by_boxes},
                 {"positions_unjudged", positions_unjudged},
                 {"mujoco_warnings", res.warnings.size()},
                 {"worst_dist_error_m", worst_dist},
                 {"wrong_verdicts", std::move(wrong_list)}};
    if (opt.intended)
        summary["intended"] = Json{{"wrong_pairs", written_wrong},
                                   {"pair_states_unjudged", written_unjudged},
                                   {"worst_dist_error_m", written_worst_dist}};
    res.report = Json{{"format", "scalecert-mujoco-1"},
                      {"model", opt.model},
                      {"tolerance", to_exact_string(opt.tolerance.rel)},
                      {"abs_tolerance", to_exact_string(opt.tolerance.abs)},
                      {"frames", std::move(frames)},
                      {"unjudged", std::move(unjudged)},
                      {"summary", std::move(summary)}};
    const Json& sm = res.report["summary"];
    text += "states: " + std::to_string(states.size()) + ", pairs considered: " + std::to_string(pairs.size()) +
            " (unjudged: " + std::to_string(sm["pairs_unjudged"].get<long>()) +
            "), judgements: " + std::to_string(judgements) + ", wrong: " + std::to_string(res.wrong) +
            " pair states (" + std::to_string(wrong_verdicts) + " verdicts), worst dist error " +
            to_shortest(worst_dist) + " m\n";
    if (contacts_outside > 0)
        text += "contacts MuJoCo reported for pairs it does not consider (a geom with itself, a filtered pair): " +
                std::to_string(contacts_outside) + ", not judged\n";
    if (opt.intended)
        text += "as written (--intended): wrong: " + std::to_string(written_wrong) + " pair states" +
                (written_unjudged ? " (" + std::to_string(written_unjudged) + " pair states unjudged)" : "") +
                ", worst dist error " + to_shortest(written_worst_dist) + " m\n";
    // The unjudged pairs, the first 20 a line each (the JSON report has them all).
    const Json& all_unjudged = res.report["unjudged"];
    for (size_t i = 0; i < all_unjudged.size() && i < 20; ++i) {
        const Json& u = all_unjudged[i];
        text += "unjudged: " + geom_label(m, u["geom1"].get<int>()) + " and " + geom_label(m, u["geom2"].get<int>()) +
                ": " + u["why"].get<std::string>() + "\n";
    }
    if (all_unjudged.size() > 20)
        text += "unjudged: " + std::to_string(all_unjudged.size() - 20) + " more pairs (--json lists them)\n";
    res.text = std::move(text);
    res.judge_seconds = std::chrono::duration<double>(Clock::now() - start).count() - res.forward_seconds;
    return res;
}

}  // namespace scalecert::internal::mj
