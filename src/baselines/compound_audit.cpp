// Audits of floating-point code on objects made of convex parts: Bullet's
// compound shapes, FCL's broad-phase managers of convex parts and libccd's GJK over the part pairs,
// judged against CompoundJudge's exact verdicts at points on the overlap region's boundary and
// pushed off it by relative distances 2^-4 ... 2^-52.
#include "baselines/audit.hpp"

#include "geometry/measures.hpp"
#include "session/compound_session.hpp"

#include <chrono>
#include <cmath>
#include <map>
#include <tuple>

namespace scalecert::internal {

namespace {

struct EdgeRef {
    Point2q from, to;
};

// A double point exactly on the edge e near p (a point of it), where one is found. With the edge's
// line as A ρ1 + B ρ2 = C in coprime integers, the points with coordinates X/2^m, Y/2^m are the
// integer solutions of A X + B Y = C 2^m: none when gcd(A, B) does not divide C 2^m (then no
// double lies on the line at that scale), else X0 + k B/g, Y0 − k A/g, of which the one nearest p
// is taken. m puts the larger coordinate of p near 2^50, so X and Y are doubles when below 2^53.
std::optional<std::array<double, 2>> double_on_edge(const EdgeRef& e, const Point2q& p) {
    const Q dx = e.to[0] - e.from[0], dy = e.to[1] - e.from[1];
    Q a = -dy, b = dx, c = dx * e.from[1] - dy * e.from[0];
    Z l;
    mpz_lcm(l.get_mpz_t(), a.get_den_mpz_t(), b.get_den_mpz_t());
    mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
    const Z A = Z(a * l), B = Z(b * l), C = Z(c * l);
    int ex = 0;
    std::frexp(std::max(std::fabs(to_double_rn(p[0])), std::fabs(to_double_rn(p[1]))), &ex);
    const int m = 50 - ex;
    const Z N = m >= 0 ? Z(C << m) : Z(0);
    if (m < 0 || (sgn(A) == 0 && sgn(B) == 0)) return std::nullopt;  // (a point beyond 2^50: none sought)
    Z g, s, t;
    mpz_gcdext(g.get_mpz_t(), s.get_mpz_t(), t.get_mpz_t(), A.get_mpz_t(), B.get_mpz_t());
    if (!mpz_divisible_p(N.get_mpz_t(), g.get_mpz_t())) return std::nullopt;
    const Z f = N / g;
    Z X = s * f, Y = t * f;
    const Z stepX = B / g, stepY = -(A / g);  // (X, Y) + k (stepX, stepY) stay on the line
    // k nearest the target along the coordinate that moves most.
    const bool along_x = abs(stepX) >= abs(stepY);
    const Q target = (along_x ? p[0] : p[1]) * Q(Z(1) << m);
    const Z& step = along_x ? stepX : stepY;
    Q kq = (target - Q(along_x ? X : Y)) / Q(step);
    Z k;
    mpz_fdiv_q(k.get_mpz_t(), Z(kq.get_num() * 2 + kq.get_den()).get_mpz_t(),
               Z(kq.get_den() * 2).get_mpz_t());  // round(kq)
    X += k * stepX;
    Y += k * stepY;
    const Z lim = Z(1) << 53;
    if (abs(X) >= lim || abs(Y) >= lim) return std::nullopt;
    const Q xq(X, Z(1) << m), yq(Y, Z(1) << m);
    if (!(std::min(e.from[0], e.to[0]) <= xq && xq <= std::max(e.from[0], e.to[0]) &&
          std::min(e.from[1], e.to[1]) <= yq && yq <= std::max(e.from[1], e.to[1])))
        return std::nullopt;
    return std::array<double, 2>{to_double_rn(xq), to_double_rn(yq)};  // (exact: both are doubles)
}

Verdict exact_verdict(CompoundJudge& judge, double r1, double r2) {
    return judge.verdict(exact_from_double(r1), exact_from_double(r2)).verdict;
}

}  // namespace

fp::CompoundFp compound_fp(const CompoundJudge& judge) {
    fp::CompoundFp f;
    const ExactScene& s = judge.scene();
    for (int i = 0; i < 2; ++i) {
        for (size_t k = 0; k < judge.parts(i); ++k) {
            const Polyhedron& P = judge.part(i, k);
            fp::CompoundFp::Part part;
            for (const Vec3q& v : P.points)
                part.pts.push_back({to_double_rn(v[0]), to_double_rn(v[1]), to_double_rn(v[2])});
            for (const Face& face : P.faces) part.faces.push_back(face.verts);
            f.parts[i].push_back(std::move(part));
        }
        f.seed[i] = {to_double_rn(s.P[i].seed[0]), to_double_rn(s.P[i].seed[1]), to_double_rn(s.P[i].seed[2])};
        f.lo[i] = to_double_rn(s.lo[i]);
        f.hi[i] = to_double_rn(s.hi[i]);
    }
    return f;
}

std::vector<CompoundSample> compound_samples(CompoundJudge& judge, const CompoundBoundary& b, int random, int points) {
    const ExactScene& s = judge.scene();
    std::vector<CompoundSample> out;
    // Random pairs in I1 × I2, drawn as the convex audit draws its own.
    Rng g(12345);
    const double lo[2] = {to_double_rn(s.lo[0]), to_double_rn(s.lo[1])},
                 hi[2] = {to_double_rn(s.hi[0]), to_double_rn(s.hi[1])};
    for (int k = 0; k < random; ++k) {
        CompoundSample c;
        c.k = -1;
        c.r1 = lo[0] + (hi[0] - lo[0]) * static_cast<double>(g.next() >> 11) * 0x1.0p-53;
        c.r2 = lo[1] + (hi[1] - lo[1]) * static_cast<double>(g.next() >> 11) * 0x1.0p-53;
        c.exact = exact_verdict(judge, c.r1, c.r2);
        out.push_back(c);
    }
    // The contact edges (the others lie on the rectangle's sides), in ring order.
    std::vector<EdgeRef> edges;
    for (const BoundaryRing& ring : b.rings)
        for (const BoundaryEdge& e : ring.edges)
            if (e.bound < 0 && e.from != e.to) edges.push_back({e.from, e.to});
    const size_t E = edges.size(), M = static_cast<size_t>(std::max(points, 0));
    std::vector<std::pair<size_t, int>> chosen;  // edge, points on it
    if (E <= M) {
        for (size_t i = 0; i < E; ++i) chosen.push_back({i, static_cast<int>(M / E)});
    } else {
        for (size_t i = 0; i < M; ++i) chosen.push_back({i * E / M, 1});
    }
    for (const auto& [ei, q] : chosen) {
        const EdgeRef& e = edges[ei];
        const Q dx = e.to[0] - e.from[0], dy = e.to[1] - e.from[1];
        // The push moves the coordinate along which the edge's left normal (−dy, dx), towards the
        // region, is larger: ρ2 when |dx| >= |dy|.
        const int axis = abs(dx) >= abs(dy) ? 1 : 0;
        const int inward = axis == 1 ? sgn(dx) : -sgn(dy);
        for (int j = 0; j < q; ++j) {
            const Q t(2 * j + 1, 2 * q);
            Point2q p{e.from[0] + t * dx, e.from[1] + t * dy};
            p[0].canonicalize();
            p[1].canonicalize();
            CompoundSample on;
            if (const auto d = double_on_edge(e, p)) {
                on.r1 = (*d)[0], on.r2 = (*d)[1];
                p = {exact_from_double(on.r1), exact_from_double(on.r2)};  // pushed from the double point on the line
            } else {
                on.r1 = to_double_rn(p[0]), on.r2 = to_double_rn(p[1]);
            }
            on.exact = exact_verdict(judge, on.r1, on.r2);
            out.push_back(on);
            for (int k = 4; k <= 52; k += 4)
                for (int side : {1, -1}) {
                    CompoundSample c;
                    c.k = k;
                    c.side = side;
                    Point2q x = p;
                    x[static_cast<size_t>(axis)] += side * inward * p[static_cast<size_t>(axis)] / Q(Z(1) << k);
                    c.r1 = to_double_rn(x[0]);
                    c.r2 = to_double_rn(x[1]);
                    c.exact = exact_verdict(judge, c.r1, c.r2);
                    out.push_back(c);
                }
        }
    }
    return out;
}

std::vector<int> score_compound(const fp::Method& m, const std::vector<CompoundSample>& samples, bool by_distance,
                                AuditRow& row) {
    std::vector<int> said(samples.size());
    AuditRow::OnBoundary on;
    if (by_distance)
        for (int k = 4; k <= 52; k += 4) row.by_distance.push_back(AuditRow::ByDistance{k});
    for (size_t i = 0; i < samples.size(); ++i) {
        const CompoundSample& c = samples[i];
        const int v = said[i] = m.classify(c.r1, c.r2);
        row.count(c.r1, c.r2, v, c.exact);
        if (c.k == 0) {
            ++on.points;
            if (c.exact == Verdict::Touching) {
                ++on.touching;
                ++(v > 0 ? on.said_separated : v == 0 ? on.said_touching : on.said_overlapping);
            } else {
                ++on.moved;
                on.moved_wrong += AuditRow::wrong(v, c.exact);
            }
        } else if (c.k > 0 && by_distance) {
            AuditRow::ByDistance& b = row.by_distance[static_cast<size_t>(c.k / 4 - 1)];
            if (c.exact == Verdict::Touching) {
                ++b.touching;
            } else {
                ++b.pairs;
                b.wrong += AuditRow::wrong(v, c.exact);
            }
        }
    }
    row.on_boundary = on;
    return said;
}

std::vector<AuditRow> audit_compound(const std::string& name, const ExactScene& s, const Q& eps,
                                     const std::vector<std::string>& methods, bool by_distance, bool measures,
                                     const MethodSettings& settings) {
    using Clock = std::chrono::steady_clock;
    // Every method is known before any work.
    const std::vector<std::string> known = fp::compound_method_names();
    for (const std::string& m : methods)
        if (std::find(known.begin(), known.end(), m) == known.end())
            throw InputError("--methods: unknown method " + in_quotes(m));
    auto none_run = [&](const std::string& why) {
        std::vector<AuditRow> rows;
        for (const std::string& m : methods) rows.push_back(not_run_row(name, m, eps, settings, measures, why));
        return rows;
    };
    CompoundSession session(s, name);
    const CompoundRegion& r = session.region(true);
    if (r.union_skipped)
        return none_run("more than " + std::to_string(kMaxUnionPolygons) +
                        " part pairs overlap with area in I1 x I2: the region's union, whose boundary the audit "
                        "samples, is not formed");
    const CompoundBoundary b = label_boundary(r, session.scene());
    CompoundJudge judge(session.scene(), name);
    const std::vector<CompoundSample> samples = compound_samples(judge, b);
    fp::CompoundFp f = compound_fp(judge);
    f.settings = settings;
    double extent = 0;
    for (int i = 0; i < 2; ++i)
        for (const fp::CompoundFp::Part& part : f.parts[i])
            extent = fp::scaled_extent(part.pts, f.seed[i], to_double_rn(s.hi[i]), extent);
    if (const std::string why = beyond_doubles(extent); !why.empty()) return none_run(why);
    std::vector<std::optional<Q>> squared(samples.size());  // exact squared distances, once for all methods
    // Exact squared depths of part pairs at samples, once for all methods (−1: the pair does not overlap).
    std::map<std::tuple<size_t, int, int>, std::optional<Q>> pair_depths;
    std::vector<AuditRow> rows;
    for (const std::string& meth : methods) {
        std::unique_ptr<fp::Method> mm = fp::make_compound_method(meth, f);
        AuditRow row;
        row.scene = name;
        row.method = mm->name();
        row.settings = fp::settings_of(row.method, settings, measures);
        row.eps = eps;
        const auto t0 = Clock::now();
        const std::vector<int> said = score_compound(*mm, samples, by_distance, row);
        row.seconds_per_query = std::chrono::duration<double>(Clock::now() - t0).count() /
                                static_cast<double>(std::max<size_t>(1, samples.size()));
        if (measures) {
            // Distances where the pair is separated and the method says so, against the exact
            // least distance over the part pairs; the closest points checked for membership.
            std::vector<double> err;
            std::vector<AuditRow::MeasureFailure> measured;
            for (size_t i = 0; i < samples.size(); ++i) {
                if (samples[i].exact != Verdict::Separated || said[i] <= 0) continue;
                const std::optional<fp::Measure> me = mm->measure(samples[i].r1, samples[i].r2, true);
                if (!me || me->depth || !std::isfinite(me->value)) continue;
                const Q a = exact_from_double(samples[i].r1), bb = exact_from_double(samples[i].r2);
                if (!squared[i]) squared[i] = judge.distance(a, bb).squared;
                const std::optional<double> e = relative_error(*squared[i], me->value);
                if (!e) continue;
                err.push_back(*e);
                measured.push_back({samples[i].r1, samples[i].r2, false, me->value, *e});
                if (me->closest && (!fp::finite(me->closest->at(0)) || !fp::finite(me->closest->at(1)))) {
                    ++row.closest_outside;  // a NaN or infinite point is in no body
                } else if (me->closest) {
                    const auto& cp = *me->closest;
                    const Vec3q p{exact_from_double(cp[0][0]), exact_from_double(cp[0][1]),
                                  exact_from_double(cp[0][2])};
                    const Vec3q q{exact_from_double(cp[1][0]), exact_from_double(cp[1][1]),
                                  exact_from_double(cp[1][2])};
                    row.closest_outside += judge.locate(0, a, p) < 0 || judge.locate(1, bb, q) < 0;
                }
            }
            row.distances = static_cast<long>(err.size());
            row.distance_err_median = median(err);
            for (double e : err) row.distance_err_max = std::max(row.distance_err_max, e);
            // Contacts where the objects overlap and the method says so: each part pair's reported
            // depth against that pair's exact depth (the pair's depth as two convex objects', proved
            // by the exact EPA), and its direction's depth along it; a contact on a pair that does
            // not overlap exactly is counted apart (contacts_apart).
            std::vector<double> derr;
            for (size_t i = 0; i < samples.size(); ++i) {
                if (samples[i].exact != Verdict::Overlapping || said[i] >= 0) continue;
                const Q a = exact_from_double(samples[i].r1), bb = exact_from_double(samples[i].r2);
                for (const fp::PartContact& c : mm->contacts(samples[i].r1, samples[i].r2)) {
                    if (c.part1 < 0 || c.part2 < 0 || static_cast<size_t>(c.part1) >= judge.parts(0) ||
                        static_cast<size_t>(c.part2) >= judge.parts(1) || !(c.depth > 0) || !std::isfinite(c.depth))
                        continue;
                    auto& E = pair_depths[{i, c.part1, c.part2}];
                    if (!E) {
                        const MeasuredDepth m = judge.pair_depth(c.part1, c.part2, a, bb);
                        E = m.state == Verdict::Overlapping && m.depth ? m.depth->squared : Q(-1);
                    }
                    if (sgn(*E) <= 0) {
                        ++row.contacts_apart;
                        continue;
                    }
                    const std::optional<double> e = relative_error(*E, c.depth);
                    if (!e) continue;
                    derr.push_back(*e);
                    measured.push_back({samples[i].r1, samples[i].r2, true, c.depth, *e, c.part1, c.part2});
                    const fp::D3& d = c.direction;
                    if ((d[0] != 0 || d[1] != 0 || d[2] != 0) && std::isfinite(d[0] + d[1] + d[2])) {
                        const Vec3q n{exact_from_double(d[0]), exact_from_double(d[1]), exact_from_double(d[2])};
                        const Q along = judge.pair_directional_depth(c.part1, c.part2, n, a, bb);
                        const std::optional<double> x =
                            sgn(along) >= 0 ? direction_excess(along, *E, extent) : std::nullopt;
                        if (x) row.direction_err_max = std::max(row.direction_err_max, *x);
                    }
                }
            }
            row.depths = static_cast<long>(derr.size());
            row.depth_err_median = median(derr);
            for (double e : derr) row.depth_err_max = std::max(row.depth_err_max, e);
            row.note_measures(std::move(measured), settings.measure_tolerance);
        }
        rows.push_back(row);
    }
    return rows;
}

}  // namespace scalecert::internal
