// Stage 1, compact: the points of one polyhedron as machine integers over one shared positive
// scale (a power of ten for decimal text, the common denominator otherwise). Large inputs are
// read straight into this form: 24 bytes a point instead of three GMP rationals.
#pragma once
#include "io/scene.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace scalecert::internal {

// |coordinate × scale| ≤ kMaxIntCoord: exact as a double, and a product with a 64-bit integer
// fits in 117 bits.
constexpr std::int64_t kMaxIntCoord = std::int64_t{1} << 53;

struct IntPoints {
    std::vector<std::int64_t> x;  // 3 per point: the point times scale
    Z scale = 1;                  // > 0
    size_t size() const { return x.size() / 3; }
    const std::int64_t* at(size_t k) const { return &x[3 * k]; }
    Vec3q point(size_t k) const;  // exact: x / scale
    Vec3q mean() const;           // the mean of all points (the default seed)
};

// The points in integers when the common denominator times every coordinate stays within
// kMaxIntCoord; none otherwise.
std::optional<IntPoints> int_points(const std::vector<Vec3q>& pts);
std::vector<Vec3q> q_points(const IntPoints& p);

// The vertices of an OFF file's text in integers, when every coordinate is a plain decimal
// ([+-]digits[.digits][e[+-]digits], at most 18 significant digits) that `numbers` reads as
// written (under Double and Float32: a decimal that is a double, a float, exactly) and the file is
// otherwise as the full reader expects (no comments among the header and vertices, 4 to
// kMaxPoints vertices). None means "read it with parse_mesh" (which gives the same points, or the
// error).
std::optional<IntPoints> parse_off_fast(const std::string& text, Numbers numbers);
std::optional<IntPoints> parse_off_fast(const char* data, size_t size, Numbers numbers);
// The same on a file, mapped into memory rather than copied; none also when the file is not a
// regular file of at most kMaxSceneBytes bytes (the full reader then reads it, or words the error).
std::optional<IntPoints> read_off_fast(const std::string& path, Numbers numbers);

// A scene whose polyhedra are IntPoints (what the scan path reads).
struct CompactScene {
    IntPoints P[2];
    Vec3q seed[2];
    bool seed_given[2] = {false, false};
    Q lo[2], hi[2];
};
// The scene in compact form, when both polyhedra fit IntPoints (never for objects made of parts).
std::optional<CompactScene> compact_scene(const ExactScene& sc);
// A scene file's text in compact form, when it has the plain shape {"P1": {"vertices": [...],
// "seed": [...]}, "P2": ..., "I1": [lo, hi], "I2": [lo, hi]} with JSON numbers (decimals as in
// parse_off_fast for the vertices) and passes the reader's checks; none means "read it with
// parse_scene_text" (the same scene, or the error). read_scene_fast maps the file.
// Under Double and Float32, every number must be what it reads as (none otherwise, as above).
std::optional<CompactScene> parse_scene_fast(const char* data, size_t size, Numbers numbers);
std::optional<CompactScene> read_scene_fast(const std::string& path, Numbers numbers);
// Two OFF files (P1, P2) read straight into compact form, both at once (a thread each), with the
// ranges and the seeds given (a seed not given: the mean of its points). None when either file is
// not read by read_off_fast, or a range is not 0 < lo <= hi: the full reader then reads the
// files, or words the error in its own order.
std::optional<CompactScene> compact_from_off(const std::string path[2], const Q lo[2], const Q hi[2],
                                             const std::optional<Vec3q> seed[2], Numbers numbers);
// Back to the exact scene (for the hull path), with the same seeds.
ExactScene full_scene(const CompactScene& cs);

}  // namespace scalecert::internal
