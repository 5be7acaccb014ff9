// What a curve model's documents and witnesses take from where its points are: the hull model's
// exact polyhedra (every vertex at hand, few of them) or the walk's points in machine integers (up
// to 10^6 a polyhedron, no hull). Each is one implementation; points_of is the one place that
// looks at which a model has.
#pragma once
#include "certify/query.hpp"
#include "io/json.hpp"

#include <string>
#include <utility>
#include <vector>

namespace scalecert::internal {

class ModelPoints {
  public:
    virtual ~ModelPoints() = default;
    // A document's "model": the engine and what it did.
    virtual Json engine_json(const Model& m) const = 0;
    // A document's "scene" (on the walk with placeholders for the points, which document_text
    // writes in).
    virtual Json scene_json(const Model& m) const = 0;
    virtual std::string document_text(const Model& m, std::string text) const = 0;
    // The seed of polyhedron i strictly inside: strictly positive weights on points spanning 3
    // dimensions.
    virtual std::vector<std::pair<int, Q>> seed_weights(const Model& m, int i) const = 0;
    // The seeds' weights a curve proof's witnesses are lifted with (none where none is lifted).
    virtual SeedWeights curve_seeds(const Model& m) const = 0;
    // A common point of P1(ρ1) and P2(ρ2) strictly above the curve (or at ρ2 = 0 left of where
    // it reaches 0): a program over every vertex, or the witness of the curve point below it (or of
    // where the curve reaches 0), lifted with the seeds' weights (lift_witness).
    virtual Witness witness_off_the_curve(const Model& m, const TouchingCurve& c, const Q& rho1, const Q& rho2,
                                          const std::vector<std::pair<int, Q>> seed[2]) const = 0;
};
const ModelPoints& points_of(const Model& m);

}  // namespace scalecert::internal
