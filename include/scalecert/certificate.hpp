// Stage 7: the JSON documents — curve, query answer and the certified partition (the certificate
// format, described field by field in certificates/FORMAT.md).
#pragma once
#include "scalecert/partition.hpp"

#include <nlohmann/json.hpp>

namespace scalecert {

using Json = nlohmann::ordered_json;

Json curve_json(const Model& m, const Curve& c);
Json query_json(const Model& m, const QueryResult& r);
Json partition_json(const Model& m, const Curve& c, const Partition& p);

// Serialises with a trailing newline; byte-identical for identical input.
std::string dump(const Json& j);

}  // namespace scalecert
