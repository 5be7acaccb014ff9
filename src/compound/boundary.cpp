// The compound region's boundary, labelled (boundary.hpp). Exact throughout: every side test is a
// sign of rationals.
#include "compound/boundary.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <stdexcept>

namespace scalecert::internal {

namespace {

// The oriented line through u → v with the left side as a ρ1 + b ρ2 >= c, scaled to |a| + |b| = 1:
// one key for every segment of the line with that orientation.
using LineKey = std::array<Q, 3>;
LineKey left_line(const Point2q& u, const Point2q& v) {
    Q a = u[1] - v[1], b = v[0] - u[0];
    const Q s = abs(a) + abs(b);
    a /= s;
    b /= s;
    return {a, b, Q(a * u[0] + b * u[1])};
}

// The part pair's features that all the given normals pick out: maximisers of n on A, of −n on B.
void common_features(const CompoundRegion& r, const CompoundRegion::Pair& p, const std::vector<size_t>& tight,
                     std::vector<int> out[2]) {
    const Polyhedron& A = r.parts[0][static_cast<size_t>(p.part1)];
    const Polyhedron& B = r.parts[1][static_cast<size_t>(p.part2)];
    for (size_t j = 0; j < tight.size(); ++j) {
        const Vec3z& n = p.constraints[tight[j]].normal;
        const std::vector<int> f[2] = {A.argmax(n), B.argmax(neg(n))};
        for (int i = 0; i < 2; ++i) {
            if (j == 0) {
                out[i] = f[i];
                continue;
            }
            std::vector<int> both;
            std::set_intersection(out[i].begin(), out[i].end(), f[i].begin(), f[i].end(), std::back_inserter(both));
            out[i] = std::move(both);
        }
    }
    if (out[0].empty() || out[1].empty())
        throw std::logic_error("label_boundary: tight normals with no common contact face");
}

int sign_at(const HalfPlane& h, const Point2q& x) { return sgn(Q(h.a * x[0] + h.b * x[1] - h.c)); }

// The pair's contact along the segment x → y of one of its polygon's edges: every constraint
// tight at both ends holds the segment.
PairContact contact_along(const CompoundRegion& r, size_t k, const Point2q& x, const Point2q& y) {
    const CompoundRegion::Pair& p = r.pairs[k];
    PairContact c{k, {}, {}};
    for (size_t j = 0; j < p.constraints.size(); ++j)
        if (sign_at(p.constraints[j], x) == 0 && sign_at(p.constraints[j], y) == 0) c.tight.push_back(j);
    const auto line = std::find_if(c.tight.begin(), c.tight.end(), [&](size_t j) {
        return sgn(p.constraints[j].a) != 0 || sgn(p.constraints[j].b) != 0;
    });
    if (line == c.tight.end()) throw std::logic_error("label_boundary: a pair edge on no constraint's line");
    c.line = *line;
    std::vector<int> f[2];
    common_features(r, p, c.tight, f);
    c.contact.feat1 = std::move(f[0]);
    c.contact.feat2 = std::move(f[1]);
    c.contact.label = {feature_letter(c.contact.feat1.size()), feature_letter(c.contact.feat2.size())};
    return c;
}

// 0..3 when u → v lies on a side of the rectangle (ρ1 = lo1, ρ1 = hi1, ρ2 = lo2, ρ2 = hi2), else −1.
int rect_side(const Point2q& u, const Point2q& v, const Q lo[2], const Q hi[2]) {
    for (int c = 0; c < 2; ++c) {
        if (u[c] == v[c] && u[c] == lo[c]) return 2 * c;
        if (u[c] == v[c] && u[c] == hi[c]) return 2 * c + 1;
    }
    return -1;
}

bool same_label(const BoundaryEdge& x, const BoundaryEdge& y) {
    if (x.bound != y.bound || x.contact.has_value() != y.contact.has_value()) return false;
    return !x.contact || (x.contact->pair == y.contact->pair && x.contact->tight == y.contact->tight);
}

}  // namespace

std::optional<PairContact> pair_contact_at(const CompoundRegion& r, const ExactScene& sc, size_t k, const Point2q& at) {
    const CompoundRegion::Pair& p = r.pairs[k];
    PairContact c{k, {}, {}};
    for (size_t j = 0; j < p.constraints.size(); ++j) {
        const int s = sign_at(p.constraints[j], at);
        if (s < 0) return std::nullopt;
        if (s == 0) c.tight.push_back(j);
    }
    if (c.tight.empty()) return std::nullopt;  // overlapping there
    std::vector<int> f[2];
    common_features(r, p, c.tight, f);
    // The span of the tight normals: one direction, a plane (its normal u) or all of space.
    const Vec3z& n0 = p.constraints[c.tight[0]].normal;
    std::optional<Vec3z> u;
    for (size_t j = 1; j < c.tight.size() && !u; ++j) {
        const Vec3z w = cross(n0, p.constraints[c.tight[j]].normal);
        if (!is_zero(w)) u = w;
    }
    bool full = false;
    if (u)
        for (size_t j : c.tight) full = full || sgn(dot(*u, p.constraints[j].normal)) != 0;
    if (u && !full) {
        const Q rho[2] = {at[0], at[1]};
        const Polyhedron* P[2] = {&r.parts[0][static_cast<size_t>(p.part1)], &r.parts[1][static_cast<size_t>(p.part2)]};
        c.contact = contact_on_line(*u, f, [&](int i, int v) {
            const Vec3q& x = P[i]->points[static_cast<size_t>(v)];
            const Vec3q& s = sc.P[i].seed;
            Vec3q y;
            for (int d = 0; d < 3; ++d) y[d] = s[d] + rho[i] * (x[d] - s[d]);
            return y;
        });
    } else {
        // One normal's faces, or (three independent normals) a vertex of the Minkowski sum: a
        // vertex of each part.
        if (full && (f[0].size() != 1 || f[1].size() != 1))
            throw std::logic_error("label_boundary: a vertex contact on faces");
        c.contact.feat1 = std::move(f[0]);
        c.contact.feat2 = std::move(f[1]);
        c.contact.label = {feature_letter(c.contact.feat1.size()), feature_letter(c.contact.feat2.size())};
    }
    return c;
}

CompoundBoundary label_boundary(const CompoundRegion& r, const ExactScene& sc) {
    const Q* lo = sc.lo;
    const Q* hi = sc.hi;
    // Every pair polygon edge off the rectangle's sides, by its oriented line (the pair's polygon,
    // counter-clockwise, on its left), as the interval [s(u), s(v)] of its ends' positions along
    // the line (s(x) = b x1 − a x2 for the line a ρ1 + b ρ2 = c: increasing along it), sorted by
    // start; `reach`, the largest end among the intervals up to each. A ring edge's pair edges are
    // then found from the last one starting before it ends, back while one can still reach it: the
    // work follows the intervals that meet ring edges, not all the line's intervals for each ring
    // edge (1,000 pair polygons sharing two lines took 9.6 s, quadratically).
    struct PairEdge {
        size_t pair;
        Q s0, s1;
    };
    struct LineEdges {
        std::vector<PairEdge> edges;
        std::vector<Q> reach;
    };
    auto position = [](const LineKey& key, const Point2q& x) { return Q(key[1] * x[0] - key[0] * x[1]); };
    std::map<LineKey, LineEdges> by_line;
    for (size_t k = 0; k < r.pairs.size(); ++k) {
        const std::vector<Point2q>& p = r.pairs[k].polygon;
        if (p.size() < 3) continue;
        for (size_t i = 0; i < p.size(); ++i) {
            const Point2q &u = p[i], &v = p[(i + 1) % p.size()];
            if (rect_side(u, v, lo, hi) >= 0) continue;
            const LineKey key = left_line(u, v);
            by_line[key].edges.push_back({k, position(key, u), position(key, v)});
        }
    }
    for (auto& [key, L] : by_line) {
        std::sort(L.edges.begin(), L.edges.end(),
                  [](const PairEdge& x, const PairEdge& y) { return x.s0 != y.s0 ? x.s0 < y.s0 : x.pair < y.pair; });
        for (size_t j = 0; j < L.edges.size(); ++j)
            L.reach.push_back(j == 0 || L.edges[j].s1 > L.reach.back() ? L.edges[j].s1 : L.reach.back());
    }
    // Each pair polygon's bounding box in doubles, widened past their rounding (region_double is
    // within 2u relative; 2^-40 of the box's size and of its coordinates' size is far more): a
    // pair touching at a point has it in its polygon, so in its box. (The union is formed of at
    // most kMaxUnionPolygons polygons with area, but a switch point asks every built pair.)
    // A box or point with a coordinate that has no such double (region_double: not a number) is
    // near everything, and the exact test decides.
    struct Box {
        bool any = false;
        double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
        bool near(double x, double y) const {
            if (!any) return false;
            if (std::isnan(x0 + x1 + y0 + y1 + x + y)) return true;
            return x0 <= x && x <= x1 && y0 <= y && y <= y1;
        }
    };
    std::vector<Box> boxes(r.pairs.size());
    for (size_t k = 0; k < r.pairs.size(); ++k) {
        Box& b = boxes[k];
        for (const Point2q& v : r.pairs[k].polygon) {
            const double x = filter::region_double(v[0]), y = filter::region_double(v[1]);
            if (!b.any) b = {true, x, x, y, y};
            if (std::isnan(x + y)) b.x0 = std::nan("");
            if (std::isnan(b.x0)) continue;
            b.x0 = std::min(b.x0, x), b.x1 = std::max(b.x1, x), b.y0 = std::min(b.y0, y), b.y1 = std::max(b.y1, y);
        }
        if (!b.any || std::isnan(b.x0)) continue;
        const double px = 0x1p-40 * (b.x1 - b.x0 + std::fabs(b.x0) + std::fabs(b.x1)) + 0x1p-1000;
        const double py = 0x1p-40 * (b.y1 - b.y0 + std::fabs(b.y0) + std::fabs(b.y1)) + 0x1p-1000;
        b.x0 -= px, b.x1 += px, b.y0 -= py, b.y1 += py;
    }
    CompoundBoundary out;
    auto label_ring = [&](size_t piece, int hole, const std::vector<Point2q>& ring) {
        BoundaryRing br{piece, hole, {}};
        for (size_t i = 0; i < ring.size(); ++i) {
            const Point2q &u = ring[i], &v = ring[(i + 1) % ring.size()];
            const int side = rect_side(u, v, lo, hi);
            if (side >= 0) {
                BoundaryEdge e{u, v, side, std::nullopt};
                br.edges.push_back(std::move(e));
                continue;
            }
            // Cut u → v where the pair edges on its line begin or end, and label each piece by the
            // first pair (in r.pairs order) whose edge holds it.
            const LineKey key = left_line(u, v);
            const auto it = by_line.find(key);
            if (it == by_line.end()) throw std::logic_error("label_boundary: a ring edge on no pair edge");
            const LineEdges& L = it->second;
            const Q su = position(key, u), sv = position(key, v);
            std::vector<const PairEdge*> near;  // the pair edges that overlap (su, sv)
            size_t j = static_cast<size_t>(std::lower_bound(L.edges.begin(), L.edges.end(), sv,
                                                            [](const PairEdge& e, const Q& x) { return e.s0 < x; }) -
                                           L.edges.begin());
            while (j-- > 0 && L.reach[j] > su)
                if (L.edges[j].s1 > su) near.push_back(&L.edges[j]);
            std::vector<Q> cuts{su, sv};
            for (const PairEdge* e : near)
                for (const Q& t : {e->s0, e->s1})
                    if (t > su && t < sv) cuts.push_back(t);
            std::sort(cuts.begin(), cuts.end());
            cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
            const Q wx = v[0] - u[0], wy = v[1] - u[1], len = sv - su;
            auto at = [&](const Q& t) {
                const Q f = (t - su) / len;
                return Point2q{u[0] + f * wx, u[1] + f * wy};
            };
            for (size_t c = 0; c + 1 < cuts.size(); ++c) {
                const PairEdge* found = nullptr;
                for (const PairEdge* e : near)
                    if (e->s0 <= cuts[c] && e->s1 >= cuts[c + 1] && (!found || e->pair < found->pair)) found = e;
                if (!found) throw std::logic_error("label_boundary: a ring edge piece on no pair edge");
                const Point2q x = at(cuts[c]), y = at(cuts[c + 1]);
                BoundaryEdge e{x, y, -1, contact_along(r, found->pair, x, y)};
                if (!br.edges.empty() && same_label(br.edges.back(), e) && br.edges.back().to == x)
                    br.edges.back().to = y;
                else
                    br.edges.push_back(std::move(e));
            }
        }
        // A ring's last and first edges with one label (the ring's first vertex inside a run).
        if (br.edges.size() > 1 && same_label(br.edges.back(), br.edges.front())) {
            br.edges.front().from = br.edges.back().from;
            br.edges.pop_back();
        }
        // The switch points: vertices between two contact edges whose labels differ.
        for (size_t i = 0; i < br.edges.size() && br.edges.size() > 1; ++i) {
            const BoundaryEdge &prev = br.edges[(i + br.edges.size() - 1) % br.edges.size()], &cur = br.edges[i];
            if (!prev.contact || !cur.contact || same_label(prev, cur)) continue;
            CompoundSwitch s{cur.from, prev.contact->pair != cur.contact->pair, {}};
            const double x = filter::region_double(s.at[0]), y = filter::region_double(s.at[1]);
            for (size_t k = 0; k < r.pairs.size(); ++k)
                if (boxes[k].near(x, y))
                    if (auto pc = pair_contact_at(r, sc, k, s.at)) s.contacts.push_back(std::move(*pc));
            out.switches.push_back(std::move(s));
        }
        out.rings.push_back(std::move(br));
    };
    for (size_t k = 0; k < r.region.size(); ++k) {
        label_ring(k, -1, r.region[k].outer);
        for (size_t h = 0; h < r.region[k].holes.size(); ++h) label_ring(k, static_cast<int>(h), r.region[k].holes[h]);
    }
    return out;
}

}  // namespace scalecert::internal
