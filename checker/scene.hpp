// The scene stored in a certificate (certificates/FORMAT.md, "Fields of a partition file":
// `scene`, `seed_interior`, and a witness) and the exact values recomputed from it: support
// values and maximisers, affine dimensions, weighted combinations of vertices.
//
// The claims compare exact values of the file against values recomputed from the scene. A value
// from the scene is an integer over one joint denominator D*, the lcm of both polytopes' vertex
// denominators and the seeds' (S_i = D* s_i, Delta = D* (s2 − s1), H_i = D* h_i): every
// recomputed quantity is then an integer combination of the scene's numbers, and each comparison
// with a number p/q of the file, p D* = q H, costs a product by the file's own number, never a gcd
// of two of the scene's numbers (which would cost, per normal or per named vertex, a power of
// digits the file pays for once).
#pragma once
#include "context.hpp"
#include "scan.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace scalecert_check {
inline constexpr const char* kPoly[2] = {"P1", "P2"};

struct Scene {
    V3 s[2];
    Q lo[2], hi[2];
    // Objects with a radius (a judgements file only: FORMAT.md, "Objects with a radius"): object i
    // is every point within r[i] of the hull of its vertices. rounded: the scene gives both radii.
    bool rounded = false;
    Q r[2];
    std::shared_ptr<const Scan> scan[2];  // (shared: a compound's pair scenes hold its parts' scans)
    mpz_class Dj = 1, E[2];               // D* and D*/D_i
    Z3 S[2], Delta;                       // D* s_i and D* (s2 − s1)
    std::array<Q, 3> sdv[2];              // D_i s_i = S_i / E_i (exact rationals), for the combinations over D_i

    size_t count(int i) const { return scan[i]->size(); }  // the vertices of polyhedron i
    // D*, S_i, Delta and D_i s_i, once the vertices are scanned and the seeds read.
    void prepare(Context& cx);

    // D* h_i(u) for an integer u, given a vertex k attaining the maximum of u·v: u·X_k E_i − u·S_i
    // (h_1(n) = n·(v − s1) with u = n; h_2(n) = −n·(w − s2) with u = −n).
    mpz_class support_at(Context& cx, int i, const Z3& u, int k) const;
    // h_i(n), max over the vertices of σ n·(v − s_i) (σ = +1 for P1, −1 for P2), and every vertex
    // attaining it (ascending): the rational value (tests compare it with a plain rational scan).
    Q h(Context& cx, int i, const V3& n, std::vector<int>* argmax = nullptr) const;
    // Both support values of n over D* (H_i = D* h_i(n)) and their maximisers, computed once per
    // direction: n = g p with p primitive and g > 0 has the maximisers of p and H_i(n) = g H_i(p)
    // (h is positively homogeneous), so a normal repeated, or listed again as a multiple, costs no
    // second scan. Returns the direction's entry (the same pointer for the same direction).
    struct Support {
        mpz_class H[2];
        std::vector<int> max[2];
    };
    const Support* support(Context& cx, const V3& n, mpz_class H_out[2],
                           const std::vector<int>* max_out[2] = nullptr) const;
    // q == H / D* (q a number of the file, H over D*).
    bool over(const Q& q, const mpz_class& H) const { return q.get_num() * Dj == q.get_den() * H; }
    Q value(const mpz_class& H) const {
        Q r(H, Dj);
        r.canonicalize();
        return r;
    }  // H / D*, for messages
    // The work of one product by vertex k's integers and D*'s (a place on a line, a support value).
    void spend_at(Context& cx, int i, int k) const;

  private:
    mutable std::map<std::string, Support> cache_;
};

// The vertices of one polytope (a polyhedron, or a compound's part), one list as it is read: as
// integers when the reader took it as one (json.hpp, parse_certificate), else as rationals, each
// vertex judged by point().
class Vertices {
  public:
    // j is a list of vertices (an array, or a list the reader took).
    static bool is_list(Context& cx, const J& j);
    // The length of the list j.
    static size_t length(Context& cx, const J& j);
    // The vertices of the list j (named where: its vertex k is where[k]), each a point of three
    // exact numbers. A list the reader took is moved out of it (a scene is read once).
    Vertices(Context& cx, const J& j, const std::string& where);
    size_t size() const { return rational_ ? rat_.size() : ints_.n; }
    // The scan of them all (`what` names the polyhedron): the vertices are moved into it.
    std::shared_ptr<const Scan> scan(Context& cx, const std::string& what);

  private:
    IntPoints ints_;
    std::vector<V3> rat_;
    bool rational_ = false;
};

// The scene object of a partition, a query answer or a judgements file: two polyhedra of at
// least 4 vertices, their seeds, I1 and I2. With `radius` (a judgements file), the objects may
// both carry a "radius" >= 0, one of them > 0; an object with a radius > 0 may have any number of
// vertices from 1.
Scene read_scene(Context& cx, const J& j, bool radius = false);
// A pose [R | t] (three rows of four exact numbers): x -> R·x + t.
using Pose = std::array<std::array<Q, 4>, 3>;
// A claim's "pose1" and "pose2" (each three rows of four exact numbers, R nonsingular), and the
// claim without them in `bare`.
std::array<std::optional<Pose>, 2> claim_poses(Context& cx, const J& cl, const std::string& wc, J& bare);
// The scene with polyhedron i moved by pose[i] (none: as it is), its seed too: a claim at poses
// is judged on it (FORMAT.md, "A judgements file").
Scene posed_scene(Context& cx, const Scene& sc, const std::array<std::optional<Pose>, 2>& pose);
// The vertices of P moved by the pose, scanned anew over their least common denominator (`what`
// names them in the limit's message): a compound's part, whose blocks read every vertex.
std::shared_ptr<const Scan> posed_scan(Context& cx, const std::shared_ptr<const Scan>& base, const Pose& pose,
                                       const std::string& what);
// The same polytope held as the base and the pose, nothing moved until asked (Scan's moved
// constructor): a convex object, whose support queries go to the base along Mᵀu. Its common
// denominator is the base's times the pose's (not reduced), refused past 16,384 bits.
std::shared_ptr<const Scan> posed_view(Context& cx, const std::shared_ptr<const Scan>& base, const Pose& pose,
                                       const std::string& what);
// The point x moved by the pose (none: x).
V3 posed_point(const V3& x, const std::optional<Pose>& pose);
// I1 and I2 of a scene object: [lo, hi] with 0 < lo <= hi.
void read_ranges(Context& cx, Q (&lo)[2], Q (&hi)[2], const J& j);

// The dimension of the affine hull of a vertex set of a polytope (of polyhedron i of a scene).
int affine_dim(Context& cx, const Scan& P, const std::vector<int>& idx);
inline int affine_dim(Context& cx, const Scene& sc, int i, const std::vector<int>& idx) {
    return affine_dim(cx, *sc.scan[i], idx);
}
// The letter of a vertex set: the dimension of its affine hull (V: a point, E: a segment, F: a
// polygon or more).
char dimension_letter(Context& cx, const Scene& sc, int i, const std::vector<int>& idx);

// Weights [[index, "w"], ...] over the vertices of a polytope P (a polyhedron, or a compound's
// part): distinct indices, w > 0, sum 1. Returns D Σ w v = Σ w X (D: P's common denominator):
// each term a product of the file's weight and the scene's integers. The vertices named are
// appended to *used.
std::array<Q, 3> combination(Context& cx, const Scan& P, const J& w, const std::string& where,
                             std::vector<int>* used = nullptr);
// The seed is a strictly positive combination of vertices that span 3 dimensions: interior.
void check_seed_interior(Context& cx, const Scene& sc, const J& j);
// The same for polyhedron i alone, its weights w named `where`.
void check_seed_weights(Context& cx, const Scene& sc, int i, const J& w, const std::string& where);
// A witness: a common point of P1(ρ1) and P2(ρ2). Returns (ρ1, ρ2); the vertices each side
// weights are appended to used[0], used[1].
P2 check_witness(Context& cx, const Scene& sc, const J& w, const std::string& where, std::vector<int>* used = nullptr);
// A two-letter contact label.
std::string contact_string(Context& cx, const J& j, const std::string& where);
}  // namespace scalecert_check
