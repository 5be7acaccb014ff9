// The proof of each judgement certify-fp makes: the document of kind "judgements"
// (certificates/FORMAT.md, "A judgements file"), which scalecert-check verifies claim by claim
// with support scans over the scene's vertices.
#pragma once
#include "certify/certificate.hpp"
#include "geometry/measures.hpp"

namespace scalecert::internal {

// Is x in P_i(ρ)? With its proof: {"in": weights} (y = s + (x − s)/ρ as a convex combination of
// vertices: a face's fan triangle when y is on the boundary, else interior weights), or
// {"out": normal} (the outward normal of a face of P_i whose plane y lies strictly beyond).
Json membership_proof(const Model& m, int i, const Q& rho, const Vec3q& x, bool* inside);
// The same for a polyhedron P scaled by ρ about `seed` (a compound's part).
Json membership_proof(const Polyhedron& P, const Vec3q& seed, const Q& rho, const Vec3q& x, bool* inside);

// The same from support queries alone, with no hull (a walked scene's point trees): the proved
// distance between P_i(ρ) and x. Inside: the weights of the closest point (x itself); outside: the
// direction from the body's closest point to x, whose plane x lies strictly beyond. None when the
// distance's rounds run out (the caller then builds the hulls).
std::optional<bool> membership_by_points(const PointSets& S, int i, const Q& rho, const Vec3q& x, Json* proof,
                                         int max_rounds = kProvedDistanceRounds);

// Is x, which lies outside P_i(ρ), within `abs` (> 0) of it? The proved distance from x to the body
// (its rounds unbounded: each adds a point): {"near": weights} of the body's point nearest x when
// that is within abs, else {"out": normal}, the direction from that point to x, along which x lies
// more than abs beyond the body's extent.
bool near_proof(const PointSets& S, int i, const Q& rho, const Vec3q& x, const Q& abs, Json* proof);

// The proved distance from x to P_i(ρ) (its rounds unbounded): p1 the body's nearest point, with
// its weights w1; p2 = x.
ExactDistance point_to_body(const PointSets& S, int i, const Q& rho, const Vec3q& x);

// A verdict with its query certificate (on the model that proves it): {"verdict", "certificate"}.
Json verdict_proof(const Model& m, const QueryAnswer& r);

// The exact squared distance E and closest points p ∈ P1(ρ1), q ∈ P2(ρ2) as weights:
// {"squared", "P1", "P2"}. With u = q − p: E = |u|², and for E > 0 the slab — u·x ≤ u·p over
// P1(ρ1), u·y ≥ u·q over P2(ρ2) — proves that no pair is closer. The weights are the distance's
// own (proved_distance) or, without them, found on the hull model m (which must then be given).
Json distance_proof(const Model* m, const ExactDistance& e, const Q& rho1, const Q& rho2);

// The proof of a measured depth (measures.hpp, measured_depth):
// - separated: {"separated": normal}, a normal whose plane separates strictly;
// - touching: {"squared": "0", "direction": normal, "common": {"P1", "P2"}}: a supporting plane of
//   the Minkowski difference through the origin, and a common point (the distance's);
// - overlapping: {"squared", "direction", "points", "triangles"}: the upper bound from the
//   direction (translating P2 by √E along it separates), the lower bound from a closed triangulated
//   surface whose vertices (each [i, j]: point i of P1(ρ1) minus point j of P2(ρ2)) lie in the
//   Minkowski difference and whose every triangle's plane lies at least √E from the origin. It is
//   the final polytope of an exact EPA (expanding polytope) run on support points.
Json depth_proof(const Model* m, const MeasuredDepth& d, const Q& rho1, const Q& rho2);

// The growth distance ρ*: {"value"} when the seeds coincide (ρ* = 0); else {"value", "normal",
// "witness"}: n·d = ρ*(h1(n) + h2(n)), so (ρ, ρ) is separated for every ρ < ρ*, and a common point
// at (ρ*, ρ*).
Json growth_proof(const Model& m, const TouchingCurve& c);

// The exact curve over a window [a, b] that holds [lo_need, hi_need] with room on both sides:
// a < lo_need (a = 0 when lo_need <= 0) and b > hi_need, each halfway to the next break of the
// curve beyond (lo_need/2 and hi_need + 1 where there is none). Its pieces, switch points and
// ends with their witnesses (curve_proof_json) prove the curve and all its switch points strictly
// inside the window: the proof of curve, switch-point and curve-point claims.
Json curve_proof(const Model& m, const TouchingCurve& c, const Q& lo_need, const Q& hi_need);
// That window [a, b], from the curve's breaks. On a walked model the curve must be proved over it
// (Session::curve_around walks until it is).
std::pair<Q, Q> curve_proof_window(const TouchingCurve& c, const Q& lo_need, const Q& hi_need);

// The document: {"format", "kind": "judgements", "tolerance", "judgements", "seed_interior",
// "scene"}, and "abs_tolerance" when it is > 0, as text.
std::string judgements_text(const Model& m, const Q& tolerance, const Q& abs_tolerance, Json judgements);

}  // namespace scalecert::internal
