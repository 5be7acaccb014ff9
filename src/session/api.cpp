// The public API (include/scalecert/scalecert.hpp) over the internal stages.
#include "scalecert/scalecert.hpp"
#include "session/scene_access.hpp"
#include "session/compound_session.hpp"
#include "session/session.hpp"

#include "certify/certificate.hpp"
#include "certify/claims.hpp"
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


}  // namespace

Scene::Scene(std::vector<Point> p1, std::vector<Point> p2, Interval i1, Interval i2, std::optional<Point> seed1,
             std::optional<Point> seed2) {
    internal::ExactScene sc;
    std::vector<Point>* pts[2] = {&p1, &p2};
    const std::optional<Point>* seeds[2] = {&seed1, &seed2};
    const Interval* ranges[2] = {&i1, &i2};
    for (int i = 0; i < 2; ++i) {
        for (Point& v : *pts[i]) v = canonical(std::move(v));
        sc.P[i].points = std::move(*pts[i]);
        seed_and_range(sc, i, *seeds[i], *ranges[i]);
    }
    finish_scene(sc, "scene");
    d_ = SceneAccess::validated(std::move(sc), "scene");
}

struct Scene::Data {
    internal::ExactScene sc;
    std::string name;  // prefixes the hull model's errors
    // The points as machine integers, for the scan path: large scenes only, when they fit.
    std::shared_ptr<const internal::CompactScene> compact;
    std::once_flag once;
    std::shared_ptr<const HullModel> model;
    const std::shared_ptr<const HullModel>& hull() {
        std::call_once(once, [this] { model = std::make_shared<const HullModel>(build_model(sc, name)); });
        return model;
    }
};

std::shared_ptr<Scene::Data> SceneAccess::validated(internal::ExactScene sc, const std::string& name) {
    auto d = std::make_shared<Scene::Data>();
    d->sc = std::move(sc);
    d->name = name;
    if (internal::walk_by_default(d->sc.P[0].points.size(), d->sc.P[1].points.size()))
        if (auto cs = internal::compact_scene(d->sc)) d->compact = std::make_shared<const internal::CompactScene>(std::move(*cs));
    if (!d->compact || !internal::scan_seeds_proved(*d->compact)) d->hull();
    return d;
}

std::shared_ptr<const HullModel> SceneAccess::hull_model(const Scene& s) { return s.d_->hull(); }

Scene Scene::load(const std::string& path) { return Scene(SceneAccess::validated(load_scene(path), path)); }

Scene Scene::from_meshes(const std::string& p1_path, const std::string& p2_path, Interval i1, Interval i2) {
    return Scene(read_mesh(p1_path), read_mesh(p2_path), std::move(i1), std::move(i2));
}

const std::vector<Point>& Scene::points(int i) const { return d_->sc.P[i & 1].points; }
const Point& Scene::seed(int i) const { return d_->sc.P[i & 1].seed; }
Interval Scene::range(int i) const { return {d_->sc.lo[i & 1], d_->sc.hi[i & 1]}; }
std::string Scene::json() const { return dump(scene_json(d_->sc)); }

struct Analysis::Impl {
    Scene scene;
    // Calls on one Analysis from several threads at once are not supported (scalecert.hpp), so
    // the session may build its models lazily behind the const interface.
    mutable internal::Session session;
    explicit Impl(const Scene& s) : scene(s), session(s.d_->compact, s.d_->name) {
        session.set_hull_source([d = s.d_] { return d->hull(); });
    }
};

Analysis::Analysis(const Scene& scene) {
    auto impl = std::make_shared<Impl>(scene);
    const internal::TouchingCurve& c = impl->session.curve();
    const Model& m = impl->session.curve_model();
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

QueryResult Analysis::query(const Rational& rho1, const Rational& rho2) const {
    check_rho(rho1, "rho1");
    check_rho(rho2, "rho2");
    // The walk where it proves the curve at ρ1 (as query_json and the command), else the hull model.
    const internal::Session::Certified c = impl_->session.certified_query(rho1, rho2);
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
        throw InputError("classify: " + std::to_string(rho1.size()) + " values of rho1 but " + std::to_string(rho2.size()) + " of rho2");
    for (size_t i = 0; i < rho1.size(); ++i)
        if (!(std::isfinite(rho1[i]) && std::isfinite(rho2[i]) && rho1[i] > 0 && rho2[i] > 0))
            throw InputError("classify: pair " + std::to_string(i) + " (numbered from 0): two finite numbers > 0 are required");
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    const internal::Session::Decider d = impl_->session.decider_for(rho1);
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
    const auto [c1, c2] = internal::plane_extents(impl_->session.points(), n, rho1, rho2);  // support queries: no hull model
    PlaneCheck r;
    r.c1 = c1;
    r.c2 = c2;
    r.separates = r.c1 < r.c2 && (!offset || (r.c1 < *offset && *offset < r.c2));
    return r;
}

std::string Analysis::curve_json() const {
    return dump(internal::curve_json(impl_->session.curve_model(), impl_->session.curve()));
}

std::string Analysis::query_json(const Rational& rho1, const Rational& rho2) const {
    check_rho(rho1, "rho1");
    check_rho(rho2, "rho2");
    return impl_->session.query_text(rho1, rho2);
}

std::string Analysis::partition_json() const { return impl_->session.partition_text(); }

ClaimReport Analysis::certify_fp(const std::string& claims, const ClaimOptions& options) const {
    long wrong = 0, count = 0;
    std::string certificate;
    std::string report = internal::certify_fp(impl_->session.claim_models(), claims, "claims", options, &wrong, &count,
                                              options.certificate ? &certificate : nullptr);
    return {std::move(report), count, wrong, std::move(certificate)};
}

Judgements Analysis::certify(const std::vector<Claim>& claims, const ClaimOptions& options) const {
    // The claims as scalecert-claims-1 with every number an exact string, judged by the one set of
    // rules (certify/claims.cpp); the report read back into types.
    if (claims.empty()) throw InputError("certify: no claims");
    Json list = Json::array();
    auto ex = [](const Rational& q) { return to_exact_string(q); };
    auto pt = [&](const Point& p) { return Json::array({ex(p[0]), ex(p[1]), ex(p[2])}); };
    for (const Claim& c : claims) {
        Json j{{"rho1", ex(c.rho1)}, {"rho2", ex(c.rho2)}};
        switch (c.kind) {
        case ClaimKind::Verdict:
            j["kind"] = "verdict";
            j["verdict"] = verdict_name(c.verdict);
            break;
        case ClaimKind::SeparatingPlane:
            j["kind"] = "separating_plane";
            j["normal"] = pt(c.normal);
            if (c.offset) j["offset"] = ex(*c.offset);
            break;
        case ClaimKind::WitnessPoint:
            j["kind"] = "witness_point";
            j["point"] = pt(c.point);
            break;
        case ClaimKind::Distance:
            j["kind"] = "distance";
            j["value"] = ex(c.value);
            if (c.closest) j["closest"] = Json::array({pt((*c.closest)[0]), pt((*c.closest)[1])});
            break;
        case ClaimKind::PenetrationDepth:
            j["kind"] = "penetration_depth";
            j["value"] = ex(c.value);
            if (c.direction) j["direction"] = pt(*c.direction);
            break;
        }
        list.push_back(std::move(j));
    }
    ClaimOptions opt = options;
    opt.json = true;
    long wrong = 0;
    Judgements out;
    const std::string report = internal::certify_fp(impl_->session.claim_models(), dump(Json{{"format", "scalecert-claims-1"}, {"claims", list}}),
                                                    "claims", opt, &wrong, nullptr, options.certificate ? &out.certificate : nullptr);
    out.wrong = wrong;
    const Json r = Json::parse(report);
    auto flag = [](const Json& o, const char* k) { return o.contains(k) ? std::optional<bool>(o[k].get<bool>()) : std::nullopt; };
    for (const Json& o : r["claims"]) {
        Judgement g;
        g.right = o["right"].get<bool>();
        g.value_right = flag(o, "value_right");
        g.closest_right = flag(o, "closest_right");
        g.direction_right = flag(o, "direction_right");
        if (o.contains("exact_squared")) {
            g.exact_squared = parse_exact(o["exact_squared"].get<std::string>());
            g.exact = sqrt_minus_rn(*g.exact_squared, Q(0));
            // (null: beyond the doubles, or relative to 0 — then 0 only for an exact 0.)
            const Json &rel = o["rel_error_double"], &abs_e = o["abs_error_double"];
            g.rel_error = !rel.is_null() ? rel.get<double>() : (!abs_e.is_null() && abs_e.get<double>() == 0 ? 0.0 : INFINITY);
        }
        if (o["kind"] == "verdict") {
            const std::string e = o["exact"].get<std::string>();
            g.exact_verdict = e == "separated" ? Verdict::Separated : e == "touching" ? Verdict::Touching : Verdict::Overlapping;
        }
        out.items.push_back(std::move(g));
    }
    return out;
}

GoldenData Analysis::golden() const {
    internal::GoldenAnswers g =
        internal::golden_answers(impl_->scene.d_->sc, impl_->session.hull(), impl_->session.hull_curve());
    g.curve["queries"] = std::move(g.queries);
    return {dump(g.curve), std::move(g.csv)};
}

struct Region::Impl {
    internal::CompoundSession session;
};

Region::Region(std::vector<std::vector<Point>> parts1, std::vector<std::vector<Point>> parts2, Interval i1, Interval i2,
               std::optional<Point> seed1, std::optional<Point> seed2) {
    internal::ExactScene sc;
    std::vector<std::vector<Point>>* parts[2] = {&parts1, &parts2};
    const std::optional<Point>* seeds[2] = {&seed1, &seed2};
    const Interval* ranges[2] = {&i1, &i2};
    for (int i = 0; i < 2; ++i) {
        const std::string name = i ? "P2" : "P1";
        if (parts[i]->empty()) throw InputError("region: " + name + ": expected a nonempty list of parts");
        if (parts[i]->size() > internal::kMaxParts)
            throw InputError("region: " + name + ": more than " + std::to_string(internal::kMaxParts) + " parts (the limit)");
        for (std::vector<Point>& part : *parts[i]) {
            for (Point& v : part) v = canonical(std::move(v));
            if (sc.P[i].points.size() + part.size() > internal::kMaxPoints)
                throw InputError("region: " + name + ": more than " + std::to_string(internal::kMaxPoints) + " points in all its parts (the limit)");
            sc.P[i].points.insert(sc.P[i].points.end(), part.begin(), part.end());
            sc.P[i].parts.push_back(std::move(part));
        }
        seed_and_range(sc, i, *seeds[i], *ranges[i]);
    }
    finish_scene(sc, "region");
    impl_ = std::make_shared<Impl>(Impl{internal::CompoundSession(std::move(sc), "region")});
}

Region Region::load(const std::string& path) {
    internal::ReadOptions opt;
    opt.allow_parts = true;
    return Region(std::make_shared<Impl>(Impl{internal::CompoundSession(load_scene(path, opt), path)}));
}

Region Region::from_meshes(const std::string& p1_path, const std::string& p2_path, Interval i1, Interval i2, bool parts_from_groups) {
    internal::ReadOptions opt;
    opt.allow_parts = true;
    opt.parts_from_groups = parts_from_groups;
    internal::ExactScene sc;
    const std::string* paths[2] = {&p1_path, &p2_path};
    const Interval* ranges[2] = {&i1, &i2};
    for (int i = 0; i < 2; ++i) {
        read_mesh_object(*paths[i], opt, sc.P[i]);
        seed_and_range(sc, i, std::nullopt, *ranges[i]);
    }
    finish_scene(sc, "region");
    return Region(std::make_shared<Impl>(Impl{internal::CompoundSession(std::move(sc), p1_path + " and " + p2_path)}));
}

Verdict Region::verdict(const Rational& rho1, const Rational& rho2) const {
    const std::string v = impl_->session.verdict(rho1, rho2).verdict;
    return v == "separated" ? Verdict::Separated : v == "touching" ? Verdict::Touching : Verdict::Overlapping;
}

std::vector<Verdict> Region::classify(const std::vector<double>& rho1, const std::vector<double>& rho2, unsigned threads) const {
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    return verdicts_of(impl_->session.classify(rho1, rho2, threads));
}

std::string Region::region_json() const { return dump(impl_->session.region_json()); }
std::string Region::partition_json() const { return dump(impl_->session.partition_json()); }

ClaimReport Region::certify_fp(const std::string& claims, const ClaimOptions& options) const {
    long wrong = 0, count = 0;
    std::string certificate;
    std::string report = internal::certify_fp(impl_->session.judge(), claims, "claims", options, &wrong, &count,
                                              options.certificate ? &certificate : nullptr);
    return {std::move(report), count, wrong, std::move(certificate)};
}

}  // namespace scalecert
