// The largest inputs scalecert reads (README "Limits"). Past any of them the input is refused
// with one line naming the limit and exit status 2, before the work that would exhaust memory or
// time: never an abort or an out-of-memory kill.
#pragma once
#include <cstddef>

namespace scalecert::internal {

constexpr std::size_t kMaxNumberChars = 100000;  // one number's text
// Bits of one number's numerator and of its denominator (10^4932 has 16,384): arithmetic on
// numbers of 10^100000 (332,000 bits, which the text limit and exponents allow) ran for seconds a
// claim, and the checker's work limit refused certificates of them.
constexpr std::size_t kMaxNumberBits = 16384;
constexpr std::size_t kMaxSceneBytes = std::size_t(256) << 20;  // a scene, OFF or claims file
constexpr std::size_t kMaxPairsBytes = std::size_t(2) << 30;    // a pairs file for classify
constexpr std::size_t kMaxPoints = 1000000;                     // points of one polyhedron
// Values in a JSON scene (numbers, strings, arrays, ...): two polyhedra of kMaxPoints points as
// [x, y, z] arrays need 8,000,000; the parsed tree takes about 90 bytes a value.
constexpr std::size_t kMaxJsonValues = 8100000;
// Bits of the common denominator of one polyhedron's coordinates (the engine works on the
// points times that denominator, in integers).
constexpr std::size_t kMaxDenominatorBits = 16384;
// Edge pairs (edges of P1 times edges of P2) of a hull model built for a claim, or summed over the
// part pairs a compound scene builds: the Gauss-map overlay and the contact lines grow with them
// (crossed n-gon prisms have O(n^2) Minkowski facets: two crossed 1,000-gon prisms, 9*10^6 edge
// pairs, take 11 s).
constexpr double kMaxEdgePairs = 2e7;
// Geom pairs scalecert mujoco judges (both geoms a box or a mesh): each keeps its own engine for
// every state (about 35 KB each: 400 free boxes, 79,800 pairs, took 2.8 GB and 49 s a state).
constexpr std::size_t kMaxJudgedGeomPairs = 20000;
// Geom pairs scalecert mujoco considers (judged or not: each unjudged one is named in the report):
// 1,000 spheres make 499,500, which took 724 MB before this limit.
constexpr std::size_t kMaxConsideredPairs = 200000;
// Pair states (states times considered pairs) in one report: each keeps a JSON entry of about
// 1.2 KB in memory until the report is written (101 boxes at 396 states, 1,999,800 pair states,
// took 2.4 GB, and 4.4 GB with --json).
constexpr std::size_t kMaxPairStates = 500000;

}  // namespace scalecert::internal
