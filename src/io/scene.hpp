// Stage 1: the scene as the user wrote it, read exactly.
#pragma once
#include "numeric/exact.hpp"

#include <array>
#include <string>
#include <vector>

namespace scalecert::internal {

struct PolyInput {
    std::vector<Vec3q>
        points;  // as given (duplicates and non-extreme points allowed); a compound's: all its parts' in order
    Vec3q seed;  // given, or the mean of the points
    bool seed_given = false;
    // A compound object: its convex parts, each the hull of its points, all scaled about
    // the one seed. Empty for a plain (convex) object. Read only with ReadOptions::allow_parts.
    std::vector<std::vector<Vec3q>> parts;
    // The parts' names (a scene's part "name", an OBJ group's name): empty when no part has one,
    // else one a part, "" for a part without one. Distinct within the object.
    std::vector<std::string> part_names;
    // The radius r >= 0 (CLAIMS.md, "Objects with a radius"): the object is every point within r of
    // the hull of its points. radius_given: the scene gave one (a "radius", or a "sphere" or
    // "capsule" shorthand, which carry theirs), even 0.
    Q radius = 0;
    bool radius_given = false;
    // An object made of parts with radii: part k is every point within part_radii[k] >= 0 of the
    // hull of its points (a part's "radius", else its object's). Empty when no part has one > 0.
    std::vector<Q> part_radii;
    // Part k's radius (0 when it has none); a convex object, one part, has its radius.
    Q part_radius(size_t k) const { return parts.empty() ? radius : part_radii.empty() ? Q(0) : part_radii[k]; }
    // Some part (or the object) has a radius > 0.
    bool has_radius() const {
        if (sgn(radius) > 0) return true;
        for (const Q& r : part_radii)
            if (sgn(r) > 0) return true;
        return false;
    }
    // A remark for the user, said once on stderr by the command (an OBJ mesh with several groups
    // read as one convex object); empty when there is none.
    std::string note;
};

// Part k's name, "" when it has none.
const std::string& part_name(const PolyInput& in, size_t k);
// Part k's name as text follows its number: " ('foot')", or "" when it has none.
std::string part_name_suffix(const PolyInput& in, size_t k);
// Part k of object i (0: P1, 1: P2) for messages: "P1.parts[3]", with its name when it has one:
// "P1.parts[3] ('foot')".
std::string part_label(int i, const PolyInput& in, size_t k);

// At most this many parts an object (each of at least 4 points, all of them within kMaxPoints).
constexpr size_t kMaxParts = 10000;

struct ExactScene {
    PolyInput P[2];
    Q lo[2], hi[2];                  // I1 = [lo[0], hi[0]], I2 = [lo[1], hi[1]]
    std::vector<std::string> files;  // the mesh files a scene file named, as opened (no output may replace one)
    // The numbers of the scene file and its meshes that the reading (ReadOptions::numbers) did not
    // take as written: 0.1 read as a double is not 1/10 (said once, in notes()).
    long inexact_numbers = 0;
    Numbers numbers = Numbers::Double;
    // Likewise for the points of objects and parts with their own "numbers" other than the
    // scene's reading, by that reading (Numbers as an index).
    std::array<long, 3> inexact_by_reading{};
    // An object given as parts (even of one): the scene is answered as objects made of parts.
    bool made_of_parts() const { return !P[0].parts.empty() || !P[1].parts.empty(); }
    // An object with a radius > 0: the scene is answered by the rules of objects with a radius.
    bool rounded() const { return P[0].has_radius() || P[1].has_radius(); }
};

struct ReadOptions {
    // How JSON numbers and mesh text numbers are read (the public Numbers: the double, the float
    // or the decimal as written); JSON strings and fractions are exact always.
    Numbers numbers = Numbers::Double;
    bool allow_off_files = true;  // "mesh" / "off": "FILE" in a scene (off for text from untrusted sources)
    bool allow_parts = false;     // objects made of "parts" (scalecert region); refused elsewhere
    bool parts_from_groups =
        false;  // an object's OBJ mesh as a compound, a part per group (region --parts-from-groups)
    // When set, counts the numbers read that are not the number as written (for the reading's note).
    long* inexact = nullptr;
};

// A pose [R | t]: three rows of four numbers, R·v + t (the public scalecert::Pose).
using scalecert::Pose;
// Whether its R is singular (determinant 0), decided in integers: R times the lcm of its
// denominators.
bool pose_singular(const Pose& m);
// Moves an object's points (every part's) and its given seed to the pose, exactly (a default seed
// is the mean of the moved points: finish_scene). Throws InputError, prefixed with `where`, when
// R is singular.
void apply_pose(const Pose& m, PolyInput& in, const std::string& where);

// What the command says once on stderr about a scene read (Scene::notes()): each object's note, and
// how many numbers were read as binary values other than their text.
std::vector<std::string> scene_notes(const ExactScene& sc);

// Reads and checks a scene file. Throws InputError naming the file and the offending field.
// (Geometric checks that need the hull — rank, seed strictly inside — are done by build_model.)
ExactScene load_scene(const std::string& path, const ReadOptions& opt = {});
// Checks a scene by the reader's rules and messages, prefixed with `name`: at least 4 and at most
// kMaxPoints points each, 0 < lo <= hi. Throws InputError. (build_model calls it; rank and the
// seeds' interiority are its own checks.)
void check_scene(const ExactScene& sc, const std::string& name);
// check_scene, then the mean of the points as the seed of each polyhedron without seed_given:
// call it for a scene assembled in code.
void finish_scene(ExactScene& sc, const std::string& name);
ExactScene parse_scene_text(const std::string& text, const std::string& name, const std::string& base_dir,
                            const ReadOptions& opt = {});

}  // namespace scalecert::internal
