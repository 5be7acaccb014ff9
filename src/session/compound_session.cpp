// The orchestration of compounds (compound_session.hpp).
#include "session/compound_session.hpp"

#include "certify/claims.hpp"
#include "certify/region_certificate.hpp"

#include <cmath>

namespace scalecert::internal {

const CompoundRegion& CompoundSession::region(bool with_union) {
    if (!region_ || (with_union && !with_union_)) {
        locator_.reset();  // it refers to the region it was built on
        region_.emplace(compound_region(sc_, name_, with_union));
        with_union_ = with_union;
    }
    return *region_;
}

Json CompoundSession::region_json(const std::optional<std::array<Q, 2>>& at) {
    if (at) check_in_rectangle((*at)[0], (*at)[1], "the point");
    return compound_region_json(sc_, region(true), at);
}

Json CompoundSession::partition_json() { return compound_partition_json(sc_, region(false)); }

CompoundJudge& CompoundSession::judge() {
    if (!judge_) judge_ = std::make_unique<CompoundJudge>(sc_, name_);
    return *judge_;
}

std::string CompoundSession::verdict_certificate(const Q& rho1, const Q& rho2) {
    CompoundJudge& j = judge();
    const Json claims{{"format", "scalecert-claims-1"},
                      {"claims", Json::array({Json{{"kind", "verdict"},
                                                   {"rho1", to_exact_string(rho1)},
                                                   {"rho2", to_exact_string(rho2)},
                                                   {"verdict", verdict_name(j.verdict(rho1, rho2).verdict)}}})}};
    long wrong = 0;
    std::string text;
    certify_fp(j, dump(claims), name_, ClaimOptions{Numbers::Double, Q(0), true}, &wrong, nullptr, &text);
    return text;
}

void CompoundSession::check_in_rectangle(const Q& rho1, const Q& rho2, const std::string& what) const {
    if (rho1 < sc_.lo[0] || rho1 > sc_.hi[0] || rho2 < sc_.lo[1] || rho2 > sc_.hi[1])
        throw InputError(what + " (" + to_exact_string(rho1) + ", " + to_exact_string(rho2) +
                         ") lies outside I1 x I2, where the region is built");
}

std::vector<Verdict> CompoundSession::classify(const std::vector<double>& rho1, const std::vector<double>& rho2,
                                               unsigned threads, const std::string& source) {
    if (rho1.size() != rho2.size())
        throw InputError(source + ": " + std::to_string(rho1.size()) + " values of rho1 but " +
                         std::to_string(rho2.size()) + " of rho2");
    std::vector<char> outside(rho1.size(), 0);  // off the rectangle: judged one by one, as query judges them
    size_t n_outside = 0;
    for (size_t k = 0; k < rho1.size(); ++k) {
        if (!std::isfinite(rho1[k]) || !std::isfinite(rho2[k]))
            throw InputError(source + ": pair " + std::to_string(k) + " (numbered from 0) is not finite");
        if (rho1[k] <= 0 || rho2[k] <= 0)
            throw InputError(source + ": pair " + std::to_string(k) + " (numbered from 0) is not positive");
        if (Q(rho1[k]) < sc_.lo[0] || Q(rho1[k]) > sc_.hi[0] || Q(rho2[k]) < sc_.lo[1] || Q(rho2[k]) > sc_.hi[1]) {
            outside[k] = 1;
            ++n_outside;
        }
    }
    // The pairs inside, located on the grid over the region (built only when some pair needs it).
    auto locate = [&](const std::vector<double>& r1, const std::vector<double>& r2) {
        const CompoundRegion& r = region(false);
        if (!locator_) locator_ = std::make_unique<CompoundLocator>(r, sc_.lo, sc_.hi, CompoundLocator::grid_for(r));
        return locator_->classify(r1, r2, threads);
    };
    if (n_outside == 0) return locate(rho1, rho2);
    std::vector<double> in1, in2;
    for (size_t k = 0; k < rho1.size(); ++k)
        if (!outside[k]) {
            in1.push_back(rho1[k]);
            in2.push_back(rho2[k]);
        }
    const std::vector<Verdict> inside = in1.empty() ? std::vector<Verdict>{} : locate(in1, in2);
    std::vector<Verdict> v(rho1.size());
    for (size_t k = 0, i = 0; k < rho1.size(); ++k)
        v[k] = outside[k] ? judge().verdict(Q(rho1[k]), Q(rho2[k])).verdict : inside[i++];
    return v;
}

}  // namespace scalecert::internal
