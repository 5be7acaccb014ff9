// A query answer (kind "query"; certificates/FORMAT.md, at the end of "Why a file that passes
// proves the partition"): a verdict at one pair (ρ1, ρ2) > 0 and its certificate, a plane for
// separated, a plane and a witness for touching, a witness at a smaller pair for overlapping
// (interior to both by 3 there: the seeds are proved interior). The `segment` annotation of
// `query --json --segment` is not read.
#include "formats.hpp"
#include "json.hpp"
#include "numbers.hpp"
#include "scene.hpp"

namespace scalecert_check {
void check_query(Context& cx, const J& c) {
    shape(cx, c, "",
          {"format", "kind", "verdict", "rho1", "rho1_double", "rho2", "rho2_double", "certificate", "seed_interior",
           "scene"},
          {"segment"});
    cx.claim(!c.contains("segment") || at(c, "segment").is_object(),
             "segment is an object (an annotation: not checked)");
    const J& vj = at(c, "verdict");
    cx.claim(vj.is_string(), "verdict is a string");
    const std::string v = vj.get<std::string>();
    cx.claim(v == "separated" || v == "touching" || v == "overlapping",
             "the verdict is separated, touching or overlapping");
    const Scene sc = read_scene(cx, at(c, "scene"));
    check_seed_interior(cx, sc, at(c, "seed_interior"));
    Q r1 = field(cx, c, "rho1", ""), r2 = field(cx, c, "rho2", "");
    cx.claim(sgn(r1) > 0 && sgn(r2) > 0, "the scalings are > 0");
    check_verdict(cx, sc, r1, r2, v, at(c, "certificate"));
}

// Its plane and witness (the seeds are proved interior).
void check_verdict(Context& cx, const Scene& sc, const Q& r1, const Q& r2, const std::string& v, const J& cert) {
    if (v == "separated") shape(cx, cert, "certificate", {"plane"});
    if (v == "touching") shape(cx, cert, "certificate", {"plane", "witness"});
    if (v == "overlapping") shape(cx, cert, "certificate", {"witness"});
    if (v == "separated" || v == "touching") {
        const J& pl = at(cert, "plane");
        shape(cx, pl, "plane",
              {"normal", "offset", "offset_double", "P1_max", "P1_max_double", "P2_min", "P2_min_double",
               "support_vertices", "contact"});
        V3 n = normal(cx, at(pl, "normal"), "plane.normal");
        mpz_class H[2];  // D* h1, D* h2
        const std::vector<int>* f[2];
        sc.support(cx, n, H, f);
        const std::vector<int>&f1 = *f[0], &f2 = *f[1];
        // D* times n·s1 + rho1 h1 and n·s2 − rho2 h2 (D* > 0 keeps their order)
        const Q c1 = Q(dotz(ints(n), sc.S[0])) + r1 * Q(H[0]), c2 = Q(dotz(ints(n), sc.S[1])) - r2 * Q(H[1]), D(sc.Dj);
        const J& sv = at(pl, "support_vertices");
        shape(cx, sv, "plane.support_vertices", {"P1", "P2"});
        cx.claim(has(f1, static_cast<int>(index(cx, at(sv, "P1"), sc.count(0), "plane.support_vertices.P1"))) &&
                     has(f2, static_cast<int>(index(cx, at(sv, "P2"), sc.count(1), "plane.support_vertices.P2"))),
                 "plane.support_vertices attain the extremes");
        cx.claim(contact_string(cx, at(pl, "contact"), "plane.contact") ==
                     std::string{dimension_letter(cx, sc, 0, f1), dimension_letter(cx, sc, 1, f2)},
                 "plane.contact is the dimension of the extreme sets");
        cx.claim(field(cx, pl, "P1_max", "plane") * D == c1 && field(cx, pl, "P2_min", "plane") * D == c2,
                 "plane.P1_max and P2_min recomputed from the vertices");
        cx.claim(field(cx, pl, "offset", "plane") * D == (c1 + c2) / 2, "plane.offset is midway");
        cx.claim(v == "separated" ? c1 < c2 : c1 == c2,
                 v == "separated" ? "the plane separates strictly" : "the plane supports both");
    }
    if (v == "touching")
        cx.claim(check_witness(cx, sc, at(cert, "witness"), "witness") == P2{r1, r2},
                 "the witness is at the queried pair");
    if (v == "overlapping") {
        P2 w = check_witness(cx, sc, at(cert, "witness"), "witness");
        cx.claim(w[0] < r1 && w[1] < r2, "the witness is at a smaller pair, hence interior to both");
    }
}
}  // namespace scalecert_check
