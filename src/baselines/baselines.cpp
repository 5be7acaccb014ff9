#include "baselines/baselines.hpp"

#include <ccd/ccd.h>

#include <algorithm>
#include <cmath>

namespace scalecert::internal::fp {

FpScene to_fp(const ExactScene& s) {
    FpScene f;
    for (int i = 0; i < 2; ++i) {
        for (const Vec3q& v : s.P[i].points)
            f.P[i].pts.push_back({to_double_rn(v[0]), to_double_rn(v[1]), to_double_rn(v[2])});
        f.P[i].seed = {to_double_rn(s.P[i].seed[0]), to_double_rn(s.P[i].seed[1]), to_double_rn(s.P[i].seed[2])};
        f.lo[i] = to_double_rn(s.lo[i]);
        f.hi[i] = to_double_rn(s.hi[i]);
    }
    return f;
}

namespace {

// A scaled polytope as libccd sees it: s + ρ(v − s).
struct Scaled {
    const Polytope* p;
    double rho;
};

void support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
    const Scaled& s = *static_cast<const Scaled*>(obj);
    const D3& c = s.p->seed;
    double best = -INFINITY;
    const D3* arg = &s.p->pts[0];
    for (const D3& v : s.p->pts) {
        double d = dir->v[0] * v[0] + dir->v[1] * v[1] + dir->v[2] * v[2];
        if (d > best) {
            best = d;
            arg = &v;
        }
    }
    for (int k = 0; k < 3; ++k) out->v[k] = c[k] + s.rho * ((*arg)[k] - c[k]);
}

void center(const void* obj, ccd_vec3_t* out) {
    const Scaled& s = *static_cast<const Scaled*>(obj);
    for (int k = 0; k < 3; ++k) out->v[k] = s.p->seed[k];
}

// Both polytopes through the same support and centre functions, with the audit's libccd settings.
ccd_t ccd_settings(const MethodSettings& s) {
    ccd_t ccd;
    CCD_INIT(&ccd);
    ccd.max_iterations = s.ccd_max_iterations;
    ccd.epa_tolerance = s.ccd_epa_tolerance;
    ccd.mpr_tolerance = s.ccd_mpr_tolerance;
    ccd.support1 = support;
    ccd.support2 = support;
    ccd.center1 = center;
    ccd.center2 = center;
    return ccd;
}

class Libccd : public Method {
  public:
    Libccd(const FpScene& s, bool mpr) : s_(s), mpr_(mpr) {}
    std::string name() const override { return mpr_ ? "libccd-mpr" : "libccd-gjk"; }
    int classify(double r1, double r2) const override {
        Scaled a{&s_.P[0], r1}, b{&s_.P[1], r2};
        const ccd_t ccd = ccd_settings(s_.settings);
        int hit = mpr_ ? ccdMPRIntersect(&a, &b, &ccd) : ccdGJKIntersect(&a, &b, &ccd);
        return hit ? -1 : 1;
    }
    // libccd gives penetration only (GJK+EPA or MPR): obj2 translated by depth along dir touches.
    std::optional<Measure> measure(double r1, double r2, bool separated) const override {
        if (separated) return std::nullopt;
        Scaled a{&s_.P[0], r1}, b{&s_.P[1], r2};
        const ccd_t ccd = ccd_settings(s_.settings);
        ccd_real_t depth = 0;
        ccd_vec3_t dir, pos;
        const int r = mpr_ ? ccdMPRPenetration(&a, &b, &ccd, &depth, &dir, &pos)
                           : ccdGJKPenetration(&a, &b, &ccd, &depth, &dir, &pos);
        if (r != 0) return std::nullopt;
        Measure m;
        m.depth = true;
        m.value = depth;
        m.direction = D3{dir.v[0], dir.v[1], dir.v[2]};
        return m;
    }

  private:
    FpScene s_;
    bool mpr_;
};

class DoubleEnvelope : public Method {
  public:
    DoubleEnvelope(const Model& m, const FpScene& s) {
        const D3 d{s.P[1].seed[0] - s.P[0].seed[0], s.P[1].seed[1] - s.P[0].seed[1], s.P[1].seed[2] - s.P[0].seed[2]};
        for (const ContactLine& L : m.lines) {
            D3 n{L.normal[0].get_d(), L.normal[1].get_d(), L.normal[2].get_d()};
            double h1 = -INFINITY, h2 = -INFINITY;
            for (const D3& v : s.P[0].pts)
                h1 = std::max(h1, n[0] * (v[0] - s.P[0].seed[0]) + n[1] * (v[1] - s.P[0].seed[1]) +
                                      n[2] * (v[2] - s.P[0].seed[2]));
            for (const D3& w : s.P[1].pts)
                h2 = std::max(h2, -(n[0] * (w[0] - s.P[1].seed[0]) + n[1] * (w[1] - s.P[1].seed[1]) +
                                    n[2] * (w[2] - s.P[1].seed[2])));
            nd_.push_back(n[0] * d[0] + n[1] * d[1] + n[2] * d[2]);
            h1_.push_back(h1);
            h2_.push_back(h2);
        }
    }
    std::string name() const override { return "double-envelope"; }
    int classify(double r1, double r2) const override {
        double best = -INFINITY;
        for (size_t i = 0; i < nd_.size(); ++i) best = std::max(best, nd_[i] - r1 * h1_[i] - r2 * h2_[i]);
        return best > 0 ? 1 : best == 0 ? 0 : -1;
    }

  private:
    std::vector<double> nd_, h1_, h2_;
};

}  // namespace

std::unique_ptr<Method> make_libccd_gjk(const FpScene& s) { return std::make_unique<Libccd>(s, false); }
std::unique_ptr<Method> make_libccd_mpr(const FpScene& s) { return std::make_unique<Libccd>(s, true); }
std::unique_ptr<Method> make_double_envelope(const Model& m, const FpScene& s) {
    return std::make_unique<DoubleEnvelope>(m, s);
}

namespace {
// An object with a radius as libccd sees it: its scaled hull's support point, plus ρr along the
// direction asked, normalised (the support of the hull ⊕ the ball of radius ρr).
struct RoundedScaled {
    const RoundedFp::Object* o;
    double rho;
};

void rounded_support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
    const RoundedScaled& s = *static_cast<const RoundedScaled*>(obj);
    const D3& c = s.o->seed;
    double best = -INFINITY;
    const D3* arg = &s.o->pts[0];
    for (const D3& v : s.o->pts) {
        const double d = dir->v[0] * v[0] + dir->v[1] * v[1] + dir->v[2] * v[2];
        if (d > best) {
            best = d;
            arg = &v;
        }
    }
    const double len = std::sqrt(dir->v[0] * dir->v[0] + dir->v[1] * dir->v[1] + dir->v[2] * dir->v[2]);
    const double m = len > 0 ? s.rho * s.o->radius / len : 0;
    for (int k = 0; k < 3; ++k) out->v[k] = c[k] + s.rho * ((*arg)[k] - c[k]) + m * dir->v[k];
}

void rounded_center(const void* obj, ccd_vec3_t* out) {
    const RoundedScaled& s = *static_cast<const RoundedScaled*>(obj);
    for (int k = 0; k < 3; ++k) out->v[k] = s.o->seed[k];
}

class RoundedLibccd : public Method {
  public:
    RoundedLibccd(const RoundedFp& s, bool mpr) : s_(s), mpr_(mpr) {}
    std::string name() const override { return mpr_ ? "libccd-mpr" : "libccd-gjk"; }
    int classify(double r1, double r2) const override {
        RoundedScaled a{&s_.P[0], r1}, b{&s_.P[1], r2};
        ccd_t ccd = ccd_settings(s_.settings);
        ccd.support1 = ccd.support2 = rounded_support;
        ccd.center1 = ccd.center2 = rounded_center;
        const int hit = mpr_ ? ccdMPRIntersect(&a, &b, &ccd) : ccdGJKIntersect(&a, &b, &ccd);
        return hit ? -1 : 1;
    }

  private:
    RoundedFp s_;
    bool mpr_;
};
}  // namespace

std::unique_ptr<Method> make_rounded_libccd(const RoundedFp& s, bool mpr) {
    return std::make_unique<RoundedLibccd>(s, mpr);
}

std::string rounded_fcl_why_not(const RoundedFp& s) {
    for (int i = 0; i < 2; ++i) {
        const RoundedFp::Object& o = s.P[i];
        if (o.shape != RoundedFp::Shape::Hull || !o.rounded) continue;
        return std::string(
                   "not applicable: FCL has no convex shape with a radius (fcl::Convex has no margin, and "
                   "FCL no Minkowski sum of shapes), and ") +
               (i == 0 ? "P1" : "P2") + " is the hull of " + std::to_string(o.pts.size()) +
               " points with a radius, neither a sphere nor a capsule";
    }
    return "";
}

namespace {
using Factory = std::unique_ptr<Method> (*)(const Model&, const FpScene&);
// Every method by name: make_method and method_names read the same table.
const std::vector<std::pair<std::string, Factory>>& methods() {
    static const std::vector<std::pair<std::string, Factory>> table{
        {"libccd-gjk", [](const Model&, const FpScene& s) { return make_libccd_gjk(s); }},
        {"libccd-mpr", [](const Model&, const FpScene& s) { return make_libccd_mpr(s); }},
        {"double-envelope", [](const Model& m, const FpScene& s) { return make_double_envelope(m, s); }},
        {"paper-tritri", [](const Model& m, const FpScene& s) { return make_paper_tritri(m, s); }},
        {"fcl-gjk-libccd", [](const Model& m, const FpScene& s) { return make_fcl(m, s, true); }},
        {"fcl-gjk-indep", [](const Model& m, const FpScene& s) { return make_fcl(m, s, false); }},
        {"bullet-gjk-epa", [](const Model&, const FpScene& s) { return make_bullet(s); }},
    };
    return table;
}
}  // namespace

namespace {
// libccd's GJK on every part pair (each part scaled about its object's seed), the first that meets
// ends the loop: what a program without a broad phase does.
class LibccdParts : public Method {
  public:
    explicit LibccdParts(const CompoundFp& s) : settings_(s.settings) {
        for (int i = 0; i < 2; ++i)
            for (const CompoundFp::Part& p : s.parts[i]) parts_[i].push_back(Polytope{p.pts, s.seed[i]});
    }
    std::string name() const override { return "libccd-gjk-parts"; }
    int classify(double r1, double r2) const override {
        const ccd_t ccd = ccd_settings(settings_);
        for (const Polytope& A : parts_[0])
            for (const Polytope& B : parts_[1]) {
                Scaled a{&A, r1}, b{&B, r2};
                if (ccdGJKIntersect(&a, &b, &ccd)) return -1;
            }
        return 1;
    }

  private:
    MethodSettings settings_;
    std::vector<Polytope> parts_[2];
};
}  // namespace

// The settings each method's calls read, each marked by whether its verdicts read it or only its
// distances and depths: libccd's GJK test its iteration limit, its EPA (the depths) the EPA
// tolerance; its MPR test the MPR tolerance, its depth search the iteration limit too; FCL's
// collide the GJK tolerance, its distance() the distance tolerance; Bullet's shapes their margin;
// the user's program its time limit.
std::vector<std::pair<std::string, double>> settings_of(const std::string& method, const MethodSettings& s,
                                                        bool measures) {
    std::vector<std::pair<std::string, double>> out;
    auto read = [&](const char* option, double value, bool by_verdicts) {
        if (by_verdicts || measures) out.push_back({option, value});
    };
    const double iterations = static_cast<double>(s.ccd_max_iterations);
    if (method == "libccd-gjk" || method == "libccd-gjk-parts") {
        read("ccd-max-iterations", iterations, true);
        if (method == "libccd-gjk") read("ccd-epa-tolerance", s.ccd_epa_tolerance, false);
    } else if (method == "libccd-mpr") {
        read("ccd-max-iterations", iterations, false);
        read("ccd-mpr-tolerance", s.ccd_mpr_tolerance, true);
    } else if (method.rfind("fcl-", 0) == 0) {
        read("fcl-gjk-tolerance", s.fcl_gjk_tolerance, true);
        read("fcl-distance-tolerance", s.fcl_distance_tolerance, false);
    } else if (method.rfind("bullet-", 0) == 0) {
        read("bullet-margin", s.bullet_margin, true);
    } else if (method.rfind("command=", 0) == 0) {
        read("command-timeout", s.command_timeout, true);
    }
    return out;
}

std::unique_ptr<Method> make_compound_method(const std::string& name, const CompoundFp& s) {
    if (name == "bullet-compound") return make_fcl_bullet_compound(s, 0);
    if (name == "fcl-compound-libccd") return make_fcl_bullet_compound(s, 1);
    if (name == "fcl-compound-indep") return make_fcl_bullet_compound(s, 2);
    if (name == "libccd-gjk-parts") return std::make_unique<LibccdParts>(s);
    return nullptr;
}

std::vector<std::string> compound_method_names() {
    return {"bullet-compound", "fcl-compound-libccd", "fcl-compound-indep", "libccd-gjk-parts"};
}

std::unique_ptr<Method> make_method(const std::string& name, const Model& m, const FpScene& s) {
    for (const auto& [n, make] : methods())
        if (n == name) return make(m, s);
    return nullptr;
}

std::vector<std::string> method_names() {
    std::vector<std::string> out;
    for (const auto& entry : methods()) out.push_back(entry.first);
    return out;
}

GridCurve grid_search(const Method& method, const FpScene& s, int n, int bisections, int repeats, bool exhaustive) {
    GridCurve g;
    auto at = [](double lo, double hi, int i, int n) { return n == 1 ? lo : lo + (hi - lo) * i / (n - 1); };
    for (int i = 0; i < n; ++i) {
        double x = at(s.lo[0], s.hi[0], i, n);
        int prev = 0;
        bool found = false;
        for (int j = 0; j < n; ++j) {
            double y = at(s.lo[1], s.hi[1], j, n);
            int c = method.classify(x, y);
            ++g.classifications;
            if (!found && j > 0 && prev > 0 && c <= 0) {
                // The touching ρ2 lies in (y_prev, y]: bisection, repeated and averaged.
                double y0 = at(s.lo[1], s.hi[1], j - 1, n), sum = 0;
                for (int r = 0; r < repeats; ++r) {
                    double lo = y0, hi = y;
                    double jitter = (hi - lo) * 1e-3 * r;  // the paper averages several runs
                    lo += jitter;
                    for (int b = 0; b < bisections; ++b) {
                        double mid = 0.5 * (lo + hi);
                        ++g.classifications;
                        (method.classify(x, mid) > 0 ? lo : hi) = mid;
                    }
                    sum += bisections ? 0.5 * (lo + hi) : y;
                }
                g.rho1.push_back(x);
                g.rho2.push_back(sum / repeats);
                found = true;
                if (!exhaustive) break;
            }
            prev = c;
        }
    }
    return g;
}

}  // namespace scalecert::internal::fp
