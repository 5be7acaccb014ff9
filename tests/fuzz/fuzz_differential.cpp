// Random small integer scenes from the bytes: the engine's verdicts must equal the brute-force
// classifier's (tests/support.hpp: no hull, every cross product of vertex differences), at
// pairs from the bytes and at pairs on, just above and just below the curve; and every
// certificate the engine writes (the partition, each query answer) must pass the checker. Half
// the scenes are two axis-aligned boxes (cubes, often), which touch edge to edge, corner to face
// and so on, where many facet normals give one line: there every piece's contact label must be
// the brute force's smallest faces holding the touching set (test::brute_contact).
#include <algorithm>
#include "fuzz_common.hpp"
#include "certify/claims.hpp"
#include "geometry/measures.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace scalecert::internal;
    if (size < 4) return 0;
    size_t at = 0;
    auto next = [&]() -> int { return at < size ? data[at++] : 0; };
    ExactScene sc;
    const int mode = next();
    if (mode & 1) {  // two boxes
        for (int i = 0; i < 2; ++i) {
            const long o[3] = {next() % 9 - 4L, next() % 9 - 4L, next() % 9 - 4L};
            long e[3] = {1 + next() % 4L, 1 + next() % 4L, 1 + next() % 4L};
            if (mode & 2) e[1] = e[2] = e[0];
            for (int k = 0; k < 8; ++k)
                sc.P[i].points.push_back(
                    {Q(o[0] + (k & 1) * e[0]), Q(o[1] + ((k >> 1) & 1) * e[1]), Q(o[2] + ((k >> 2) & 1) * e[2])});
            sc.lo[i] = Q(1, 4);
            sc.hi[i] = Q(4);
        }
    } else {
        const int n[2] = {4 + next() % 6, 4 + next() % 6};
        const int shift[3] = {next() % 15 - 7, next() % 15 - 7, next() % 15 - 7};
        for (int i = 0; i < 2; ++i) {
            for (int k = 0; k < n[i]; ++k) {
                Vec3q v;
                for (int c = 0; c < 3; ++c) v[c] = Q(next() % 9 - 4 + (i ? shift[c] : 0));
                sc.P[i].points.push_back(v);
            }
            sc.lo[i] = Q(1, 4);
            sc.hi[i] = Q(4);
        }
    }
    finish_scene(sc, "fuzz");  // the mean seeds
    HullModel m;
    TouchingCurve cv;
    if (!fuzz::certify(sc, &m, &cv)) return 0;
    test::Brute brute(sc);
    std::vector<std::pair<Q, Q>> pairs;
    while (at + 1 < size && pairs.size() < 8) {
        Q r1(next() + 1, 32), r2(next() + 1, 32);
        r1.canonicalize();
        r2.canonicalize();
        pairs.push_back({r1, r2});
    }
    for (const CurvePiece& p : cv.pieces) {  // the contact label against the brute force
        const std::optional<Q> x = contact_rho1(m, cv, p);
        if (!x) continue;
        const auto [g1, g2] = test::brute_contact(sc, *x, m.lines[cv.env.pieces[p.env].line].at(*x));
        const std::string want{"VEF"[test::affine_dimension(sc.P[0].points, g1)],
                               "VEF"[test::affine_dimension(sc.P[1].points, g2)]};
        if (g1.empty() || p.contact.label != want)
            fuzz::finding("contact " + p.contact.label + " at rho1 = " + x->get_str() + ", brute force says " + want);
        for (int i = 0; i < 2; ++i)
            for (int k : i ? p.contact.feat2 : p.contact.feat1)
                if (!std::binary_search((i ? g2 : g1).begin(), (i ? g2 : g1).end(), k))
                    fuzz::finding("a contact feature vertex outside the touching face");
    }
    for (const CurvePiece& p : cv.pieces) {  // on the curve, and 2^-20 of it above and below
        Q x = (p.from + p.to) / 2, y = m.lines[cv.env.pieces[p.env].line].at(x);
        if (sgn(y) <= 0) continue;
        for (const Q& f : {Q(1), Q(1048575, 1048576), Q(1048577, 1048576)}) pairs.push_back({x, y * f});
    }
    const std::vector<Vec3z> normals = all_facet_normals(m);
    std::string claims = "{\"format\": \"scalecert-claims-1\", \"claims\": [";
    bool first = true;
    for (const auto& [r1, r2] : pairs) {
        QueryAnswer r = query(m, cv, r1, r2, true);
        const int want = brute.classify(sc, r1, r2);
        if (test::verdict_sign(r.verdict) != want)
            fuzz::finding("verdict " + std::string(verdict_name(r.verdict)) + " at (" + r1.get_str() + ", " +
                          r2.get_str() + "), brute force says " + std::to_string(want));
        fuzz::must_pass_checker(dump(query_json(m, r, seed_weights(m))), "query answer");
        // The fast measures against the exact path (test_measures does the same at random).
        if (proved_distance(m, r1, r2).d.squared != exact_distance(m, r1, r2).squared)
            fuzz::finding("proved distance differs from the QP at (" + r1.get_str() + ", " + r2.get_str() + ")");
        const ExactDepth e = exact_penetration_depth(m, normals, r1, r2);
        const std::optional<ProvedDepth> d = proved_depth(m, r1, r2);
        if (r.verdict == Verdict::Overlapping ? (!d || d->squared != e.squared) : d.has_value())
            fuzz::finding("EPA depth differs from the enumeration at (" + r1.get_str() + ", " + r2.get_str() + ")");
        // What certify-fp runs for a depth: its state must be the verdict, its depth the enumeration's.
        const std::optional<MeasuredDepth> md = measured_depth(HullPoints(m), r1, r2);
        const Verdict st = r.verdict;
        if (md && (md->state != st || (st == Verdict::Overlapping && md->depth->squared != e.squared)))
            fuzz::finding("measured depth differs from the verdict or the enumeration at (" + r1.get_str() + ", " +
                          r2.get_str() + ")");
        claims += std::string(first ? "" : ", ") + "{\"kind\": \"distance\", \"rho1\": \"" + r1.get_str() +
                  "\", \"rho2\": \"" + r2.get_str() +
                  "\", \"value\": 1}, {\"kind\": \"penetration_depth\", \"rho1\": \"" + r1.get_str() +
                  "\", \"rho2\": \"" + r2.get_str() + "\", \"value\": 1}, {\"kind\": \"verdict\", \"rho1\": \"" +
                  r1.get_str() + "\", \"rho2\": \"" + r2.get_str() +
                  "\", \"verdict\": \"separated\"}, {\"kind\": \"curve_point\", \"rho1\": \"" + r1.get_str() +
                  "\", \"rho2\": \"" + r2.get_str() + "\"}, {\"kind\": \"switch_point\", \"rho1\": \"" + r1.get_str() +
                  "\", \"rho2\": \"" + r2.get_str() + "\"}";
        first = false;
    }
    // A curve claim over I1 by the curve's own vertices (right, unless the curve is <= 0 there).
    if (!cv.pieces.empty()) {
        std::string v = "[";
        const Q lo = cv.pieces.front().from, hi = cv.pieces.back().to;
        for (const Q& x : {lo, Q((lo + hi) / 2), hi})
            if (sgn(x) > 0)
                v += std::string(v.size() > 1 ? ", " : "") + "[\"" + x.get_str() + "\", \"" +
                     cv.env.value(m.lines, x).get_str() + "\"]";
        v += "]";
        if (std::count(v.begin(), v.end(), '[') >= 3 && lo < hi && sgn(cv.env.value(m.lines, hi)) > 0)
            claims += std::string(first ? "" : ", ") + "{\"kind\": \"curve\", \"vertices\": " + v +
                      ", \"switch_points\": []}",
                first = false;
    }
    // Every judgement of those claims, with its certificate, must pass the checker.
    if (!first) {
        long wrong = 0;
        std::string cert;
        certify_fp(HullClaimModels(m, cv), claims + "]}", "fuzz", ClaimOptions{Numbers::Double, Q(0), true}, &wrong,
                   nullptr, &cert);
        fuzz::must_pass_checker(cert, "judgements");
    }
    return 0;
}
