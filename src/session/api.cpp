// The public API (include/scalecert/scalecert.hpp) over the internal stages.
#include "scalecert/scalecert.hpp"
#include "session/scene_access.hpp"
#include "session/compound_session.hpp"
#include "session/session.hpp"

#include "certify/certificate.hpp"
#include "certify/claim.hpp"
#include "certify/compound_judge.hpp"
#include "certify/judgements.hpp"
#include "certify/region_certificate.hpp"
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
const char* name(ContactKind k) {
    static const char* const names[] = {"VV", "VE", "VF", "EV", "EE", "EF", "FV", "FE", "FF"};
    return names[static_cast<int>(k)];
}
Feature feature1(ContactKind k) { return static_cast<Feature>(static_cast<int>(k) / 3); }
Feature feature2(ContactKind k) { return static_cast<Feature>(static_cast<int>(k) % 3); }

namespace {

int feature_index(char c) {
    switch (c) {
    case 'V': return 0;
    case 'E': return 1;
    case 'F': return 2;
    }
    throw std::logic_error("unknown feature letter");
}

Contact contact_of(const std::string& label, const std::vector<int>& f1, const std::vector<int>& f2) {
    if (label.size() != 2) throw std::logic_error("contact label of two letters expected");
    return {static_cast<ContactKind>(3 * feature_index(label[0]) + feature_index(label[1])), f1, f2};
}

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
                                  std::string note1 = {}, std::string note2 = {}) {
    internal::ExactScene sc;
    std::vector<Point>* pts[2] = {&p1, &p2};
    const std::optional<Point>* seeds[2] = {&seed1, &seed2};
    const Interval* ranges[2] = {&i1, &i2};
    for (int i = 0; i < 2; ++i) {
        for (Point& v : *pts[i]) v = canonical(std::move(v));
        sc.P[i].points = std::move(*pts[i]);
        seed_and_range(sc, i, *seeds[i], *ranges[i]);
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
    // A session on the scene: the engine it chooses (Session::plan) with the scene's hull model.
    std::unique_ptr<internal::Session> session(const std::shared_ptr<Data>& self) const {
        auto s = integers_only ? std::make_unique<internal::Session>(compact, name)
                               : std::make_unique<internal::Session>(scene, compact, name);
        s->set_hull_source([self] { return self->hull(); });
        return s;
    }
};

std::shared_ptr<Scene::Data> SceneAccess::validated(internal::ExactScene sc, const std::string& name) {
    auto d = std::make_shared<Scene::Data>();
    d->scene = std::make_shared<const internal::ExactScene>(std::move(sc));
    d->name = name;
    if (!d->convex()) return d;  // its parts' hulls are built where they are needed
    const std::unique_ptr<internal::Session> s = d->session(d);
    s->check();
    d->compact = s->compact_scene();
    return d;
}

Scene Scene::from_parts(std::vector<std::vector<Point>> parts1, std::vector<std::vector<Point>> parts2, Interval i1,
                        Interval i2, std::optional<Point> seed1, std::optional<Point> seed2) {
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
std::string Scene::json() const { return dump(internal::scene_file_json(d_->sc())); }

struct Analysis::Impl {
    Scene scene;
    // Calls on one Analysis from several threads at once are not supported (scalecert.hpp), so
    // the sessions build their models lazily behind the const interface. A convex scene has its
    // Session (and a CompoundSession too once its region is asked for); a scene of parts has its
    // CompoundSession only.
    mutable std::unique_ptr<internal::Session> session;
    mutable std::unique_ptr<internal::CompoundSession> compound;
    explicit Impl(const Scene& s) : scene(s) {
        if (!s.d_->convex()) {
            compound = std::make_unique<internal::CompoundSession>(s.d_->sc(), s.d_->name);
            return;
        }
        session = s.d_->session(s.d_);
    }
    bool convex() const { return session != nullptr; }
    internal::CompoundSession& region() const {
        if (!compound) compound = std::make_unique<internal::CompoundSession>(scene.d_->sc(), scene.d_->name);
        return *compound;
    }
    // What is defined for two convex objects only, refused on parts with what answers instead.
    internal::Session& convex_only(const char* what) const {
        if (!session)
            throw InputError(std::string(what) +
                             " is defined for two convex objects; on objects made of parts, the region gives where "
                             "they meet, with its labelled boundary, switch points and growth set (C++ region_json(), "
                             "Python region(), "
                             "`scalecert region`)");
        return *session;
    }
};

Analysis::Analysis(const Scene& scene) {
    auto impl = std::make_shared<Impl>(scene);
    if (!impl->convex()) {
        impl_ = std::move(impl);
        return;
    }
    const internal::TouchingCurve& c = impl->session->curve();
    const Model& m = impl->session->curve_model();
    for (const CurvePiece& p : c.pieces) {
        const ContactLine& L = m.lines[c.env.pieces[p.env].line];
        std::optional<Contact> k;
        if (!p.contact.label.empty()) k = contact_of(p.contact.label, p.contact.feat1, p.contact.feat2);
        curve_.pieces.push_back({p.from, p.to, L.slope, L.intercept, to_q(L.normal), k});
    }
    for (const internal::CurveSwitch& s : c.switches) {
        std::optional<Contact> k;
        if (!s.contact.label.empty()) k = contact_of(s.contact.label, s.contact.feat1, s.contact.feat2);
        curve_.switches.push_back({s.rho1, s.rho2, k});
    }
    curve_.growth = {c.growth.value, c.growth.in_rectangle};
    impl_ = std::move(impl);
}

static void check_rho(const Rational& r, const char* what) {
    if (sgn(r) <= 0) throw InputError(std::string(what) + ": a scaling factor must be > 0");
}

bool Analysis::convex() const { return impl_->convex(); }

const Curve& Analysis::curve() const {
    impl_->convex_only("curve");
    return curve_;
}

Verdict Analysis::verdict(const Rational& rho1, const Rational& rho2) const {
    check_rho(rho1, "rho1");
    check_rho(rho2, "rho2");
    if (!impl_->convex()) return impl_->compound->judge().verdict(canonical_q(rho1), canonical_q(rho2)).verdict;
    return impl_->session->verdict(canonical_q(rho1), canonical_q(rho2));
}

QueryResult Analysis::query(const Rational& rho1, const Rational& rho2) const {
    check_rho(rho1, "rho1");
    check_rho(rho2, "rho2");
    if (!impl_->convex()) return {verdict(rho1, rho2), std::nullopt, std::nullopt};
    // The walk where it proves the curve at ρ1 (as query_json and the command), else the hull model.
    const internal::Session::Certified c = impl_->session->certified_query(rho1, rho2);
    const Model& m = c.model;
    const internal::QueryAnswer& r = c.result;
    QueryResult out{r.verdict, std::nullopt, std::nullopt};
    if (r.plane) out.plane = Plane{to_q(m.lines[r.plane->line].normal), r.plane->c1, r.plane->c2, r.plane->offset};
    if (r.witness) out.common = CommonPoint{r.witness->rho1, r.witness->rho2, r.witness->point};
    return out;
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
    if (!impl_->convex()) return impl_->compound->classify(rho1, rho2, threads);
    const internal::Session::Decider d = impl_->session->decider_for(rho1);
    FastCurve f(d.model, d.curve);
    std::vector<Verdict> out;
    classify_batch(f, rho1, rho2, out, threads);
    return out;
}

PlaneCheck Analysis::check_plane(const Rational& rho1, const Rational& rho2, const Point& normal,
                                 const std::optional<Rational>& offset) const {
    check_rho(rho1, "rho1");
    check_rho(rho2, "rho2");
    const Point n = canonical(normal);
    if (sgn(n[0]) == 0 && sgn(n[1]) == 0 && sgn(n[2]) == 0) throw InputError("check_plane: the normal is zero");
    // Support queries over the points: no hull model (on parts, over every part's points).
    const auto [c1, c2] = impl_->convex() ? internal::plane_extents(impl_->session->points(), n, rho1, rho2)
                                          : impl_->compound->judge().plane_extents(n, rho1, rho2);
    PlaneCheck r;
    r.c1 = c1;
    r.c2 = c2;
    r.separates = r.c1 < r.c2 && (!offset || (r.c1 < *offset && *offset < r.c2));
    return r;
}

std::string Analysis::curve_json() const {
    internal::Session& s = impl_->convex_only("curve_json");
    return dump(internal::curve_json(s.curve_model(), s.curve()));
}

std::string Analysis::query_json(const Rational& rho1, const Rational& rho2) const {
    check_rho(rho1, "rho1");
    check_rho(rho2, "rho2");
    if (impl_->convex()) return impl_->session->query_text(rho1, rho2);
    return impl_->compound->verdict_certificate(canonical_q(rho1), canonical_q(rho2));
}

std::string Analysis::partition_json() const {
    return impl_->convex() ? impl_->session->partition_text() : dump(impl_->compound->partition_json());
}

std::string Analysis::region_json() const { return dump(impl_->region().region_json()); }

ClaimReport Analysis::certify_fp(const std::string& claims, const ClaimOptions& options) const {
    long wrong = 0, count = 0;
    std::string certificate;
    std::string* cert = options.certificate ? &certificate : nullptr;
    std::string report =
        impl_->convex()
            ? internal::certify_fp(impl_->session->claim_models(), claims, "claims", options, &wrong, &count, cert)
            : internal::certify_fp(impl_->compound->judge(), claims, "claims", options, &wrong, &count, cert);
    return {std::move(report), count, wrong, std::move(certificate)};
}

namespace {
// A public claim, typed for the rules (claim.hpp), its faults refused with one line naming it.
// parts: the scene of objects made of parts, none for two convex objects.
internal::TypedClaim typed_claim(const Claim& c, size_t i, const internal::ExactScene* parts) {
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
        t.verdict = c.verdict == ClaimedVerdict::Separated     ? internal::Claimed::Separated
                    : c.verdict == ClaimedVerdict::Touching    ? internal::Claimed::Touching
                    : c.verdict == ClaimedVerdict::Overlapping ? internal::Claimed::Overlapping
                                                               : internal::Claimed::Intersecting;
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
        // A contact of one part pair on objects made of parts (the objects' depth is not defined);
        // on two convex objects only the pair (0, 0), or none.
        if (parts && !c.parts)
            throw InputError(where +
                             ".parts: missing: a penetration depth on objects made of parts is a contact of "
                             "one part pair (parts = {part of P1, part of P2})");
        if (c.parts)
            for (size_t k = 0; k < 2; ++k) {
                const size_t n = parts ? std::max<size_t>(1, parts->P[k].parts.size()) : 1;
                if ((*c.parts)[k] < 0 || static_cast<size_t>((*c.parts)[k]) >= n)
                    throw InputError(where + ".parts[" + std::to_string(k) + "]: P" + std::to_string(k + 1) + " has " +
                                     std::to_string(n) + (n == 1 ? " part" : " parts") + " (numbered from 0)");
            }
        if (parts) t.parts = c.parts;
        t.type = ClaimType::Depth;
        t.value = canonical_q(c.value);
        if (c.direction) t.direction = nonzero(*c.direction, "direction");
        break;
    }
    return t;
}

// Its judgement, as the public type has it.
Judgement public_judgement(const internal::TypedClaim& c, const internal::Judged& g,
                           const internal::ExactScene* parts) {
    Judgement j;
    if (parts && g.part1 >= 0 && g.part2 >= 0) {
        j.part1 = g.part1;
        j.part2 = g.part2;
        j.part1_name = internal::part_name(parts->P[0], static_cast<size_t>(g.part1));
        j.part2_name = internal::part_name(parts->P[1], static_cast<size_t>(g.part2));
    }
    j.right = g.right;
    j.value_right = g.value_right;
    j.closest_right = g.closest_right;
    j.direction_right = g.direction_right;
    if (g.exact_squared) {
        j.exact_squared = *g.exact_squared;
        j.exact = sqrt_minus_rn(*g.exact_squared, Q(0));
        // |value − exact| / exact, MPFR-rounded; relative to an exact 0: 0 for a claimed 0, else inf.
        j.rel_error = sgn(*g.exact_squared) ? relative_sqrt_error_rn(*g.exact_squared, c.value)
                      : sgn(c.value) == 0   ? 0.0
                                            : INFINITY;
    }
    if (c.type == internal::ClaimType::Verdict) j.exact_verdict = g.exact_verdict;
    if (!c.no_answer.empty()) j.reason = c.no_answer + ": " + c.no_answer_reason;
    return j;
}

// Typed claims through typed rules: no JSON unless a certificate is asked for.
template <class Rules, class Certificate>
Judgements judge_all(Rules& rules, const std::vector<Claim>& claims, const ClaimOptions& options,
                     const internal::ExactScene* parts, Certificate&& certificate) {
    std::vector<internal::TypedClaim> typed;
    typed.reserve(claims.size());
    for (size_t i = 0; i < claims.size(); ++i) typed.push_back(typed_claim(claims[i], i, parts));
    Judgements out;
    out.items.reserve(claims.size());
    Json entries = Json::array();
    for (size_t i = 0; i < typed.size(); ++i) {
        internal::Proof p;
        internal::Judged g;
        try {
            g = rules.judge(typed[i], options.certificate ? &p : nullptr);
        } catch (const InputError& e) {  // a limit met while judging it (a pose's moved points)
            if (!typed[i].posed()) throw;
            throw InputError("certify: claims[" + std::to_string(i) + "]." + e.what());
        }
        out.wrong += !g.right;
        out.items.push_back(public_judgement(typed[i], g, parts));
        if (options.certificate)
            entries.push_back(
                Json{{"index", i}, {"claim", std::move(p.claim)}, {"right", g.right}, {"proof", std::move(p.proof)}});
    }
    if (options.certificate) out.certificate = certificate(std::move(entries));
    return out;
}

void check_tolerance(const ClaimOptions& options) {
    if (sgn(options.tolerance) < 0)
        throw InputError("tolerance: must be >= 0 (got " + to_exact_string(options.tolerance) + ")");
    if (sgn(options.abs_tolerance) < 0)
        throw InputError("abs_tolerance: must be >= 0 (got " + to_exact_string(options.abs_tolerance) + ")");
}
}  // namespace

Judgements Analysis::certify(const std::vector<Claim>& claims, const ClaimOptions& options) const {
    check_tolerance(options);
    if (!impl_->convex()) {
        internal::CompoundJudge& judge = impl_->compound->judge();
        internal::PartsRules rules(judge, {options.tolerance, options.abs_tolerance});
        return judge_all(rules, claims, options, &judge.scene(), [&](Json entries) {
            return internal::compound_judgements_text(judge.scene(), options.tolerance, options.abs_tolerance,
                                                      std::move(entries));
        });
    }
    const internal::ClaimModels models = impl_->session->claim_models();
    internal::ConvexRules rules(models, {options.tolerance, options.abs_tolerance});
    return judge_all(rules, claims, options, nullptr, [&](Json entries) {
        return internal::judgements_text(models.document(), options.tolerance, options.abs_tolerance,
                                         std::move(entries));
    });
}

GoldenData Analysis::golden(const GoldenOptions& options) const {
    const internal::GoldenPoints points{options.verticals, options.offsets};
    internal::GoldenAnswers g;
    if (!impl_->convex()) {  // the region document, with queries where the meeting set ends
        internal::CompoundSession& cs = *impl_->compound;
        g = internal::golden_answers_parts(cs.region(true), cs.judge(), cs.region_json(), points);
    } else {
        internal::Session& s = impl_->convex_only("golden");
        const internal::ClaimModels models = s.claim_models();
        g = internal::golden_answers(impl_->scene.d_->sc(), s.curve_model(), s.curve(), models, points);
    }
    g.curve["queries"] = std::move(g.queries);
    return {dump(g.curve), std::move(g.csv), std::move(g.rational_csv)};
}

}  // namespace scalecert
