#include "baselines/audit.hpp"

#include "baselines/guest.hpp"
#include "certify/claim.hpp"

#include "certify/certificate.hpp"
#include "certify/region_certificate.hpp"
#include "certify/rounded.hpp"
#include "curve/closed_forms.hpp"
#include "geometry/measures.hpp"
#include "io/files.hpp"
#include "io/strict_json.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace scalecert::internal {

// ---- audits -----------------------------------------------------------------------------------

namespace {
// Matches the exact switch points inside the rectangle with the junctions found: missed when no
// junction is within two grid cells; merged when two switch points share their nearest junction.
void match_junctions(const TouchingCurve& c, const ExactScene& s, const std::vector<double>& found, double cell,
                     AuditRow& r) {
    r.junctions_found = static_cast<int>(found.size());
    std::vector<int> claimed(found.size(), 0);
    for (const CurveSwitch& sp : c.switches) {
        if (sp.rho2 < s.lo[1] || sp.rho2 > s.hi[1]) continue;
        double x = to_double_rn(sp.rho1), best = INFINITY;
        size_t arg = 0;
        for (size_t k = 0; k < found.size(); ++k)
            if (std::fabs(found[k] - x) < best) best = std::fabs(found[k] - x), arg = k;
        if (found.empty() || !(best <= 2 * cell)) {
            ++r.junctions_missed;
            continue;
        }  // (a NaN cell misses too)
        r.max_junction_error = std::max(r.max_junction_error, best);
        if (claimed[arg]++) ++r.junctions_merged;
    }
}
}  // namespace

std::optional<double> relative_error(const Q& squared, double value) {
    const double root = std::sqrt(to_double_rn(squared));
    if (!(root > 0) || !std::isfinite(root)) return std::nullopt;
    return std::fabs(sqrt_minus_rn(squared, exact_from_double(value))) / root;
}

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const size_t h = v.size() / 2;
    return v.size() % 2 ? v[h] : (v[h - 1] + v[h]) / 2;
}

std::optional<double> direction_excess(const Q& along, const Q& squared, double extent) {
    const double root = std::sqrt(to_double_rn(squared));
    if (!(root >= std::ldexp(extent, -26)) || !(root > 0)) return std::nullopt;
    return (sqrt_minus_rn(along, Q(0)) - root) / root;
}

namespace {

// Exact squared distances and depths at the audit's pairs, computed once for all methods.
struct ExactCache {
    explicit ExactCache(size_t n) : squared(n) {}
    std::vector<std::optional<Q>> squared;
};

// The method's distances and depths where its verdict is right, against the exact ones.
// `verdicts` are the method's own at those pairs.
void measure_errors(const fp::Method& mm, const HullModel& m, const std::vector<double>& r1,
                    const std::vector<double>& r2, const std::vector<Verdict>& exact, const std::vector<int>& verdicts,
                    ExactCache& cache, double tolerance, double extent, AuditRow& row) {
    std::vector<double> dist_err, depth_err;
    std::vector<AuditRow::MeasureFailure> measured;
    for (size_t i = 0; i < r1.size(); ++i) {
        if (exact[i] == Verdict::Touching) continue;
        const bool sep = exact[i] == Verdict::Separated;
        const int v = verdicts[i];
        if ((v > 0) != sep || v == 0) continue;  // wrong verdicts are counted already
        const std::optional<fp::Measure> me = mm.measure(r1[i], r2[i], sep);
        if (!me || me->depth == sep || !std::isfinite(me->value)) continue;
        const Q a = exact_from_double(r1[i]), b = exact_from_double(r2[i]);
        if (!cache.squared[i]) {
            // Proved at floating-point speed (measures.hpp): the slab for a distance, the exact EPA
            // for the depth of an overlapping pair (touching pairs are skipped above).
            if (sep) {
                cache.squared[i] = proved_distance(m, a, b).d.squared;
            } else {
                const std::optional<ProvedDepth> d = proved_depth(m, a, b);
                if (!d) throw std::logic_error("audit: an overlapping pair whose difference does not hold the origin");
                cache.squared[i] = d->squared;
            }
        }
        const Q& E = *cache.squared[i];
        const std::optional<double> err = relative_error(E, me->value);
        if (!err) continue;
        (sep ? dist_err : depth_err).push_back(*err);
        measured.push_back({r1[i], r2[i], !sep, me->value, *err});
        if (me->closest) {
            const auto& cp = *me->closest;
            if (!fp::finite(cp[0]) || !fp::finite(cp[1])) {
                ++row.closest_outside;  // a NaN or infinite point is in no body
            } else {
                const Vec3q p{exact_from_double(cp[0][0]), exact_from_double(cp[0][1]), exact_from_double(cp[0][2])};
                const Vec3q q{exact_from_double(cp[1][0]), exact_from_double(cp[1][1]), exact_from_double(cp[1][2])};
                row.closest_outside += !contains(m, 0, a, p) || !contains(m, 1, b, q);
            }
        }
        if (!me->direction) continue;
        const fp::D3& d = *me->direction;
        if ((d[0] != 0 || d[1] != 0 || d[2] != 0) && std::isfinite(d[0] + d[1] + d[2])) {
            const Vec3q n{exact_from_double(d[0]), exact_from_double(d[1]), exact_from_double(d[2])};
            const Q along = directional_depth_squared(m, n, a, b);
            if (sgn(along) < 0) continue;  // (a plane separating an overlapping pair does not exist)
            if (const std::optional<double> x = direction_excess(along, E, extent))
                row.direction_err_max = std::max(row.direction_err_max, *x);
        }
    }
    row.distances = static_cast<long>(dist_err.size());
    row.depths = static_cast<long>(depth_err.size());
    row.distance_err_median = median(dist_err);
    row.depth_err_median = median(depth_err);
    for (double e : dist_err) row.distance_err_max = std::max(row.distance_err_max, e);
    for (double e : depth_err) row.depth_err_max = std::max(row.depth_err_max, e);
    row.note_measures(std::move(measured), tolerance);
}

// The pairs at relative distances 2^-k from the curve (k = 4, 8, ..., 52), on 15 verticals, above
// and below, rounded to doubles, with the exact verdicts of those doubles: built once per scene.
struct DistancePairs {
    std::vector<int> k;
    std::vector<double> x, y;
    std::vector<Verdict> exact;
};
DistancePairs distance_pairs(const Model& m, const TouchingCurve& c, const ExactScene& s) {
    DistancePairs p;
    for (int k = 4; k <= 52; k += 4)
        for (int j = 1; j < 16; ++j) {
            Q x = s.lo[0] + (s.hi[0] - s.lo[0]) * Q(j, 16);
            x.canonicalize();
            const Q y = c.env.value(m.lines, x);
            if (sgn(y) <= 0) continue;
            for (int sg : {-1, 1}) {
                const double xd = to_double_rn(x), yd = to_double_rn(y + sg * y / Q(Z(1) << k));
                p.k.push_back(k);
                p.x.push_back(xd);
                p.y.push_back(yd);
                p.exact.push_back(query(m, c, exact_from_double(xd), exact_from_double(yd), false).verdict);
            }
        }
    return p;
}

// The method's wrong verdicts on those pairs, per k; exactly touching pairs counted apart.
// (said(i): the method's verdict at near pair i.)
void wrong_by_distance(const std::function<int(size_t)>& said, const DistancePairs& p, AuditRow& row) {
    for (int k = 4; k <= 52; k += 4) row.by_distance.push_back(AuditRow::ByDistance{k});
    for (size_t i = 0; i < p.k.size(); ++i) {
        AuditRow::ByDistance& b = row.by_distance[static_cast<size_t>(p.k[i] / 4 - 1)];
        if (p.exact[i] == Verdict::Touching) {
            ++b.touching;
            continue;
        }
        ++b.pairs;
        b.wrong += AuditRow::wrong(said(i), p.exact[i]);
    }
}

// A JSON value of a program's claims file as a JSON document, as the program wrote it: a number
// that the JSON library writes back otherwise (1e-400, -0, 1e5, NaN, which the strict reader takes
// in claims files) as the string of its text.
Json json_of(const JNode& n) {
    switch (n.kind) {
    case JNode::Null: return nullptr;
    case JNode::Bool: return n.text == "true";
    case JNode::Number: {
        // As a JSON number where that writes back as the program wrote it, else as its text.
        const Json v = Json::parse(n.text, nullptr, false);  // (no exception: discarded when malformed)
        return v.is_number() && v.dump() == n.text ? v : Json(n.text);
    }
    case JNode::String: return n.text;
    case JNode::Array: {
        Json a = Json::array();
        for (const JNode& x : n.items) a.push_back(json_of(x));
        return a;
    }
    case JNode::Object: {
        Json o = Json::object();
        for (size_t i = 0; i < n.keys.size(); ++i) o[n.keys[i]] = json_of(n.items[i]);
        return o;
    }
    }
    return nullptr;
}

// The user's own program as a method (audit --command CMD, docs/audits.md): run once per scene as
// `CMD SCENE.json PAIRS.json CLAIMS.json` in a private temporary folder (guest.hpp), where
// SCENE.json is the scene exactly, PAIRS.json {"format": "scalecert-pairs-1", "pairs": [[rho1,
// rho2], ...]} the doubles the audit asks, and CLAIMS.json what it writes: a claims file
// (scalecert-claims-1) of one verdict claim per pair, in order, at those doubles. Its claims are
// read as certify-fp reads them (a JSON number is the double it spells, a string exact), so a
// pair written as the exact fraction of the double asked is that pair. A claim that does not
// answer its pair (unreadable, of another kind, at another pair or at a pose of its own, or
// missing) is no answer: wrong, with its reason and what the program wrote. A program that fails
// (exit status, signal, timeout) or writes no claims file gives no method: `failed` says why.
class CommandMethod : public fp::Method {
  public:
    CommandMethod(const std::string& command, const ExactScene& s, const std::vector<std::pair<double, double>>& pairs,
                  double timeout)
        : command_(command) {
        const GuestSignals signals;  // from before the folder is made to after it is removed
        const GuestFolder folder;
        const std::string& dir = folder.path();
        auto stop_if_asked = [&] {
            if (const int sig = signals.pending()) GuestSignals::end_by(sig, dir);
        };
        const std::string scene = dir + "/scene.json", asked = dir + "/pairs.json", out = dir + "/claims.json";
        Json pj = Json::array();
        for (const auto& [a, b] : pairs) pj.push_back(Json::array({a, b}));
        std::ofstream(scene) << dump(scene_file_json(s));
        std::ofstream(asked) << dump(Json{{"format", "scalecert-pairs-1"}, {"pairs", std::move(pj)}});
        stop_if_asked();
        const GuestRun run =
            run_guest(command + " " + shell_word(scene) + " " + shell_word(asked) + " " + shell_word(out), timeout);
        if (run.end == GuestRun::Interrupted) GuestSignals::end_by(run.code, dir);  // the program is stopped
        if (!run.ok()) {
            failed = printable(run.why_failed(timeout));
            return;
        }
        if (!std::filesystem::exists(std::filesystem::symlink_status(out))) {
            failed = "it wrote no claims file (CLAIMS.json, its third argument)";
            return;
        }
        JNode doc;
        try {  // (read_regular_file refuses a file that is no regular file, and one past the limit)
            doc = read_claims_root(read_regular_file(out, "claims file", kMaxSceneBytes), "its claims file");
        } catch (const InputError& e) {
            failed = e.what();  // naming the file as the program knows it, not our temporary path
            if (failed.rfind(out, 0) == 0) failed.replace(0, out.size(), "CLAIMS.json");
            failed = printable(failed);  // (a key of the program's own, on one line)
            stop_if_asked();
            return;
        }
        stop_if_asked();
        const std::vector<JNode>& claims = doc.find("claims")->items;
        answers_.resize(pairs.size());
        for (size_t i = 0; i < pairs.size(); ++i) {
            Answer& a = answers_[i];
            if (i >= claims.size()) {
                a.reason = "no claim for this pair (the file has " + std::to_string(claims.size()) + " claims for " +
                           std::to_string(pairs.size()) + " pairs asked)";
                continue;
            }
            a.claim = dump(json_of(claims[i]));
            TypedClaim c;
            try {
                c = read_claim(claims[i], i, "its claims file", Numbers::Double);
            } catch (const InputError& e) {
                a.reason = e.what();
                continue;
            }
            const Q r1 = exact_from_double(pairs[i].first), r2 = exact_from_double(pairs[i].second);
            if (c.type != ClaimType::Verdict)
                a.reason = std::string("a ") + type_name(c.type) + " claim, not a verdict";
            else if (c.rho1 != r1 || c.rho2 != r2)
                a.reason = "at (" + to_exact_string(c.rho1) + ", " + to_exact_string(c.rho2) +
                           "), not at the pair asked (" + to_shortest(pairs[i].first) + ", " +
                           to_shortest(pairs[i].second) + ")";
            else if (c.posed())
                a.reason = std::string("at a pose of its own (") + (c.pose[0] ? "pose1" : "pose2") +
                           "), not at the scene's poses, where the pair is asked";
            else
                a.said = c.verdict == Claimed::Separated     ? AuditRow::kSaidSeparated
                         : c.verdict == Claimed::Touching    ? AuditRow::kSaidTouching
                         : c.verdict == Claimed::Overlapping ? AuditRow::kSaidOverlapping
                                                             : AuditRow::kSaidIntersecting;
        }
        extra_claims = claims.size() > pairs.size() ? static_cast<long>(claims.size() - pairs.size()) : 0;
    }
    std::string failed;     // why the program gave no claims ("" when it did)
    long extra_claims = 0;  // claims past the pairs asked (answers to no question)
    std::string name() const override { return "command (" + command_ + ")"; }
    // The answer to pair i as asked (its claim in the file's place i).
    int said_at(size_t i) const { return answers_.at(i).said; }
    std::pair<std::string, std::string> no_answer_at(size_t i) const {
        return {answers_.at(i).reason, answers_.at(i).claim};
    }
    // (The audit asks it by position, said_at: a pair may be asked twice, each time a question.)
    int classify(double, double) const override {
        throw std::logic_error("audit: the user's program is asked by position");
    }

  private:
    struct Answer {
        int said = AuditRow::kSaidNoAnswer;
        std::string reason, claim;  // why it is no answer; what the program wrote ("" for nothing)
    };
    std::string command_;
    std::vector<Answer> answers_;
};

}  // namespace

// Why no floating-point method can run on a scene whose largest scaled coordinate is `extent`
// ("" when they can): past 2^200, about 1.6·10^60, the methods' squared lengths and their products
// overflow doubles (libccd's EPA then never stops, whatever its tolerance: 10^77 ran for minutes,
// 10^75 stopped; FCL aborts on an assertion at 10^155).
std::string beyond_doubles(double extent) {
    if (extent <= 0x1p200) return "";
    char m[200];
    std::snprintf(m, sizeof m,
                  "the largest scaled coordinate is %.3g, past 2^200: the floating-point methods' squared lengths "
                  "overflow doubles there (libccd's EPA never stops, FCL aborts)",
                  extent);
    return m;
}

// The name a method's row has: the method's own, or "command (CMD)" for the user's program.
std::string row_name(const std::string& meth) {
    const std::string prefix = kCommandMethod;
    return meth.rfind(prefix, 0) == 0 ? "command (" + meth.substr(prefix.size()) + ")" : meth;
}

// A row that says the method did not run on this scene, and why.
AuditRow not_run_row(const std::string& scene, const std::string& meth, const Q& eps, const MethodSettings& settings,
                     bool measures, std::string why) {
    AuditRow r;
    r.scene = scene;
    r.method = row_name(meth);
    r.settings = fp::settings_of(meth, settings, measures);
    r.eps = eps;
    r.not_run = std::move(why);
    return r;
}

namespace {

// The convex audit: the curve, its pairs and every convex method (and the grid).
std::vector<AuditRow> audit_convex(const std::string& name, const ExactScene& s, const Q& eps,
                                   const std::vector<std::string>& methods, const std::vector<int>& grid_ns,
                                   bool by_distance, bool measures, const MethodSettings& settings) {
    using Clock = std::chrono::steady_clock;
    auto t_exact = Clock::now();
    HullModel m = build_model(s);
    TouchingCurve c = build_curve(m);
    double exact_seconds = std::chrono::duration<double>(Clock::now() - t_exact).count();
    fp::FpScene f = fp::to_fp(s);
    f.settings = settings;
    const double extent =
        fp::scaled_extent(f.P[1].pts, f.P[1].seed, f.hi[1], fp::scaled_extent(f.P[0].pts, f.P[0].seed, f.hi[0]));
    const std::string beyond = beyond_doubles(extent);
    // Why a method cannot run on this scene ("" when it can). libccd's EPA (libccd-gjk's depths)
    // loops until its tolerance is met, whatever the iteration limit. Its two stopping tests compare
    // the tolerance with differences of squared lengths (dot products of points whose coordinates
    // reach L), which doubles resolve no finer than one unit in the last place of L², about
    // 2^-52·L²; below that the loop may never end. Measured on two near-sphere scenes: L = 6·10^3
    // stopped at 1e-10 and ran for minutes at 1e-12; L = 6·10^10 stopped at 1e3 and ran for minutes
    // at 1e2 (both near 2^-62·L²). A tolerance below 2^-52·L² is not run, naming the least accepted
    // one (rounded up to two digits).
    auto cannot_run = [&](const std::string& meth) -> std::string {
        if (!beyond.empty()) return beyond;
        if (!measures || meth != "libccd-gjk") return "";
        const double least = std::ldexp(extent * extent, -52);
        if (settings.ccd_epa_tolerance >= least) return "";
        char shown[32];
        for (double up = least;; up = std::nextafter(up * 1.01, HUGE_VAL)) {
            std::snprintf(shown, sizeof shown, "%.2g", up);
            if (std::strtod(shown, nullptr) >= least) break;
        }
        char m[360];
        std::snprintf(m, sizeof m,
                      "--ccd-epa-tolerance %.3g: finer than libccd's EPA resolves where the largest coordinate is "
                      "%.3g (2^-52 of its square), and its loop may never stop; give at least %s, or --no-measures",
                      settings.ccd_epa_tolerance, extent, shown);
        return m;
    };
    // Query pairs (doubles) and their exact verdicts.
    std::vector<double> r1, r2;
    Rng g(12345);
    for (int k = 0; k < 200; ++k) {
        r1.push_back(f.lo[0] + (f.hi[0] - f.lo[0]) * (g.next() >> 11) * 0x1.0p-53);
        r2.push_back(f.lo[1] + (f.hi[1] - f.lo[1]) * (g.next() >> 11) * 0x1.0p-53);
    }
    for (int k = 1; k < 16; ++k) {
        Q x = s.lo[0] + (s.hi[0] - s.lo[0]) * Q(k, 16);
        x.canonicalize();
        Q y = c.env.value(m.lines, x);
        if (sgn(y) <= 0) continue;
        for (int e : {8, 16, 24, 32, 40, 48})
            for (int sg : {-1, 1}) {
                r1.push_back(to_double_rn(x));
                r2.push_back(to_double_rn(y + sg * y / Q(Z(1) << e)));
            }
    }
    std::vector<Verdict> exact(r1.size());
    for (size_t i = 0; i < r1.size(); ++i)
        exact[i] = query(m, c, exact_from_double(r1[i]), exact_from_double(r2[i]), false).verdict;
    std::vector<AuditRow> rows;
    ExactCache cache(r1.size());
    const DistancePairs near = by_distance ? distance_pairs(m, c, s) : DistancePairs{};
    std::vector<int> verdicts(r1.size());
    for (const std::string& meth : methods) {
        if (meth == "grid") continue;
        std::string why = cannot_run(meth);
        std::unique_ptr<fp::Method> mm;
        auto t0 = Clock::now();
        if (!why.empty()) {
        } else if (meth.rfind(kCommandMethod, 0) == 0) {  // the user's program, asked every pair at once
            // Every pair in the order the audit judges them (the random and boundary pairs, then
            // those by distance; a pair asked twice is two questions), each judged by its claim.
            std::vector<std::pair<double, double>> pairs;
            for (size_t i = 0; i < r1.size(); ++i) pairs.push_back({r1[i], r2[i]});
            for (size_t i = 0; i < near.x.size(); ++i) pairs.push_back({near.x[i], near.y[i]});
            const std::string command = meth.substr(std::string(kCommandMethod).size());
            auto cm = std::make_unique<CommandMethod>(command, s, pairs, settings.command_timeout);
            if (!cm->failed.empty())
                why = "--command: " + cm->failed;
            else
                mm = std::move(cm);
        } else {
            mm = fp::make_method(meth, m, f);
            if (!mm) throw InputError("--methods: unknown method " + in_quotes(meth));
            t0 = Clock::now();  // a library's time is its queries'
        }
        if (!why.empty()) {
            rows.push_back(not_run_row(name, meth, eps, settings, measures, why));
            continue;
        }
        AuditRow r;
        r.scene = name;
        r.method = mm->name();
        r.settings = fp::settings_of(meth, settings, measures);  // the option's name (command=CMD)
        r.eps = eps;
        // The user's program answers by position (its claims[i] answers pair i), the libraries by value.
        const auto* cm = dynamic_cast<const CommandMethod*>(mm.get());
        if (cm) r.extra_claims = cm->extra_claims;
        for (size_t i = 0; i < r1.size(); ++i) verdicts[i] = cm ? cm->said_at(i) : mm->classify(r1[i], r2[i]);
        for (size_t i = 0; i < r1.size(); ++i)
            if (verdicts[i] == AuditRow::kSaidNoAnswer) {
                auto [reason, claim] = cm->no_answer_at(i);
                r.count_no_answer(r1[i], r2[i], exact[i], std::move(reason), std::move(claim));
            } else {
                r.count(r1[i], r2[i], verdicts[i], exact[i]);
            }
        // A program's time is its whole run (start-up included) over the pairs it was asked.
        r.seconds_per_query = std::chrono::duration<double>(Clock::now() - t0).count() / static_cast<double>(r1.size());
        if (measures) measure_errors(*mm, m, r1, r2, exact, verdicts, cache, settings.measure_tolerance, extent, r);
        if (by_distance)
            wrong_by_distance(
                [&](size_t i) { return cm ? cm->said_at(r1.size() + i) : mm->classify(near.x[i], near.y[i]); }, near,
                r);
        rows.push_back(r);
    }
    {
        AuditRow r;  // the exact engine itself: no errors by construction, for the speed chart
        r.scene = name;
        r.method = "scalecert (exact)";
        r.eps = eps;
        r.has_curve = true;
        r.seconds_per_curve = exact_seconds;
        for (const CurveSwitch& sp : c.switches) r.exact_junctions += sp.rho2 >= s.lo[1] && sp.rho2 <= s.hi[1];
        r.junctions_found = r.exact_junctions;
        rows.push_back(r);
    }
    if (std::find(methods.begin(), methods.end(), "grid") != methods.end() && !beyond.empty()) {
        for (int n : grid_ns)
            for (const char* g : {"grid+bisection (libccd-gjk)", "grid+analytical (libccd-gjk)"}) {
                AuditRow r = not_run_row(name, "libccd-gjk", eps, settings, false, beyond);
                r.method = g;
                r.has_curve = true;
                r.grid_n = n;
                rows.push_back(r);
            }
    } else if (std::find(methods.begin(), methods.end(), "grid") != methods.end()) {
        auto gjk = fp::make_libccd_gjk(f);
        for (int n : grid_ns) {
            AuditRow r;
            r.scene = name;
            r.method = "grid+bisection (libccd-gjk)";
            r.settings = fp::settings_of("libccd-gjk", settings, false);
            r.eps = eps;
            r.has_curve = true;
            r.grid_n = n;
            auto t0 = Clock::now();
            fp::GridCurve gc = fp::grid_search(*gjk, f, n, 20, 3);
            r.seconds_per_curve = std::chrono::duration<double>(Clock::now() - t0).count();
            // Growth distance: where the sampled polyline crosses ρ1 = ρ2.
            double gexact = to_double_rn(c.growth.value), gest = NAN;
            for (size_t i = 0; i + 1 < gc.rho1.size(); ++i) {
                double a = gc.rho2[i] - gc.rho1[i], b = gc.rho2[i + 1] - gc.rho1[i + 1];
                if (a >= 0 && b <= 0) {
                    gest = gc.rho1[i] + (gc.rho1[i + 1] - gc.rho1[i]) * a / (a - b);
                    break;
                }
            }
            r.growth_error = c.growth.in_rectangle ? std::fabs(gest - gexact) : 0;
            // Junctions: slope changes between consecutive sample segments beyond a tolerance,
            // located by intersecting the neighbouring segments' lines.
            std::vector<double> jx;
            for (size_t i = 0; i + 2 < gc.rho1.size(); ++i) {
                double s1 = (gc.rho2[i + 1] - gc.rho2[i]) / (gc.rho1[i + 1] - gc.rho1[i]);
                double s2 = (gc.rho2[i + 2] - gc.rho2[i + 1]) / (gc.rho1[i + 2] - gc.rho1[i + 1]);
                if (std::fabs(s2 - s1) > 1e-3 * (1 + std::fabs(s1))) {
                    jx.push_back(gc.rho1[i + 1]);
                    ++i;
                }
            }
            double cell = (f.hi[0] - f.lo[0]) / (n - 1);
            for (const CurveSwitch& sp : c.switches) r.exact_junctions += sp.rho2 >= s.lo[1] && sp.rho2 <= s.hi[1];
            match_junctions(c, s, jx, cell, r);
            rows.push_back(r);
            // The same samples with the Appendix's equations (the paper's remedy, Figs. 3-4): at
            // each sample, the contact pair is the largest contact line there (in double); the
            // pieces are runs of samples with one pair, each junction the intersection of the two
            // pairs' closed-form lines.
            AuditRow a = r;
            a.method = "grid+analytical (libccd-gjk)";
            a.settings = fp::settings_of("libccd-gjk", settings, false);
            auto t1 = Clock::now();
            std::vector<size_t> pair;
            for (size_t i = 0; i < gc.rho1.size(); ++i) {
                size_t best = 0;
                double bv = -INFINITY;
                for (size_t k = 0; k < m.lines.size(); ++k) {
                    double v = m.lines[k].slope.get_d() * gc.rho1[i] + m.lines[k].intercept.get_d();
                    if (v > bv) bv = v, best = k;
                }
                pair.push_back(best);
            }
            std::vector<double> ajx;
            for (size_t i = 0; i + 1 < pair.size(); ++i)
                if (pair[i] != pair[i + 1]) {
                    ClosedLine A = closed_form_line(m, m.lines[pair[i]]), B = closed_form_line(m, m.lines[pair[i + 1]]);
                    double aa = A.slope().get_d(), ab = A.intercept().get_d(), ba = B.slope().get_d(),
                           bb = B.intercept().get_d();
                    ajx.push_back((bb - ab) / (aa - ba));
                }
            a.seconds_per_curve = r.seconds_per_curve + std::chrono::duration<double>(Clock::now() - t1).count();
            a.junctions_missed = a.junctions_merged = 0;
            a.max_junction_error = 0;
            match_junctions(c, s, ajx, cell, a);
            rows.push_back(a);
        }
    }
    return rows;
}

// ---- Objects with a radius ----------------------------------------------------------------------

// The objects as the floating-point methods see them (fp::RoundedFp): the nearest doubles, and
// each object's shape decided exactly: its points one point (a sphere), on one line (a capsule
// between the two extreme ones), else a hull; the faces of a hull spanning 3 dimensions.
fp::RoundedFp rounded_fp(const ExactScene& s, const std::string& name, const MethodSettings& settings) {
    const fp::FpScene f = fp::to_fp(s);
    fp::RoundedFp r;
    for (int i = 0; i < 2; ++i) {
        fp::RoundedFp::Object& o = r.P[i];
        const std::vector<Vec3q>& pts = s.P[i].points;
        o.pts = f.P[i].pts;
        o.seed = f.P[i].seed;
        o.radius = to_double_rn(s.P[i].radius);
        o.rounded = sgn(s.P[i].radius) > 0;
        r.lo[i] = f.lo[i];
        r.hi[i] = f.hi[i];
        // The first point unlike pts[0], and whether every point lies on the line through both.
        size_t other = 0;
        for (size_t k = 1; k < pts.size() && !other; ++k)
            if (pts[k] != pts[0]) other = k;
        bool on_line = true;
        const Vec3q d = other ? sub(pts[other], pts[0]) : Vec3q{Q(0), Q(0), Q(0)};
        for (size_t k = 1; k < pts.size() && on_line && other; ++k) {
            const Vec3q c = cross(d, sub(pts[k], pts[0]));
            on_line = sgn(c[0]) == 0 && sgn(c[1]) == 0 && sgn(c[2]) == 0;
        }
        if (!other) {
            o.shape = fp::RoundedFp::Shape::Sphere;
        } else if (on_line) {
            o.shape = fp::RoundedFp::Shape::Capsule;
            size_t lo = 0, hi = 0;
            for (size_t k = 1; k < pts.size(); ++k) {
                if (dot(d, pts[k]) < dot(d, pts[lo])) lo = k;
                if (dot(d, pts[k]) > dot(d, pts[hi])) hi = k;
            }
            o.ends = {static_cast<int>(lo), static_cast<int>(hi)};
        } else {
            bool flat = true;  // every point in the plane of pts[0], pts[other] and a third
            Vec3q n{Q(0), Q(0), Q(0)};
            for (size_t k = 1; k < pts.size() && flat; ++k) {
                const Vec3q c = cross(d, sub(pts[k], pts[0]));
                if (sgn(n[0]) == 0 && sgn(n[1]) == 0 && sgn(n[2]) == 0)
                    n = c;
                else
                    flat = sgn(dot(n, sub(pts[k], pts[0]))) == 0;
            }
            if (!flat)
                for (const Face& face : build_polyhedron(pts, name + ": " + (i ? "P2" : "P1")).faces)
                    o.faces.push_back(face.verts);
        }
    }
    r.settings = settings;
    return r;
}

// The audit of objects with a radius. The exact verdicts are the rounded engine's
// (rounded_verdict on hull_measure, exact at the doubles' values). The pairs: the 200 random
// ones of the convex audit; and, since the touching set is curved, at 15 verticals ρ1 = x spread
// over I1 where it crosses x × I2, bisection on ρ2 with exact verdicts (as rounded_golden) down to
// 2^-60 of I2, or to the touching pair itself, gives y; the pairs (x, y(1 ± 2^-e)) for e = 8, 16, …,
// 48 are judged, and with by_distance those at 2^-k, k = 4, 8, …, 52. The methods: libccd's GJK
// and MPR (support inflated), FCL (spheres, capsules, hulls without a radius; elsewhere not
// applicable), Bullet (margins), and the user's program; the others not applicable, and the grid
// (one row). No distances or depths are compared.
std::vector<AuditRow> audit_rounded(const std::string& name, const ExactScene& s, const Q& eps,
                                    const std::vector<std::string>& methods, bool by_distance,
                                    const MethodSettings& settings) {
    using Clock = std::chrono::steady_clock;
    if (s.made_of_parts()) throw InputError("objects made of parts with a radius are not audited");
    const RoundedPoints S(s, name);
    check_rounded(s, S, name);
    const std::pair<int, Vec3z> span = S.difference_span(S);
    auto exact_at = [&](const Q& a, const Q& b) {
        return rounded_verdict(hull_measure(S, span.first, span.second, a, b), a * s.P[0].radius + b * s.P[1].radius);
    };
    const fp::RoundedFp f = rounded_fp(s, name, settings);
    double extent = 0;
    for (int i = 0; i < 2; ++i)
        extent = std::max(extent, fp::scaled_extent(f.P[i].pts, f.P[i].seed, f.hi[i]) + f.hi[i] * f.P[i].radius);
    const std::string beyond = beyond_doubles(extent);
    std::vector<double> r1, r2;
    Rng g(12345);
    for (int k = 0; k < 200; ++k) {
        r1.push_back(f.lo[0] + (f.hi[0] - f.lo[0]) * (g.next() >> 11) * 0x1.0p-53);
        r2.push_back(f.lo[1] + (f.hi[1] - f.lo[1]) * (g.next() >> 11) * 0x1.0p-53);
    }
    // The touching set on each vertical that crosses it inside I2.
    std::vector<std::pair<Q, Q>> on;
    for (int k = 1; k < 16; ++k) {
        Q x = s.lo[0] + (s.hi[0] - s.lo[0]) * Q(k, 16);
        x.canonicalize();
        if (exact_at(x, s.lo[1]) != Verdict::Separated || exact_at(x, s.hi[1]) == Verdict::Separated) continue;
        Q a = s.lo[1], b = s.hi[1];
        std::optional<Q> hit;
        for (int step = 0; step < 60 && !hit; ++step) {
            Q m = (a + b) / 2;
            m.canonicalize();
            const Verdict v = exact_at(x, m);
            if (v == Verdict::Touching) hit = m;
            (v == Verdict::Separated ? a : b) = m;
        }
        Q y = hit ? *hit : Q((a + b) / 2);
        y.canonicalize();
        on.push_back({x, y});
    }
    for (const auto& [x, y] : on)
        for (int e : {8, 16, 24, 32, 40, 48})
            for (int sg : {-1, 1}) {
                r1.push_back(to_double_rn(x));
                r2.push_back(to_double_rn(y + sg * y / Q(Z(1) << e)));
            }
    std::vector<Verdict> exact(r1.size());
    for (size_t i = 0; i < r1.size(); ++i) exact[i] = exact_at(exact_from_double(r1[i]), exact_from_double(r2[i]));
    DistancePairs near;
    if (by_distance)
        for (int k = 4; k <= 52; k += 4)
            for (const auto& [x, y] : on)
                for (int sg : {-1, 1}) {
                    const double xd = to_double_rn(x), yd = to_double_rn(y + sg * y / Q(Z(1) << k));
                    near.k.push_back(k);
                    near.x.push_back(xd);
                    near.y.push_back(yd);
                    near.exact.push_back(exact_at(exact_from_double(xd), exact_from_double(yd)));
                }
    const std::string fcl_not = fp::rounded_fcl_why_not(f);
    std::vector<AuditRow> rows;
    for (const std::string& meth : methods) {
        if (meth == "grid") {  // one row for every resolution
            rows.push_back(not_run_row(name, "grid", eps, settings, false,
                                       "not applicable: the touching set of objects with a radius is curved, with no "
                                       "junctions or growth distance of a touching curve to compare"));
            continue;
        }
        std::string why = beyond;
        std::unique_ptr<fp::Method> mm;
        auto t0 = Clock::now();
        if (!why.empty()) {
        } else if (meth.rfind(kCommandMethod, 0) == 0) {
            std::vector<std::pair<double, double>> pairs;
            for (size_t i = 0; i < r1.size(); ++i) pairs.push_back({r1[i], r2[i]});
            for (size_t i = 0; i < near.x.size(); ++i) pairs.push_back({near.x[i], near.y[i]});
            const std::string command = meth.substr(std::string(kCommandMethod).size());
            auto cm = std::make_unique<CommandMethod>(command, s, pairs, settings.command_timeout);
            if (!cm->failed.empty())
                why = "--command: " + cm->failed;
            else
                mm = std::move(cm);
        } else if (meth == "libccd-gjk" || meth == "libccd-mpr") {
            mm = fp::make_rounded_libccd(f, meth == "libccd-mpr");
        } else if (meth == "fcl-gjk-libccd" || meth == "fcl-gjk-indep") {
            why = fcl_not;
            if (why.empty()) mm = fp::make_rounded_fcl_bullet(f, meth == "fcl-gjk-libccd" ? 1 : 2);
        } else if (meth == "bullet-gjk-epa") {
            mm = fp::make_rounded_fcl_bullet(f, 0);
        } else if (meth == "double-envelope" || meth == "paper-tritri") {
            why = "not applicable: " + meth + " reads two polyhedra's " +
                  (meth == "double-envelope" ? "contact lines" : "triangulated faces") +
                  ", and objects with a radius are no polyhedra";
        } else {
            const std::vector<std::string> cn = fp::compound_method_names();
            if (std::find(cn.begin(), cn.end(), meth) == cn.end())
                throw InputError("--methods: unknown method " + in_quotes(meth));
            why = "not applicable: " + meth + " audits objects made of parts";
        }
        if (!why.empty()) {
            rows.push_back(not_run_row(name, meth, eps, settings, false, why));
            continue;
        }
        const auto* cm = dynamic_cast<const CommandMethod*>(mm.get());
        if (!cm) t0 = Clock::now();  // a library's time is its queries'; a program's its whole run
        AuditRow r;
        r.scene = name;
        r.method = mm->name();
        r.settings = fp::settings_of(meth, settings, false);
        r.eps = eps;
        if (cm) r.extra_claims = cm->extra_claims;
        for (size_t i = 0; i < r1.size(); ++i) {
            const int v = cm ? cm->said_at(i) : mm->classify(r1[i], r2[i]);
            if (v == AuditRow::kSaidNoAnswer) {
                auto [reason, claim] = cm->no_answer_at(i);
                r.count_no_answer(r1[i], r2[i], exact[i], std::move(reason), std::move(claim));
            } else {
                r.count(r1[i], r2[i], v, exact[i]);
            }
        }
        r.seconds_per_query = std::chrono::duration<double>(Clock::now() - t0).count() / static_cast<double>(r1.size());
        if (by_distance)
            wrong_by_distance(
                [&](size_t i) { return cm ? cm->said_at(r1.size() + i) : mm->classify(near.x[i], near.y[i]); }, near,
                r);
        rows.push_back(r);
    }
    return rows;
}

}  // namespace

std::vector<AuditRow> audit_scene(const std::string& name, const ExactScene& s, const Q& eps,
                                  const std::vector<std::string>& methods, const std::vector<int>& grid_ns,
                                  bool by_distance, bool measures, const MethodSettings& settings) {
    if (s.rounded()) return audit_rounded(name, s, eps, methods, by_distance, settings);
    const std::vector<std::string> cn = fp::compound_method_names();
    std::vector<std::string> convex, compound;
    for (const std::string& m : methods)
        (std::find(cn.begin(), cn.end(), m) != cn.end() ? compound : convex).push_back(m);
    const bool p1 = !s.P[0].parts.empty(), p2 = !s.P[1].parts.empty();
    if ((p1 || p2) && !convex.empty()) {
        std::string all;
        for (const std::string& m : cn) all += (all.empty() ? "" : ",") + m;
        const std::string which = p1 && p2 ? "P1 and P2 are" : p1 ? "P1 is" : "P2 is";
        if (std::any_of(convex.begin(), convex.end(),
                        [](const std::string& m) { return m.rfind(kCommandMethod, 0) == 0; }))
            throw InputError(which +
                             " made of parts: --command audits a program on two convex objects; on objects made "
                             "of parts, audit your own test from Python with Scene.audit(method) (docs/library.md)");
        throw InputError(which + " made of parts, and method " + internal::in_quotes(convex[0]) +
                         " audits convex objects only (for objects made of parts: --methods " + all + ")");
    }
    std::vector<AuditRow> rows;
    if (!convex.empty() || (compound.empty() && !p1 && !p2))
        rows = audit_convex(name, s, eps, convex, grid_ns, by_distance, measures, settings);
    if (!compound.empty()) {
        std::vector<AuditRow> c = audit_compound(name, s, eps, compound, by_distance, measures, settings);
        rows.insert(rows.end(), c.begin(), c.end());
    }
    return rows;
}

Auditor baseline_auditor() {
    return {[] {
                std::vector<std::string> all = fp::method_names(), cn = fp::compound_method_names();
                all.insert(all.end(), cn.begin(), cn.end());
                return all;
            },
            audit_scene};
}

}  // namespace scalecert::internal
