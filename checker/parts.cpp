#include "parts.hpp"

#include "json.hpp"
#include "numbers.hpp"

#include <numeric>

namespace scalecert_check {
CompoundScene read_compound_scene(Context& cx, const J& sj) {
    CompoundScene cs;
    shape(cx, sj, "scene", {"P1", "P2", "I1", "I2"});
    for (int i = 0; i < 2; ++i) {
        const std::string w = std::string("scene.") + kPoly[i];
        const J& p = at(sj, kPoly[i]);
        shape(cx, p, w, {"parts", "seed"});
        const J& parts = at(p, "parts");
        cx.claim(parts.is_array() && !parts.empty(), w + ".parts is a nonempty list");
        if (parts.size() > kMaxCompoundParts)
            throw Unreadable{w + " has more than " + std::to_string(kMaxCompoundParts) +
                             " parts (scalecert's own limit)"};
        auto obj = std::make_shared<CompoundObject>();
        for (size_t k = 0; k < parts.size(); ++k) {
            const std::string wk = w + ".parts[" + std::to_string(k) + "]";
            shape(cx, parts[k], wk, {"vertices"}, {"radius"});
            // Radii: on every part of both objects, or on none.
            const bool first = i == 0 && k == 0;
            if (first && parts[k].contains("radius")) cs.r[0].reserve(parts.size());
            const bool rounded = first ? parts[k].contains("radius") : !cs.r[0].empty();
            cx.claim(parts[k].contains("radius") == rounded,
                     wk + (rounded ? " has a radius (every part has one when any has)"
                                   : " has no radius (no part has one)"));
            if (rounded) {
                const Q r = num(cx, at(parts[k], "radius"), wk + ".radius");
                cx.claim(sgn(r) >= 0, wk + ".radius is >= 0");
                cs.r[i].push_back(r);
            }
            const J& vs = at(parts[k], "vertices");
            cx.claim(Vertices::is_list(cx, vs) && Vertices::length(cx, vs) > 0, wk + ".vertices is a nonempty list");
            Vertices v(cx, vs, wk + ".vertices");
            obj->part.push_back(v.scan(cx, wk));
        }
        obj->index(cx);
        cs.obj[i] = std::move(obj);
        cs.s[i] = point(cx, at(p, "seed"), w + ".seed");
    }
    read_ranges(cx, cs.lo, cs.hi, sj);
    // Each part spans 3 dimensions, as scalecert requires of its input (the claims would hold for
    // flat parts too: the file states a scene the engine reads); with a radius > 0 it may be flat.
    for (int i = 0; i < 2; ++i)
        for (size_t k = 0; k < cs.parts(i); ++k) {
            if (cs.rounded() && sgn(cs.r[i][k]) > 0) continue;
            std::vector<int> idx(cs.part(i, k).size());
            std::iota(idx.begin(), idx.end(), 0);
            cx.claim(affine_dim(cx, cs.part(i, k), idx) == 3,
                     std::string("scene.") + kPoly[i] + ".parts[" + std::to_string(k) + "] spans 3 dimensions");
        }
    return cs;
}

Scene CompoundScene::pair(Context& cx, size_t a, size_t b) const {
    Scene sc;
    const size_t k[2] = {a, b};
    for (int i = 0; i < 2; ++i) {
        sc.scan[i] = obj[i]->part[k[i]];
        sc.s[i] = s[i];
        sc.lo[i] = lo[i];
        sc.hi[i] = hi[i];
        if (rounded()) sc.r[i] = r[i][k[i]];
    }
    sc.rounded = rounded();
    sc.prepare(cx);
    return sc;
}

void CompoundObject::index(Context& cx) {
    flat.assign(part.size(), Flat{});
    size_t n = 0;
    for (const auto& P : part) n += P->machine() ? P->size() : 0;
    cx.spend(100.0 * static_cast<double>(part.size()) + 3.0 * static_cast<double>(n));
    for (auto& c : x) {
        c.clear();
        c.reserve(n);
    }
    for (size_t k = 0; k < part.size(); ++k) {
        const Scan& P = *part[k];
        Flat& f = flat[k];
        if (mpz_fits_ulong_p(P.D().get_mpz_t())) f.den = mpz_get_ui(P.D().get_mpz_t());
        if (!P.machine()) continue;
        f.begin = x[0].size();
        for (int c = 0; c < 3; ++c) x[c].insert(x[c].end(), P.coords(c), P.coords(c) + P.size());
        f.end = x[0].size();
        f.bits = P.bits();
    }
}

// The running maximum is held as best/bd (bd a part's denominator), a part's as v/D: v/D > best/bd
// iff v·bd > best·D, both denominators positive (of integer parts, D = bd = 1: v > best). A
// machine part with a machine direction is scanned in the object's arrays under the bounds of
// argmax() (scan.hpp), any other by its own scan. Counted before each product by its operands'
// limbs.
Q CompoundScene::top(Context& cx, int i, const Z3& u, size_t first, size_t last) const {
    mpz_class best, bd, v, l, r;
    const Direction d(u);
    const CompoundObject& o = *obj[i];
    const int64_t *X = o.x[0].data(), *Y = o.x[1].data(), *Z = o.x[2].data();
    for (size_t k = first; k <= last; ++k) {
        const CompoundObject::Flat& f = o.flat[k];
        if (d.small && f.end > f.begin && f.bits + d.bits <= 61) {
            cx.spend(20 + static_cast<double>(f.end - f.begin));
            set64(v, max_dot64(X, Y, Z, f.begin, f.end, d.w));
        } else {
            cx.spend(1000);  // the part's own arrays, wherever they lie (measured about 1 µs)
            o.part[k]->max_dot(cx, d, v);
        }
        bool higher = k == first;
        if (!higher && f.den == 1 && bd == 1) {
            higher = v > best;
        } else if (!higher && f.den != 0) {
            cx.spend(40 + 2 * (1 + limbs(v)) * (1 + limbs(bd)) + 4 * (1 + limbs(best)));
            l = v * bd;
            mpz_mul_ui(r.get_mpz_t(), best.get_mpz_t(), f.den);
            higher = l > r;
        } else if (!higher) {
            const mpz_class& D = o.part[k]->D();
            cx.spend(400 + 2 * (1 + limbs(v)) * (1 + limbs(bd)) + 2 * (1 + limbs(best)) * (1 + limbs(D)));
            l = v * bd;
            r = best * D;
            higher = l > r;
        }
        if (higher) {
            mpz_swap(best.get_mpz_t(), v.get_mpz_t());
            if (f.den != 0)
                mpz_set_ui(bd.get_mpz_t(), f.den);
            else
                bd = o.part[k]->D();
        }
    }
    cx.spend_ops(1, limbs(best) + limbs(bd));
    Q q(best, bd);
    q.canonicalize();
    return q;
}

CompoundScene CompoundScene::posed(Context& cx, const std::array<std::optional<Pose>, 2>& pose) const {
    CompoundScene out;
    for (int i = 0; i < 2; ++i) {
        out.r[i] = r[i];
        out.s[i] = posed_point(s[i], pose[i]);
        out.lo[i] = lo[i];
        out.hi[i] = hi[i];
        if (!pose[i]) {
            out.obj[i] = obj[i];
            continue;
        }
        // a part's new scan and its arrays (measured about 3 µs a part of 4 vertices)
        cx.spend(2500.0 * static_cast<double>(parts(i)));
        auto moved = std::make_shared<CompoundObject>();
        for (size_t k = 0; k < parts(i); ++k)
            moved->part.push_back(
                posed_scan(cx, obj[i]->part[k], *pose[i], std::string(kPoly[i]) + "'s part " + std::to_string(k)));
        moved->index(cx);
        out.obj[i] = std::move(moved);
    }
    return out;
}

namespace {
// [first, last] of a part range, 0 <= first <= last < n.
std::array<size_t, 2> part_range(Context& cx, const J& j, size_t n, const std::string& where) {
    cx.claim(j.is_array() && j.size() == 2, where + " is [first, last]");
    const size_t a = index(cx, j[0], n, where + "[0]"), b = index(cx, j[1], n, where + "[1]");
    cx.claim(a <= b, where + " has first <= last");
    return {a, b};
}
}  // namespace

PairCover::PairCover(Context& cx, size_t m, size_t n) : m_(m), n_(n) {
    cx.spend(static_cast<double>(m) * static_cast<double>(n) / 8);
    covered_.assign(m * n, false);
}

std::array<std::array<size_t, 2>, 2> PairCover::next(Context& cx, const J& entry, const std::string& w,
                                                     const char* noun) {
    const std::array<size_t, 2> ra = part_range(cx, at(entry, "P1_parts"), m_, w + ".P1_parts"),
                                rb = part_range(cx, at(entry, "P2_parts"), n_, w + ".P2_parts");
    cx.claim(blocks_ == 0 || std::array<size_t, 2>{ra[0], rb[0]} > previous_,
             w + " comes after the " + noun + " before it (by first P1 part, then first P2 part)");
    ++blocks_;
    previous_ = {ra[0], rb[0]};
    cx.spend(3 * static_cast<double>(ra[1] - ra[0] + 1) * static_cast<double>(rb[1] - rb[0] + 1));  // 2.4 ns a pair
    for (size_t a = ra[0]; a <= ra[1]; ++a)
        for (size_t b = rb[0]; b <= rb[1]; ++b) {
            if (covered_[a * n_ + b])  // (the message only when it fails: a block may cover 10^8 pairs)
                cx.claim(false,
                         w + " covers the pair (" + std::to_string(a) + ", " + std::to_string(b) + ") a second time");
            covered_[a * n_ + b] = true;
            ++count_;
        }
    return {ra, rb};
}

void PairCover::complete(Context& cx, const std::string& what) const {
    cx.claim(count_ == m_ * n_, what + " (" + std::to_string(count_) + " of " + std::to_string(m_ * n_) + ")");
}
}  // namespace scalecert_check
