// The public API (include/scalecert/scalecert.hpp) over the internal stages.
#include "scalecert/scalecert.hpp"
#include "session/scene_access.hpp"
#include "session/engine.hpp"

#include "certify/certificate.hpp"
#include "certify/claim.hpp"
#include "certify/judgements.hpp"
#include "certify/report.hpp"
#include "certify/classify.hpp"
#include "certify/golden.hpp"
#include "geometry/measures.hpp"
#include "io/mesh.hpp"
#include "curve/scan.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <thread>

namespace scalecert {

// The engine's names: none shares a name with the public API's.
using namespace internal;

const char* version() { return SCALECERT_VERSION_STRING; }

Rational exact(double x) {
    if (!std::isfinite(x)) throw InputError("not a finite number");
    return exact_from_double(x);
}
Rational parse_rational(const std::string& text) { return parse_exact(text); }
const char* name(Numbers n) { return numbers_name(n); }
Rational held(double x, Numbers numbers) {
    if (!std::isfinite(x)) throw InputError("not a finite number");
    if (numbers == Numbers::Double) return exact_from_double(x);
    if (numbers == Numbers::Float32) {
        const float f = static_cast<float>(x);
        if (!std::isfinite(f)) throw InputError(to_shortest(x) + " is beyond the float32 range");
        return exact_from_double(static_cast<double>(f));
    }
    return parse_exact(to_shortest(x));
}
std::string to_string(const Rational& q) { return to_exact_string(q); }

const char* name(Verdict v) { return verdict_name(v); }
const char* name(ClaimedVerdict v) { return claimed_name(v); }
const char* name(ContactKind k) {
    static const char* const names[] = {"VV", "VE", "VF", "EV", "EE", "EF", "FV", "FE", "FF"};
    return names[static_cast<int>(k)];
}
Feature feature1(ContactKind k) { return static_cast<Feature>(static_cast<int>(k) / 3); }
Feature feature2(ContactKind k) { return static_cast<Feature>(static_cast<int>(k) % 3); }

namespace {

Point canonical(Point p) {
    for (Rational& x : p) x.canonicalize();
    return p;
}

Q canonical_q(Q q) {
    q.canonicalize();
    return q;
}

// Object i's seed (when given) and range, in lowest terms.
void seed_and_range(internal::ExactScene& sc, int i, const std::optional<Point>& seed, const Interval& range) {
    if (seed) {
        sc.P[i].seed = canonical(*seed);
        sc.P[i].seed_given = true;
    }
    sc.lo[i] = range.lo;
    sc.hi[i] = range.hi;
    sc.lo[i].canonicalize();
    sc.hi[i].canonicalize();
}

// Two convex objects from their points, ranges and seeds, read as a scene file is (not yet
// validated); each object's note (a reader's remark) kept.
internal::ExactScene convex_scene(std::vector<Point> p1, std::vector<Point> p2, const Interval& i1, const Interval& i2,
                                  const std::optional<Point>& seed1, const std::optional<Point>& seed2,
                                  std::string note1 = {}, std::string note2 = {},
                                  const std::array<Rational, 2>* radii = nullptr) {
    internal::ExactScene sc;
    std::vector<Point>* pts[2] = {&p1, &p2};
    const std::optional<Point>* seeds[2] = {&seed1, &seed2};
    const Interval* ranges[2] = {&i1, &i2};
    for (int i = 0; i < 2; ++i) {
        for (Point& v : *pts[i]) v = canonical(std::move(v));
        sc.P[i].points = std::move(*pts[i]);
        seed_and_range(sc, i, *seeds[i], *ranges[i]);
        if (radii) {
            Rational r = (*radii)[static_cast<size_t>(i)];
            r.canonicalize();
            if (sgn(r) < 0)
                throw InputError(std::string("scene: ") + (i ? "P2" : "P1") + ": radius: a radius is >= 0 (got " +
                                 in_quotes(to_exact_string(r)) + ")");
            sc.P[i].radius = r;
            sc.P[i].radius_given = true;
        }
    }
    sc.P[0].note = std::move(note1);
    sc.P[1].note = std::move(note2);
    finish_scene(sc, "scene");
    return sc;
}

}  // namespace

Scene::Scene(std::vector<Point> p1, std::vector<Point> p2, Interval i1, Interval i2, std::optional<Point> seed1,
             std::optional<Point> seed2) {
    d_ = SceneAccess::validated(convex_scene(std::move(p1), std::move(p2), i1, i2, seed1, seed2), "scene");
}

Scene Scene::with_radii(std::vector<Point> p1, std::vector<Point> p2, std::array<Rational, 2> radii, Interval i1,
                        Interval i2, std::optional<Point> seed1, std::optional<Point> seed2) {
    return Scene(SceneAccess::validated(
        convex_scene(std::move(p1), std::move(p2), i1, i2, seed1, seed2, {}, {}, &radii), "scene"));
}

struct Scene::Data {
    // The scene read exactly. A scene read straight into machine integers (from_meshes on two
    // large OFF files of integers, as the command reads them) has none until something asks for
    // it (its parts, points, JSON, golden data): then it is made once from `compact`.
    mutable std::shared_ptr<const internal::ExactScene> scene;
    mutable std::once_flag exact_once;
    bool integers_only = false;  // read straight into `compact` (a convex scene)
    const internal::ExactScene& sc() const {
        if (integers_only)
            std::call_once(exact_once, [this] {
                scene = std::make_shared<const internal::ExactScene>(internal::full_scene(*compact));
            });
        return *scene;
    }
    std::string name;  // prefixes the hull model's errors
    // The points as machine integers, when the engine walks (Session::plan decides; large scenes
    // only, when they fit): made once, shared by every Analysis of the scene.
    std::shared_ptr<const internal::CompactScene> compact;
    std::once_flag once;
    std::shared_ptr<const HullModel> model;
    bool convex() const { return integers_only || !scene->made_of_parts(); }
    // The hull model, built once for every Analysis of the scene.
    const std::shared_ptr<const HullModel>& hull() {
        std::call_once(once, [this] { model = std::make_shared<const HullModel>(build_model(sc(), name)); });
        return model;
    }
    // The scene's engine (open_engine chooses it), with the scene's hull model.
    std::unique_ptr<internal::SceneEngine> engine(const std::shared_ptr<Data>& self) const {
        internal::SceneSource src;
        if (!integers_only) src.exact = scene;
        src.compact = compact;
        src.name = name;
        src.hull = [self] { return self->hull(); };
        return internal::open_engine(std::move(src));
    }
};

std::shared_ptr<Scene::Data> SceneAccess::validated(internal::ExactScene sc, const std::string& name) {
    auto d = std::make_shared<Scene::Data>();
    d->scene = std::make_shared<const internal::ExactScene>(std::move(sc));
    d->name = name;
    const std::unique_ptr<internal::SceneEngine> e = d->engine(d);
    e->check();
    d->compact = e->compact();
    return d;
}

Scene Scene::from_parts(std::vector<std::vector<Point>> parts1, std::vector<std::vector<Point>> parts2, Interval i1,
                        Interval i2, std::optional<Point> seed1, std::optional<Point> seed2,
                        std::array<std::vector<Rational>, 2> part_radii) {
    internal::ExactScene sc;
    std::vector<std::vector<Point>>* parts[2] = {&parts1, &parts2};
    const std::optional<Point>* seeds[2] = {&seed1, &seed2};
    const Interval* ranges[2] = {&i1, &i2};
    for (int i = 0; i < 2; ++i) {
        const std::string name = i ? "P2" : "P1";
        if (parts[i]->empty()) throw InputError("scene: " + name + ": expected a nonempty list of parts");
        if (parts[i]->size() > internal::kMaxParts)
            throw InputError("scene: " + name + ": more than " + std::to_string(internal::kMaxParts) +
                             " parts (the limit)");
        for (std::vector<Point>& part : *parts[i]) {
            for (Point& v : part) v = canonical(std::move(v));
            if (sc.P[i].points.size() + part.size() > internal::kMaxPoints)
                throw InputError("scene: " + name + ": more than " + std::to_string(internal::kMaxPoints) +
                                 " points in all its parts (the limit)");
            sc.P[i].points.insert(sc.P[i].points.end(), part.begin(), part.end());
            sc.P[i].parts.push_back(std::move(part));
        }
        std::vector<Rational>& radii = part_radii[static_cast<size_t>(i)];
        if (!radii.empty() && radii.size() != sc.P[i].parts.size())
            throw InputError("scene: " + name + ": " + std::to_string(radii.size()) + " radii for " +
                             std::to_string(sc.P[i].parts.size()) + " parts (give one a part, or none)");
        bool some = false;
        for (size_t k = 0; k < radii.size(); ++k) {
            radii[k] = canonical_q(std::move(radii[k]));
            if (sgn(radii[k]) < 0)
                throw InputError("scene: " + name + ": part " + std::to_string(k) + ": a radius is >= 0 (got " +
                                 radii[k].get_str() + ")");
            some = some || sgn(radii[k]) > 0;
        }
        if (some) sc.P[i].part_radii.assign(radii.begin(), radii.end());
        seed_and_range(sc, i, *seeds[i], *ranges[i]);
    }
    finish_scene(sc, "scene");
    return Scene(SceneAccess::validated(std::move(sc), "scene"));
}

Scene Scene::load(const std::string& path, Numbers numbers) {
    internal::ReadOptions opt;
    opt.allow_parts = true;
    opt.numbers = numbers;
    return Scene(SceneAccess::validated(load_scene(path, opt), path));
}

std::shared_ptr<Scene::Data> SceneAccess::from_integers(const std::string& p1_path, const std::string& p2_path,
                                                        const Interval& i1, const Interval& i2, Numbers numbers) {
    try {
        const std::string paths[2] = {p1_path, p2_path};
        const Rational lo[2] = {i1.lo, i2.lo}, hi[2] = {i1.hi, i2.hi};
        const std::optional<internal::Vec3q> seeds[2];
        std::optional<internal::CompactScene> cs = internal::compact_from_off(paths, lo, hi, seeds, numbers);
        if (!cs || !internal::walk_by_default(cs->P[0].size(), cs->P[1].size())) return nullptr;
        auto d = std::make_shared<Scene::Data>();
        d->integers_only = true;
        d->compact = std::make_shared<internal::CompactScene>(std::move(*cs));
        d->name = "scene";
        // Session::plan walks such a scene (compact points, walk_by_default); Session::check would
        // then prove the seeds as here, and build the hull model when they are not.
        if (!internal::scan_seeds_proved(*d->compact)) return nullptr;
        return d;
    } catch (const InputError&) {
        return nullptr;
    }
}

Scene Scene::from_meshes(const std::string& p1_path, const std::string& p2_path, Interval i1, Interval i2,
                         bool parts_from_groups, Numbers numbers,
                         const std::array<std::optional<scalecert::Pose>, 2>& poses,
                         const std::array<std::optional<Point>, 2>& seeds) {
    const bool posed = poses[0] || poses[1], seeded = seeds[0] || seeds[1];
    if (!parts_from_groups && !posed && !seeded)
        if (std::shared_ptr<Data> d = SceneAccess::from_integers(p1_path, p2_path, i1, i2, numbers))
            return Scene(std::move(d));
    // Each object's given seed, then the object and its seed at its pose, when it has one.
    auto move = [&poses, &seeds](int i, internal::PolyInput& in) {
        if (const auto& s = seeds[static_cast<size_t>(i)]) {
            in.seed = canonical(*s);
            in.seed_given = true;
        }
        if (const auto& m = poses[static_cast<size_t>(i)])
            internal::apply_pose(*m, in, std::string("scene: pose of P") + (i ? "2" : "1"));
    };
    auto seed_of = [](const internal::PolyInput& in) {
        return in.seed_given ? std::optional<Point>(in.seed) : std::nullopt;
    };
    long inexact = 0;
    internal::ReadOptions opt;
    opt.numbers = numbers;
    opt.inexact = &inexact;
    if (!parts_from_groups) {
        std::string note[2];
        internal::PolyInput in[2];
        in[0].points = read_mesh(p1_path, opt, &note[0]);
        in[1].points = read_mesh(p2_path, opt, &note[1]);
        for (int i = 0; i < 2; ++i) move(i, in[i]);
        internal::ExactScene sc = convex_scene(std::move(in[0].points), std::move(in[1].points), i1, i2, seed_of(in[0]),
                                               seed_of(in[1]), std::move(note[0]), std::move(note[1]));
        sc.inexact_numbers = inexact;
        sc.numbers = numbers;
        return Scene(SceneAccess::validated(std::move(sc), "scene"));
    }
    opt.allow_parts = true;
    opt.parts_from_groups = true;
    internal::ExactScene sc;
    sc.numbers = numbers;
    const std::string* paths[2] = {&p1_path, &p2_path};
    const Interval* ranges[2] = {&i1, &i2};
    for (int i = 0; i < 2; ++i) {
        read_mesh_object(*paths[i], opt, sc.P[i]);
        move(i, sc.P[i]);
        seed_and_range(sc, i, std::nullopt, *ranges[i]);
    }
    const std::string name = p1_path + " and " + p2_path;
    finish_scene(sc, name);
    sc.inexact_numbers = inexact;
    return Scene(SceneAccess::validated(std::move(sc), name));
}

bool Scene::convex() const { return d_->convex(); }
size_t Scene::part_count(int i) const {
    if (i != 0 && i != 1)
        throw InputError("scene: object " + std::to_string(i) + ": the objects are 0 (P1) and 1 (P2)");
    return std::max<size_t>(1, d_->sc().P[i].parts.size());
}
const std::vector<Point>& Scene::part(int i, size_t k) const {
    const size_t n = part_count(i);  // i checked
    const internal::PolyInput& P = d_->sc().P[i];
    if (k >= n)
        throw InputError("scene: P" + std::to_string(i + 1) + " has no part " + std::to_string(k) +
                         " (its parts are numbered from 0)");
    return P.parts.empty() ? P.points : P.parts[k];
}
const std::string& Scene::part_name(int i, size_t k) const {
    part(i, k);  // i and k checked
    return internal::part_name(d_->sc().P[i], k);
}
std::vector<std::string> Scene::notes() const {
    std::vector<std::string> n;
    if (d_->integers_only) return n;  // OFF files read as written: no groups, nothing to say (and no exact form made)
    return internal::scene_notes(d_->sc());
}
const std::vector<Point>& Scene::points(int i) const { return d_->sc().P[i & 1].points; }
const Point& Scene::seed(int i) const { return d_->sc().P[i & 1].seed; }
Interval Scene::range(int i) const { return {d_->sc().lo[i & 1], d_->sc().hi[i & 1]}; }
Rational Scene::radius(int i) const { return d_->sc().P[i & 1].radius; }
Rational Scene::part_radius(int i, size_t k) const {
    const internal::PolyInput& in = d_->sc().P[i & 1];
    if (k >= std::max<size_t>(1, in.parts.size()))
        throw InputError("scene: P" + std::to_string((i & 1) + 1) + " has no part " + std::to_string(k));
    return in.part_radius(k);
}
std::string Scene::json() const { return dump(internal::scene_file_json(d_->sc())); }

struct Analysis::Impl {
    Scene scene;
    // Calls on one Analysis from several threads at once are not supported (scalecert.hpp), so
    // the engine builds its models lazily behind the const interface.
    std::unique_ptr<internal::SceneEngine> engine;
    explicit Impl(const Scene& s) : scene(s), engine(s.d_->engine(s.d_)) {}
};

namespace {
// What is defined for two convex objects only, refused on parts with what answers instead.
std::string convex_only(const char* what) {
    return std::string(what) +
           " is defined for two convex objects; on objects made of parts, the region gives where they meet, with its "
           "labelled boundary, switch points and growth set (C++ region_json(), Python region(), `scalecert region`)";
}

void check_rho(const Rational& r, const char* what) {
    if (sgn(r) <= 0) throw InputError(std::string(what) + ": a scaling factor must be > 0");
}
}  // namespace

Analysis::Analysis(const Scene& scene) {
    auto impl = std::make_shared<Impl>(scene);
    impl->engine->prepare();
    impl_ = std::move(impl);
}

bool Analysis::convex() const { return impl_->engine->convex(); }

const Curve& Analysis::curve() const { return impl_->engine->curve(convex_only("curve")); }

Verdict Analysis::verdict(const Rational& rho1, const Rational& rho2) const {
    check_rho(rho1, "rho1");
    check_rho(rho2, "rho2");
    return impl_->engine->verdict(canonical_q(rho1), canonical_q(rho2));
}

QueryResult Analysis::query(const Rational& rho1, const Rational& rho2) const {
    check_rho(rho1, "rho1");
    check_rho(rho2, "rho2");
    return impl_->engine->query(canonical_q(rho1), canonical_q(rho2));
}

std::vector<Verdict> Analysis::classify(const std::vector<double>& rho1, const std::vector<double>& rho2,
                                        unsigned threads) const {
    if (rho1.size() != rho2.size())
        throw InputError("classify: " + std::to_string(rho1.size()) + " values of rho1 but " +
                         std::to_string(rho2.size()) + " of rho2");
    for (size_t i = 0; i < rho1.size(); ++i)
        if (!(std::isfinite(rho1[i]) && std::isfinite(rho2[i]) && rho1[i] > 0 && rho2[i] > 0))
            throw InputError("classify: pair " + std::to_string(i) +
                             " (numbered from 0): two finite numbers > 0 are required");
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    return impl_->engine->classify(rho1, rho2, threads, "classify", nullptr);
}

PlaneCheck Analysis::check_plane(const Rational& rho1, const Rational& rho2, const Point& normal,
                                 const std::optional<Rational>& offset) const {
    check_rho(rho1, "rho1");
    check_rho(rho2, "rho2");
    const Point n = canonical(normal);
    if (sgn(n[0]) == 0 && sgn(n[1]) == 0 && sgn(n[2]) == 0) throw InputError("check_plane: the normal is zero");
    const auto [c1, c2] = impl_->engine->plane_extents(n, rho1, rho2);
    PlaneCheck r;
    r.c1 = c1;
    r.c2 = c2;
    r.separates = internal::plane_separates(r.c1, r.c2, offset);
    return r;
}

std::string Analysis::curve_json() const {
    internal::Session& s = impl_->engine->convex_session(convex_only("curve_json"));
    return dump(internal::curve_json(s.curve_model(), s.curve()));
}

std::string Analysis::query_json(const Rational& rho1, const Rational& rho2) const {
    check_rho(rho1, "rho1");
    check_rho(rho2, "rho2");
    return impl_->engine->verdict_document(canonical_q(rho1), canonical_q(rho2));
}

std::string Analysis::partition_json() const { return impl_->engine->partition_document(); }

std::string Analysis::region_json() const { return dump(impl_->engine->region().region_json()); }

ClaimReport Analysis::certify_fp(const std::string& claims, const ClaimOptions& options) const {
    long wrong = 0, count = 0;
    std::string certificate;
    std::unique_ptr<internal::ClaimRules> rules = impl_->engine->rules({options.tolerance, options.abs_tolerance});
    std::string report = internal::certify_fp(*rules, claims, "claims", options, &wrong, &count,
                                              options.certificate ? &certificate : nullptr);
    return {std::move(report), count, wrong, std::move(certificate)};
}

namespace {
// A public claim, typed for the rules (claim.hpp), its faults refused with one line naming it.
internal::TypedClaim typed_claim(const Claim& c, size_t i, const internal::ClaimRules& rules) {
    using internal::ClaimType;
    const std::string where = "certify: claims[" + std::to_string(i) + "]";
    internal::TypedClaim t;
    t.rho1 = canonical_q(c.rho1);
    t.rho2 = canonical_q(c.rho2);
    if (sgn(t.rho1) <= 0) throw InputError(where + ".rho1: scalings must be > 0 (got " + to_exact_string(t.rho1) + ")");
    if (sgn(t.rho2) <= 0) throw InputError(where + ".rho2: scalings must be > 0 (got " + to_exact_string(t.rho2) + ")");
    if (!c.no_answer.empty()) t.no_answer = c.no_answer, t.no_answer_reason = "not a number";
    for (size_t k = 0; k < 2; ++k) {
        const std::optional<Pose>& m = k ? c.pose2 : c.pose1;
        if (!m) continue;
        const std::string w = where + (k ? ".pose2" : ".pose1");
        Pose& p = t.pose[k].emplace();
        for (size_t r = 0; r < 3; ++r)
            for (size_t q = 0; q < 4; ++q) p[r][q] = canonical_q((*m)[r][q]);
        if (internal::pose_singular(p))
            throw InputError(w + ": its 3x3 part R is singular (determinant 0): the object would be flat");
    }
    auto nonzero = [&](const Point& p, const char* key) {
        const Point q = canonical(p);
        if (sgn(q[0]) == 0 && sgn(q[1]) == 0 && sgn(q[2]) == 0 && t.no_answer.empty())
            t.no_answer = key, t.no_answer_reason = "the zero vector";
        return q;
    };
    switch (c.kind) {
    case ClaimKind::Verdict:
        t.type = ClaimType::Verdict;
        t.verdict = c.verdict;
        break;
    case ClaimKind::SeparatingPlane:
        t.type = ClaimType::Plane;
        t.normal = nonzero(c.normal, "normal");
        if (c.offset) t.offset = canonical_q(*c.offset);
        break;
    case ClaimKind::WitnessPoint:
        t.type = ClaimType::Witness;
        t.point = canonical(c.point);
        break;
    case ClaimKind::Distance:
        t.type = ClaimType::Distance;
        t.value = canonical_q(c.value);
        if (c.closest) t.closest = std::array<Point, 2>{canonical((*c.closest)[0]), canonical((*c.closest)[1])};
        break;
    case ClaimKind::PenetrationDepth:
        t.parts = rules.part_pair(c.parts, where);
        t.type = ClaimType::Depth;
        t.value = canonical_q(c.value);
        if (c.direction) t.direction = nonzero(*c.direction, "direction");
        break;
    case ClaimKind::SignedDistance:
        t.type = ClaimType::SignedDistance;
        // On parts: refused (no radii), or a contact of one part pair (radii).
        if (const std::string why = rules.refusal(t.type); !why.empty())
            throw InputError(where + ".kind: signed_distance: " + why);
        t.parts = rules.part_pair(c.parts, where);
        t.value = canonical_q(c.value);
        t.bound = c.bound == SignedBound::AtLeast ? internal::TypedClaim::Bound::AtLeast
                  : c.bound == SignedBound::Below ? internal::TypedClaim::Bound::Below
                                                  : internal::TypedClaim::Bound::Value;
        break;
    }
    if (const std::string why = rules.refusal(t.type); !why.empty())
        throw InputError(where + ".kind: " + internal::type_name(t.type) + ": " + why);
    return t;
}

// Its judgement, as the public type has it.
Judgement public_judgement(const internal::TypedClaim& c, const internal::Judged& g,
                           const internal::ClaimRules& rules) {
    Judgement j;
    if (const internal::ExactScene* parts = rules.parts(); parts && g.part1 >= 0 && g.part2 >= 0) {
        j.part1 = g.part1;
        j.part2 = g.part2;
        j.part1_name = internal::part_name(parts->P[0], static_cast<size_t>(g.part1));
        j.part2_name = internal::part_name(parts->P[1], static_cast<size_t>(g.part2));
    }
    j.right = g.right;
    if (const auto* d = g.get<internal::DistanceJudged>()) {
        j.value_right = d->value_right;
        j.closest_right = d->closest_right;
    }
    if (const auto* d = g.get<internal::DepthJudged>()) {
        j.value_right = d->value_right;
        j.direction_right = d->direction_right;
    }
    if (const std::optional<internal::Judged::Surd> v = g.radii ? g.exact_value() : std::nullopt) {
        // Objects with a radius: exact = s·√E + k, E the hulls' square.
        j.exact_squared = v->E;
        j.radius_sum = (*g.radii)[0] + (*g.radii)[1];
        j.exact = internal::report_parts::surd_rn(v->s, v->E, v->k);
        const double err = std::fabs(internal::report_parts::surd_rn(v->s, v->E, Q(v->k - c.value)));
        j.rel_error = j.exact != 0 ? err / std::fabs(j.exact) : err == 0 ? 0.0 : INFINITY;
    } else if (const std::optional<Q> e = g.exact_squared()) {
        j.exact_squared = *e;
        j.exact = sqrt_minus_rn(*e, Q(0));
        // A signed distance σ·√E: |value − σ√E| = |σ·value − √E| for σ = ±1 (E = 0 when σ = 0).
        const auto* sd = g.get<internal::SignedDistanceJudged>();
        const int sigma = sd ? sd->sign() : 1;
        if (sigma < 0) j.exact = -j.exact;
        // |value − exact| / |exact|, MPFR-rounded; relative to an exact 0: 0 for a claimed 0, else inf.
        j.rel_error = sgn(*e)             ? relative_sqrt_error_rn(*e, sigma < 0 ? Q(-c.value) : c.value)
                      : sgn(c.value) == 0 ? 0.0
                                          : INFINITY;
    }
    if (c.type == internal::ClaimType::Verdict || c.type == internal::ClaimType::SignedDistance)
        j.exact_verdict = g.exact_verdict();
    if (!c.no_answer.empty()) j.reason = c.no_answer + ": " + c.no_answer_reason;
    return j;
}

void check_tolerance(const ClaimOptions& options) {
    if (sgn(options.tolerance) < 0)
        throw InputError("tolerance: must be >= 0 (got " + to_exact_string(options.tolerance) + ")");
    if (sgn(options.abs_tolerance) < 0)
        throw InputError("abs_tolerance: must be >= 0 (got " + to_exact_string(options.abs_tolerance) + ")");
}
}  // namespace

// Typed claims through typed rules: no JSON unless a certificate is asked for.
Judgements Analysis::certify(const std::vector<Claim>& claims, const ClaimOptions& options) const {
    check_tolerance(options);
    std::unique_ptr<internal::ClaimRules> rules = impl_->engine->rules({options.tolerance, options.abs_tolerance});
    std::vector<internal::TypedClaim> typed;
    typed.reserve(claims.size());
    for (size_t i = 0; i < claims.size(); ++i) typed.push_back(typed_claim(claims[i], i, *rules));
    Judgements out;
    out.items.reserve(claims.size());
    Json entries = Json::array();
    for (size_t i = 0; i < typed.size(); ++i) {
        const internal::Judged g =
            internal::judge_claim(*rules, typed[i], i, "certify: claims[" + std::to_string(i) + "]",
                                  options.certificate ? &entries : nullptr);
        out.wrong += !g.right;
        out.items.push_back(public_judgement(typed[i], g, *rules));
    }
    if (options.certificate) out.certificate = rules->certificate(std::move(entries));
    return out;
}

GoldenData Analysis::golden(const GoldenOptions& options) const {
    internal::GoldenAnswers g = impl_->engine->golden(internal::GoldenPoints{options.verticals, options.offsets});
    g.curve["queries"] = std::move(g.queries);
    return {dump(g.curve), std::move(g.csv), std::move(g.rational_csv)};
}

}  // namespace scalecert
