// scalecert: exact, certified collision of two objects P1, P2, each one or more convex polyhedra
// (its parts) scaled about one seed s_i by a factor ρ_i in a range I_i: P_i(ρ) = s_i + ρ·(P_i − s_i).
// Every answer is exact (GMP rationals); certificates are JSON documents that scalecert-check
// verifies. This header is the whole public API. Link the CMake target scalecert::core.
#pragma once
#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace scalecert {

const char* version();  // "MAJOR.MINOR.PATCH"

using Rational = mpq_class;
using Point = std::array<Rational, 3>;
// A pose [R | t] by rows: a point v moves to R·v + t, exactly. R need not be orthogonal (a rotation
// written in doubles rarely is); a singular R is refused.
using Pose = std::array<std::array<Rational, 4>, 3>;
struct Interval {
    Rational lo{1}, hi{1};
};  // a closed range of scaling factors, 0 < lo <= hi; Interval{} is [1, 1]: no scaling

Rational exact(double x);                          // the double's exact binary value (x finite)
Rational parse_rational(const std::string& text);  // "3/7", "-12", "0.1" (= 1/10), "1e-3", exactly
std::string to_string(const Rational& q);          // "p/q" in lowest terms, or "p"

// What a number written as a floating-point program writes it means (certificates/CLAIMS.md,
// "Numbers"): a decimal (a JSON number; a number in a mesh, in a claims line, on the command line)
// is the binary value a program reading it holds: the double strtod gives (Double, the default),
// or the float strtof gives (Float32). Exact reads it as written (0.1 = 1/10). JSON strings and
// fractions p/q are exact under every reading.
enum class Numbers : std::int8_t { Double, Float32, Exact };
const char* name(Numbers n);  // "double", "float32", "exact"
// A double a program holds, read the same way: its exact value (Double), the float nearest it
// (Float32), or the shortest decimal that reads back as it, as written (Exact: 0.1 is 1/10).
// Throws InputError for a NaN or an infinity, and under Float32 for a double beyond the floats.
Rational held(double x, Numbers numbers);

// Bad input: a scene, a number, a file. what() is one line naming the problem.
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

enum class Verdict : std::int8_t { Separated, Touching, Overlapping };
enum class Feature { Vertex, Edge, Face };
enum class ContactKind { VV, VE, VF, EV, EE, EF, FV, FE, FF };  // feature of P1, then of P2
const char* name(Verdict v);                                    // "separated", "touching", "overlapping"
const char* name(ContactKind k);                                // "VE"
Feature feature1(ContactKind k);
Feature feature2(ContactKind k);

// Two features in contact: the vertices (indices into the input points) spanning each.
struct Contact {
    ContactKind kind;
    std::vector<int> verts1, verts2;
};

// A validated scene of two objects. Each part is the convex hull of its points (duplicates and
// interior points allowed). An object given by its points is one convex part, its seed strictly
// inside; two such objects are a convex scene, with everything the paper defines for two convex
// polyhedra (the curve, its switch points, the growth distance). An object given as parts is made
// of parts (even of one), its seed anywhere; a scene with one is answered as scalecert region
// answers it. A seed defaults to the mean of the object's points. Checked at construction by the
// scene file's rules and messages (4 to 10^6 points an object, 0 < lo <= hi, each part spanning 3
// dimensions). Throws InputError.
class Scene {
  public:
    // Two convex objects.
    Scene(std::vector<Point> p1, std::vector<Point> p2, Interval i1, Interval i2, std::optional<Point> seed1 = {},
          std::optional<Point> seed2 = {});
    // Two convex objects with radii (certificates/CLAIMS.md, "Objects with a radius"): object i is
    // every point within radii[i] >= 0 of the hull of its points, so one point with a radius is a
    // sphere and two a capsule (with a radius > 0 the points may be flat). Verdicts and claims at
    // any pair; the curve and what is built on it are refused (InputError).
    static Scene with_radii(std::vector<Point> p1, std::vector<Point> p2, std::array<Rational, 2> radii,
                            Interval i1 = {}, Interval i2 = {}, std::optional<Point> seed1 = {},
                            std::optional<Point> seed2 = {});
    // Two objects made of parts: parts[i] is object i's parts, each a list of points. With
    // part_radii[i] (empty, or a radius >= 0 for each of object i's parts), part k is every point
    // within its radius of its hull: a part of one point with a radius is a sphere, so a robot of
    // spheres is one object (CLAIMS.md, "Parts with radii"); a part with a radius > 0 may be flat.
    static Scene from_parts(std::vector<std::vector<Point>> parts1, std::vector<std::vector<Point>> parts2, Interval i1,
                            Interval i2, std::optional<Point> seed1 = {}, std::optional<Point> seed2 = {},
                            std::array<std::vector<Rational>, 2> part_radii = {});
    // The scene file format ("vertices" or "parts"); its JSON numbers and its meshes' text numbers
    // read as `numbers` says (JSON strings exact always).
    static Scene load(const std::string& scene_json_path, Numbers numbers = Numbers::Double);
    // Mesh files (.off .obj .ply .stl; text numbers read as `numbers` says, binary floats at their
    // value): each mesh one convex part, or with parts_from_groups each OBJ file's 'o'/'g' groups
    // with faces its parts (other formats have no groups: each stays one convex object). seeds[i],
    // when given, is object i's seed in its mesh's frame (else the mean of its points); poses[i],
    // when given, moves object i's points and seed to that pose before anything else.
    static Scene from_meshes(const std::string& p1_path, const std::string& p2_path, Interval i1, Interval i2,
                             bool parts_from_groups = false, Numbers numbers = Numbers::Double,
                             const std::array<std::optional<Pose>, 2>& poses = {},
                             const std::array<std::optional<Point>, 2>& seeds = {});
    bool convex() const;                                    // two convex objects (neither given as parts)
    size_t part_count(int i) const;                         // 1 for a convex object
    const std::vector<Point>& points(int i) const;          // i = 0 (P1) or 1 (P2): all its points, as given
    const std::vector<Point>& part(int i, size_t k) const;  // the points of part k of object i
    // The name of part k of object i: a scene file's part "name", or an OBJ group's name read as a
    // part; "" when it has none. The same checks as part(i, k).
    const std::string& part_name(int i, size_t k) const;
    // Remarks for the user from reading the scene (an OBJ mesh with two or more groups read as one
    // convex object, which parts_from_groups reads a part per group; how many decimals were read as
    // binary values other than as written); empty when there are none.
    std::vector<std::string> notes() const;
    const Point& seed(int i) const;
    Rational radius(int i) const;                 // 0 for an object without one
    Rational part_radius(int i, size_t k) const;  // part k's (a convex object's own for k = 0)
    Interval range(int i) const;
    std::string json() const;  // the scene file, every number exact

  private:
    friend class Analysis;
    friend struct SceneAccess;  // the library's own front ends; not part of the API
    struct Data;
    explicit Scene(std::shared_ptr<Data> d) : d_(std::move(d)) {}
    std::shared_ptr<Data> d_;
};

// The touching curve over I1: ρ2 = slope·ρ1 + intercept on each piece, descending and convex.
// Below a piece, the plane of its normal separates; above the curve, the polyhedra overlap.
// A piece's contact: the smallest faces holding the touching set P1(ρ1) ∩ P2(ρ2) along it; none
// if ρ2 <= 0 all along the piece.
struct Piece {
    Rational from, to, slope, intercept;
    Point normal;
    std::optional<Contact> contact;
};
struct SwitchPoint {
    Rational rho1, rho2;
    std::optional<Contact> contact;
};  // none if ρ2 <= 0
struct GrowthDistance {
    Rational value;
    bool in_rectangle;
};  // f(ρ*) = ρ* (0: seeds coincide)
struct Curve {
    std::vector<Piece> pieces;
    std::vector<SwitchPoint> switches;
    GrowthDistance growth;
};

// P1(ρ1) ⊆ {normal·x <= c1} and P2(ρ2) ⊆ {normal·x >= c2}: c1 < c2 separates, c1 = c2 touches.
struct Plane {
    Point normal;
    Rational c1, c2, offset;
};  // offset = (c1 + c2) / 2
struct CommonPoint {
    Rational rho1, rho2;
    Point point;
};  // a point of P1(rho1) ∩ P2(rho2)
struct QueryResult {
    Verdict verdict;
    std::optional<Plane> plane;         // separated, touching
    std::optional<CommonPoint> common;  // touching (at the pair), overlapping (at a pair <= it)
};
struct PlaneCheck {
    bool separates;
    Rational c1, c2;
};  // exact c1, c2 as in Plane

// A floating-point program's claims (certificates/CLAIMS.md: JSON scalecert-claims-1, or lines
// 'RHO1 RHO2 VERDICT', 'curve RHO1 RHO2', 'growth RHO'), each marked right or wrong, exactly.
struct ClaimOptions {
    // A claim written by a floating-point program means the binary value it held: a JSON number or
    // a decimal of the line format is read as `numbers` says (Numbers). JSON strings and fractions
    // such as 3/7 are exact always.
    Numbers numbers = Numbers::Double;
    Rational tolerance = 0;    // relative error accepted on numeric JSON claims (>= 0)
    bool json = true;          // the report as JSON (scalecert certify-fp --json), else as text
    bool certificate = false;  // also the judgements certificate (certify-fp --certificate)
    // A length (>= 0) within which a point may lie off its body, a length value off the exact one
    // (on top of the relative tolerance), and a body past a claimed plane (CLAIMS.md, "Tolerances").
    Rational abs_tolerance = 0;
};
// The report; the number of claims and of wrong ones; with options.certificate, the judgements
// certificate (FORMAT.md, kind "judgements"; scalecert-check verifies it): the proof of every
// judgement.
struct ClaimReport {
    std::string report;
    long claims, wrong;
    std::string certificate;
};
// One claim of a floating-point program, typed (the JSON kinds of CLAIMS.md, minus curves):
// the fields its kind uses. A double's claim is its exact value: exact(x).
enum class ClaimKind { Verdict, SeparatingPlane, WitnessPoint, Distance, PenetrationDepth, SignedDistance };
// What a SignedDistance claim says of the exact signed distance S (CLAIMS.md, "Signed distances"):
// S is the value, S >= the value (no contact within a margin), or S < the value (a contact).
enum class SignedBound { Value, AtLeast, Below };
// A claimed verdict: one of the exact three, intersecting (overlapping or touching: what a
// collision test that answers yes or no claims), or not overlapping (separated or touching: what
// an engine that reports no contact at margin 0 claims).
enum class ClaimedVerdict { Separated, Touching, Overlapping, Intersecting, NotOverlapping };
const char* name(ClaimedVerdict v);  // name(Verdict)'s words, "intersecting" and "not_overlapping"
struct Claim {
    ClaimKind kind = ClaimKind::Distance;
    Rational rho1 = 1, rho2 = 1;
    ClaimedVerdict verdict = ClaimedVerdict::Separated;  // Verdict
    Point normal{};                                      // SeparatingPlane
    std::optional<Rational> offset;                      // SeparatingPlane
    Point point{};                                       // WitnessPoint
    Rational value = 0;                                  // Distance, PenetrationDepth, SignedDistance
    SignedBound bound = SignedBound::Value;              // SignedDistance
    std::optional<std::array<Point, 2>> closest;         // Distance: on P1, on P2
    std::optional<Point> direction;                      // PenetrationDepth
    // PenetrationDepth on objects made of parts: the part pair it speaks of (a contact, as FCL and
    // Bullet report one per colliding part pair), {part of P1, part of P2}, numbered from 0.
    std::optional<std::array<int, 2>> parts;
    // The objects at poses (every kind): P1 moved by pose1 = [R | t] as the
    // scene places it (v -> R·v + t, the seed too), then scaled about its seed; none: as the
    // scene is. R must be nonsingular (else InputError). Doubles a program held: exact(x).
    std::optional<Pose> pose1, pose2;
    // The field in which the program gave no answer (a NaN or an infinity it wrote, e.g. "value"),
    // if any: the claim is judged wrong (CLAIMS.md, "Outputs that are no answer"). A zero normal
    // or direction is no answer too.
    std::string no_answer;
};
// Its judgement, part by part (CLAIMS.md): right when every part given is right.
struct Judgement {
    bool right = false;
    std::optional<bool> value_right, closest_right, direction_right;  // distances, depths
    // Distances, depths, signed distances (none: a depth claimed of a separated pair); a signed
    // distance's is D² apart, P² overlapping (its sign is exact_verdict's).
    std::optional<Rational> exact_squared;
    // Objects with a radius (Scene::with_radii): exact_squared is the hulls' and radius_sum is
    // R = ρ1 r1 + ρ2 r2, the exact value ±√exact_squared − R (a depth's R ∓ √exact_squared).
    std::optional<Rational> radius_sum;
    double exact = 0;      // √exact_squared, correctly rounded (MPFR); a signed distance's with its sign
    double rel_error = 0;  // |value − exact| / |exact|, MPFR-rounded (0 when both are 0; inf when only exact is)
    std::optional<Verdict> exact_verdict;  // verdicts, signed distances
    std::string reason;                    // a claim with no answer: the field and why ("value: not a number")
    // Objects made of parts: the part pair the exact answer rests on (a verdict's meeting pair, a
    // distance's closest pair, a depth's pair), −1 for none; their names ("" for a part without one).
    int part1 = -1, part2 = -1;
    std::string part1_name, part2_name;
};
struct Judgements {
    std::vector<Judgement> items;  // one per claim, in order
    long wrong = 0;
    std::string certificate;  // with options.certificate: the judgements certificate
};
// Golden data: the curve document with, near the curve, exact verdicts of pairs and of their
// nearest doubles (JSON), and those doubles with their verdicts (CSV).
// What golden data holds for a scene (scalecert golden --verticals, --offsets; docs/manual.md).
struct GoldenOptions {
    int verticals = 7;                                // values of ρ1 where the boundary is sampled
    std::vector<int> offsets{4, 12, 20, 30, 40, 52};  // pairs 2^-K of a coordinate from each sample
};
struct GoldenData {
    std::string json, csv, rational_csv;  // NAME.golden.json, .golden.csv, .golden.rational.csv
};

// The analysis of one scene, convex or made of parts. Calls on one Analysis from several threads
// at once are not supported; classify() itself runs on many threads. What is defined only for two
// convex objects (the curve) throws InputError on a scene of parts, naming what answers instead.
class Analysis {
  public:
    // A convex scene's curve is built here, by the engine the scalecert command chooses: by
    // walking it (the scan path, no hull) from 2,000 points (or 250,000 as the product of the
    // counts), else from the hull model. Every call answers from the walk where it proved what the
    // answer needs (queries, documents, classify, claims, golden data), with support queries on
    // the points' trees for planes, distances and depths; the hull model, built at most once a
    // scene, answers the rest. On a scene of parts nothing is built before it is needed.
    explicit Analysis(const Scene& scene);
    bool convex() const;
    // The exact verdict at (ρ1, ρ2), ρ1, ρ2 > 0.
    Verdict verdict(const Rational& rho1, const Rational& rho2) const;
    // The verdict with its evidence on a convex scene (a plane, a common point); on parts the verdict.
    QueryResult query(const Rational& rho1, const Rational& rho2) const;
    // The exact verdicts at doubles' exact values (> 0, finite), on
    // `threads` threads (0: all cores).
    std::vector<Verdict> classify(const std::vector<double>& rho1, const std::vector<double>& rho2,
                                  unsigned threads = 0) const;
    // Is n·x = offset (or, without offset, some plane of normal n) strictly between P1(ρ1) and
    // P2(ρ2), every part of each?
    PlaneCheck check_plane(const Rational& rho1, const Rational& rho2, const Point& normal,
                           const std::optional<Rational>& offset = {}) const;
    // JSON documents (certificates/FORMAT.md); byte-identical to the scalecert command's output.
    std::string query_json(const Rational& rho1, const Rational& rho2) const;  // parts: its judgements certificate
    std::string partition_json() const;  // the certificate (parts: compound_partition): check it with scalecert-check
    std::string region_json() const;     // scalecert region: pair polygons, their union, its labelled boundary
    // scalecert certify-fp; throws InputError for malformed claims, and on parts for claims defined
    // on two convex objects only (curves, switch points, growth distances; a penetration depth on
    // parts names its part pair).
    ClaimReport certify_fp(const std::string& claims, const ClaimOptions& options = {}) const;
    // The same, typed, over an array of claims (options.numbers and .json do not apply: a typed
    // claim's numbers are exact; held() gives what a program reading a double holds).
    Judgements certify(const std::vector<Claim>& claims, const ClaimOptions& options = {}) const;
    // What scalecert golden writes for each of its scenes, without the family's fields (on parts:
    // the region document with queries where the objects' meeting set ends).
    GoldenData golden(const GoldenOptions& options = {}) const;
    // Two convex objects only:
    const Curve& curve() const;
    std::string curve_json() const;

  private:
    struct Impl;
    std::shared_ptr<const Impl> impl_;
};

// Golden data of a family of scenes, as scalecert golden --family writes it: `count` scenes of
// `family` at degeneracy eps > 0 (smaller is more degenerate), scene i drawn from `seed`, each as
// NAME-i.scene.json, .golden.json, .golden.csv and .golden.rational.csv in `dir` (created); the
// same bytes for the same arguments. families() lists the names. Throws InputError.
void write_golden(const std::string& family, int count, std::uint64_t seed, const Rational& eps, const std::string& dir,
                  const GoldenOptions& options = {});
std::vector<std::string> families();

// MuJoCo as it runs (scalecert mujoco; docs/manual.md, "mujoco"): the model (MJCF or MJB) loaded
// by MuJoCo itself (Debian's libmujoco, in a module loaded on first use), run by mj_forward at each
// state, and every geom pair its collision pipeline considers judged against the exact answer for
// the geometry MuJoCo held. States: each qpos given (nq doubles), else keyframe `key` (>= 0), else
// qpos0. InputError for bad input, as the command words it (a missing module too).
struct MujocoOptions {
    Rational tolerance = 0, abs_tolerance = 0;  // as certify-fp's --tolerance, --abs-tolerance (metres)
    int key = -1;
    std::string failures;  // a folder for reproducers of wrong judgements ("": none)
    // Also judge against the model as written (scalecert mujoco --intended): the mesh files'
    // numbers as doubles in MuJoCo's mesh frame; each pair's "intended" in the report. judge_mujoco
    // only (held arrays carry no files).
    bool intended = false;
};
struct MujocoJudgement {
    std::string json;      // the report (format scalecert-mujoco-1), the bytes `scalecert mujoco --json` writes
    std::string text;      // a line per wrong judgement, then the summary
    long wrong_pairs = 0;  // pair states with a wrong judgement
    long judgements = 0;   // judgements made (0: nothing of the model could be judged)
};
MujocoJudgement judge_mujoco(const std::string& model, const std::vector<std::vector<double>>& qpos = {},
                             const MujocoOptions& options = {});

// What a program's own MuJoCo holds, by mjModel's and mjData's field names, flat as MuJoCo stores
// them: the same judgement without loading anything (scalecert/mujoco.hpp fills these from an
// mjModel* and mjData*; Python's judge_mujoco_held from MjModel and MjData's attributes). Sizes
// follow from the arrays: ngeom = geom_type.size(), nbody = body_parentid.size(), and so on.
struct MujocoHeldModel {
    int nq = 0;
    std::vector<int> geom_type, geom_bodyid, geom_contype, geom_conaffinity, geom_dataid;
    std::vector<double> geom_size, geom_margin, geom_gap;  // ngeom x 3, ngeom, ngeom
    std::vector<std::string> geom_names, body_names;       // empty, or ngeom (nbody) names ("" unnamed)
    std::vector<int> body_parentid, body_weldid;
    std::vector<int> mesh_vertadr, mesh_vertnum;
    std::vector<float> mesh_vert;  // nmeshvert x 3
    std::vector<int> pair_geom1, pair_geom2;
    std::vector<double> pair_margin, pair_gap;
    std::vector<int> exclude_signature;
    int opt_disableflags = 0, opt_enableflags = 0, opt_collision = 0;  // mjOption's
    double opt_o_margin = 0;
};
struct MujocoHeldContact {
    int geom1 = 0, geom2 = 0;
    double dist = 0;
    std::array<double, 3> pos{};
    std::array<double, 9> frame{};  // the normal, from geom1 to geom2, in frame[0..2]
    double includemargin = 0;
    int exclude = 0;
};
struct MujocoHeldData {
    std::vector<double> qpos;                  // nq (for the report and the reproducers)
    std::vector<double> geom_xpos, geom_xmat;  // ngeom x 3, ngeom x 9
    std::vector<MujocoHeldContact> contact;    // the ncon contacts
    // MuJoCo dropped contacts at this state (ncon reached nconmax): pairs without a contact are
    // then not judged, as in judge_mujoco.
    bool contact_buffer_full = false;
};
// Each data judged in turn, as judge_mujoco judges its states; `source` names the model in the
// report and the reproducers. InputError when the arrays do not fit together (each named).
MujocoJudgement judge_mujoco_held(const MujocoHeldModel& model, const std::vector<MujocoHeldData>& data,
                                  const MujocoOptions& options = {}, const std::string& source = "held arrays");

}  // namespace scalecert
