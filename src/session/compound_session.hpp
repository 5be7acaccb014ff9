// The orchestration of compounds: a scene whose objects may be made of convex parts,
// its region built at most once (with the union when a document needs it), the query grid on
// first use. The engine of a scene of parts (engine.hpp) holds one; so does a convex scene's, for
// its region.
#pragma once
#include "certify/certificate.hpp"
#include "certify/compound_judge.hpp"
#include "compound/locate.hpp"
#include "compound/region.hpp"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace scalecert::internal {

class CompoundSession {
  public:
    // `name` prefixes the errors ("FILE: P1.parts[2]: ..."). Nothing is built yet.
    CompoundSession(ExactScene scene, std::string name) : sc_(std::move(scene)), name_(std::move(name)) {}
    const ExactScene& scene() const { return sc_; }
    // The region; with_union: with the union of the pair polygons and so the boundary (documents).
    // Throws InputError past the limits of compound_region.
    const CompoundRegion& region(bool with_union);
    // The region document (compound_region_json), with the verdict at `at` when given.
    Json region_json(const std::optional<std::array<Q, 2>>& at = std::nullopt);
    // The certified partition (kind compound_partition).
    Json partition_json();
    // The exact verdicts of doubles' exact values, those in I1 × I2 located on the grid, on `threads`
    // threads; a pair outside I1 x I2 is judged alone, by judge() (as `query` judges it). Every pair
    // is checked first: one not finite or not positive gives InputError "SOURCE: pair K ...".
    std::vector<Verdict> classify(const std::vector<double>& rho1, const std::vector<double>& rho2, unsigned threads,
                                  const std::string& source = "classify");
    // Judgements at any (ρ1, ρ2) > 0 with their proofs (certify-fp): the parts' hulls, built on
    // first use.
    CompoundJudge& judge();
    // The compound judgements certificate of the exact verdict at (ρ1, ρ2) > 0, one verdict claim
    // (scalecert query --json on parts).
    std::string verdict_certificate(const Q& rho1, const Q& rho2);

  private:
    void check_in_rectangle(const Q& rho1, const Q& rho2, const std::string& what) const;
    ExactScene sc_;
    std::string name_;
    std::optional<CompoundRegion> region_;
    bool with_union_ = false;
    std::unique_ptr<CompoundLocator> locator_;
    std::unique_ptr<CompoundJudge> judge_;
};

}  // namespace scalecert::internal
