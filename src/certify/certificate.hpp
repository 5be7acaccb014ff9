// Stage 7: the JSON documents — curve, query answer and the certified partition (the certificate
// format, described field by field in certificates/FORMAT.md).
#pragma once
#include "certify/partition.hpp"
#include "io/json.hpp"

namespace scalecert::internal {

// o[key] = exact string, o[key + "_double"] = nearest double (for a list or a point, each).
void put_exact(Json& o, const std::string& key, const Q& q);
void put_exact(Json& o, const std::string& key, const std::vector<Q>& qs);
void put_exact(Json& o, const std::string& key, const Vec3q& v);

Json curve_json(const Model& m, const TouchingCurve& c);
// Pieces of the documents, for the judgements certificate (judgements.cpp): a query answer's
// "certificate" object (its plane and witness), weights [[index, "w"], ...], and the seeds'
// "seed_interior" object.
Json query_certificate_json(const Model& m, const QueryAnswer& r);
Json weights_json(const std::vector<std::pair<int, Q>>& w);
Json witness_object(const Witness& w);  // {rho1, rho2, point (with _double), P1, P2 weights}
Json normal_json(const Vec3z& n);       // three integer strings
Json seed_interior(const SeedWeights& seeds);
Json query_json(const Model& m, const QueryAnswer& r, const SeedWeights& seeds);
Json partition_json(const Model& m, const TouchingCurve& c, const Partition& p);
// The curve c over its range [a, b] as a judgement's proof (FORMAT.md, "A judgements file"):
// {"rho1": [a, b], "pieces", "switch_points", "curve_ends"} in a partition's form, with witnesses.
Json curve_proof_json(const Model& m, const TouchingCurve& c, const CurveWitnesses& w);

// A query answer's or partition's text: dump(j), with the scene's points written in on the walk
// (whose documents hold placeholders for them). Use it for every document from query_json and
// partition_json.
std::string document_text(const Model& m, const Json& j);
// The scene of m for a document: the exact scene, or on the walk its seeds and ranges with
// placeholders for the points, which document_text fills in.
Json document_scene(const Model& m);

}  // namespace scalecert::internal
