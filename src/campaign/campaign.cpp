#include "campaign/campaign.hpp"

#include <scalecert/scalecert.hpp>

#include "certify/golden.hpp"
#include "certify/region_certificate.hpp"
#include "session/engine.hpp"
#include "io/files.hpp"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace scalecert::internal {

// ---- SHA-256 (FIPS 180-4), for the run folder's content hashes ------------------------------
namespace {
constexpr std::uint32_t kK[64] = {
    0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
    0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
    0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
    0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
    0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
    0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
    0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
    0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2};
inline std::uint32_t rotr(std::uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }
}  // namespace

std::string sha256_hex(const std::string& bytes) {
    std::uint32_t h[8] = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                          0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
    std::string m = bytes;
    const std::uint64_t bits = static_cast<std::uint64_t>(bytes.size()) * 8;
    m += static_cast<char>(0x80);
    while (m.size() % 64 != 56) m += '\0';
    for (int i = 7; i >= 0; --i) m += static_cast<char>((bits >> (8 * i)) & 0xff);
    for (size_t off = 0; off < m.size(); off += 64) {
        std::uint32_t w[64];
        for (int i = 0; i < 16; ++i) {
            const auto* p = reinterpret_cast<const unsigned char*>(m.data() + off + 4 * i);
            w[i] = std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
        }
        for (int i = 16; i < 64; ++i) {
            const std::uint32_t s0 = rotr(w[i - 15], 7) ^ rotr(w[i - 15], 18) ^ (w[i - 15] >> 3);
            const std::uint32_t s1 = rotr(w[i - 2], 17) ^ rotr(w[i - 2], 19) ^ (w[i - 2] >> 10);
            w[i] = w[i - 16] + s0 + w[i - 7] + s1;
        }
        std::uint32_t a = h[0], b = h[1], c = h[2], d = h[3], e = h[4], f = h[5], g = h[6], hh = h[7];
        for (int i = 0; i < 64; ++i) {
            const std::uint32_t t1 =
                hh + (rotr(e, 6) ^ rotr(e, 11) ^ rotr(e, 25)) + ((e & f) ^ (~e & g)) + kK[i] + w[i];
            const std::uint32_t t2 = (rotr(a, 2) ^ rotr(a, 13) ^ rotr(a, 22)) + ((a & b) ^ (a & c) ^ (b & c));
            hh = g, g = f, f = e, e = d + t1, d = c, c = b, b = a, a = t1 + t2;
        }
        h[0] += a, h[1] += b, h[2] += c, h[3] += d, h[4] += e, h[5] += f, h[6] += g, h[7] += hh;
    }
    char out[65];
    for (int i = 0; i < 8; ++i) std::snprintf(out + 8 * i, 9, "%08x", h[i]);
    return std::string(out, 64);
}

// ---- planning ----------------------------------------------------------------------------------

void validate(const CampaignArgs& a) {
    std::vector<std::string> files;
    for (const std::string& p : a.scenes)
        if (!a.given.count(p)) files.push_back(p);
    note_inputs(files);  // before any output: none may replace a scene, however they are ordered
    if (a.golden) {
        if (a.family.empty() && a.scenes.empty()) throw InputError("golden: give SCENES, or --family");
        if (!a.family.empty()) family_description(a.family);
        if (!a.family.empty() && (a.count < 1 || a.count > kMaxGoldenCount))
            throw InputError("golden: the count of scenes must be from 1 to 10^7 (got " + std::to_string(a.count) +
                             ")");
        const Q eps = parse_exact(a.eps_text);
        if (sgn(eps) <= 0) throw InputError("--eps must be > 0");
        validate(a.points);
        std::set<std::string> stems;
        for (const std::string& p : a.scenes)
            if (!stems.insert(golden_stem(p)).second)
                throw InputError("golden: two scenes named " + in_quotes(golden_stem(p)) +
                                 " (their files would be the same)");
        return;
    }
    if (!a.family.empty()) family_description(a.family);
    if (!a.family.empty() && a.sweep_to < a.sweep_from) throw InputError("--sweep-to must be >= --sweep");
    if (!a.auditor.run)
        throw InputError(
            "audit: this build has no floating-point baselines (configure with SCALECERT_BUILD_BASELINES=ON)");
    const std::vector<std::string> known = a.auditor.method_names();
    for (const std::string& m : a.methods)
        if (m != "grid" && m.rfind(kCommandMethod, 0) != 0 && std::find(known.begin(), known.end(), m) == known.end())
            throw InputError("--methods: unknown method " + in_quotes(m));
    if (a.scenes.empty() && a.family.empty() && !a.atlas)
        throw InputError("audit: no scenes (give SCENES, --family with --sweep, or --atlas)");
}

std::vector<Shard> plan(const CampaignArgs& a) {
    std::vector<Shard> out;
    const int size = a.shard_size > 0 ? a.shard_size : a.golden ? 16 : 4;
    auto ranges = [&](int k, int atlas = -1) {
        for (int first = 0; first < a.count; first += size) {
            Shard s{static_cast<int>(out.size())};
            s.k = k;
            s.atlas = atlas;
            s.first = first;
            s.last = std::min(a.count, first + size);
            out.push_back(s);
        }
    };
    for (size_t i = 0; i < a.scenes.size(); ++i) {
        Shard s{static_cast<int>(out.size())};
        s.scene_file = static_cast<int>(i);
        out.push_back(s);
    }
    if (a.golden && !a.family.empty()) ranges(0);
    if (!a.golden && !a.family.empty())
        for (int k = a.sweep_from; k <= a.sweep_to; ++k) ranges(k);
    if (!a.golden && a.atlas)
        for (size_t c = 0; c < atlas_classes().size(); ++c)
            for (int k : atlas_classes()[c].ks) ranges(k, static_cast<int>(c));
    return out;
}

std::uint64_t scene_seed(std::uint64_t run_seed, int k, int i) {
    Rng r(run_seed);
    return Rng(r.next() ^ (static_cast<std::uint64_t>(k) << 32) ^ static_cast<std::uint64_t>(i)).next();
}

// ---- running a shard ---------------------------------------------------------------------------

namespace {

// Doubles as JSON numbers, or as "nan", "inf", "-inf" (a grid that never crosses ρ1 = ρ2 has no
// growth estimate): JSON has no number for them, and the row must come back bit for bit.
Json num_json(double x) {
    if (std::isfinite(x)) return x;
    return std::isnan(x) ? "nan" : x > 0 ? "inf" : "-inf";
}
double num_of(const Json& j) {
    if (j.is_string()) return std::strtod(j.get<std::string>().c_str(), nullptr);
    return j.get<double>();
}

Json row_json(const AuditRow& r) {
    return Json{
        {"scene", r.scene},
        {"method", r.method},
        {"eps", to_exact_string(r.eps)},
        {"queries", r.queries},
        {"false_separated", r.false_separated},
        {"false_overlapping", r.false_overlapping},
        {"false_touching", r.false_touching},
        {"seconds_per_query", num_json(r.seconds_per_query)},
        {"has_curve", r.has_curve},
        {"grid_n", r.grid_n},
        {"growth_error", num_json(r.growth_error)},
        {"max_junction_error", num_json(r.max_junction_error)},
        {"seconds_per_curve", num_json(r.seconds_per_curve)},
        {"exact_junctions", r.exact_junctions},
        {"junctions_found", r.junctions_found},
        {"junctions_missed", r.junctions_missed},
        {"junctions_merged", r.junctions_merged},
        {"distances", r.distances},
        {"depths", r.depths},
        {"closest_outside", r.closest_outside},
        {"contacts_apart", r.contacts_apart},
        {"distance_err_median", num_json(r.distance_err_median)},
        {"distance_err_max", num_json(r.distance_err_max)},
        {"depth_err_median", num_json(r.depth_err_median)},
        {"depth_err_max", num_json(r.depth_err_max)},
        {"direction_err_max", num_json(r.direction_err_max)},
        {"by_distance",
         [&] {
             Json a = Json::array();
             for (const AuditRow::ByDistance& b : r.by_distance)
                 a.push_back(Json::array({b.k, b.pairs, b.wrong, b.touching}));
             return a;
         }()},
        {"on_boundary",
         r.on_boundary ? Json::array({r.on_boundary->points, r.on_boundary->touching, r.on_boundary->said_separated,
                                      r.on_boundary->said_touching, r.on_boundary->said_overlapping,
                                      r.on_boundary->moved, r.on_boundary->moved_wrong})
                       : Json()},
        {"failures",
         [&] {
             Json a = Json::array();
             for (const AuditRow::Failure& f : r.failures) {
                 Json x = Json::array({num_json(f.rho1), num_json(f.rho2), f.said, static_cast<int>(f.exact)});
                 if (f.said == AuditRow::kSaidNoAnswer) x.push_back(Json::array({f.reason, f.claim}));
                 a.push_back(std::move(x));
             }
             return a;
         }()},
        {"not_answered", r.not_answered},
        {"not_run", r.not_run},
        {"extra_claims", r.extra_claims},
        {"measures_wrong", r.measures_wrong},
        {"measure_failures",
         [&] {
             Json a = Json::array();
             for (const AuditRow::MeasureFailure& f : r.measure_failures)
                 a.push_back(Json::array({num_json(f.rho1), num_json(f.rho2), f.depth, num_json(f.value),
                                          num_json(f.error), f.part1, f.part2}));
             return a;
         }()},
        {"settings", [&] {
             Json a = Json::array();
             for (const auto& [key, value] : r.settings) a.push_back(Json::array({key, num_json(value)}));
             return a;
         }()}};
}

// An exact verdict as a shard writes it (its enum value), checked.
Verdict verdict_code(int v) {
    if (v < 0 || v > 2) throw std::out_of_range("a verdict code outside 0..2");
    return static_cast<Verdict>(v);
}

AuditRow row_of(const Json& j) {
    AuditRow r;
    r.scene = j.at("scene").get<std::string>();
    r.method = j.at("method").get<std::string>();
    r.eps = parse_exact(j.at("eps").get<std::string>());
    r.queries = j.at("queries").get<long>();
    r.false_separated = j.at("false_separated").get<long>();
    r.false_overlapping = j.at("false_overlapping").get<long>();
    r.false_touching = j.at("false_touching").get<long>();
    r.seconds_per_query = num_of(j.at("seconds_per_query"));
    r.has_curve = j.at("has_curve").get<bool>();
    r.grid_n = j.at("grid_n").get<int>();
    r.growth_error = num_of(j.at("growth_error"));
    r.max_junction_error = num_of(j.at("max_junction_error"));
    r.seconds_per_curve = num_of(j.at("seconds_per_curve"));
    r.exact_junctions = j.at("exact_junctions").get<int>();
    r.junctions_found = j.at("junctions_found").get<int>();
    r.junctions_missed = j.at("junctions_missed").get<int>();
    r.junctions_merged = j.at("junctions_merged").get<int>();
    r.distances = j.at("distances").get<long>();
    r.depths = j.at("depths").get<long>();
    r.closest_outside = j.at("closest_outside").get<long>();
    r.contacts_apart = j.at("contacts_apart").get<long>();
    r.distance_err_median = num_of(j.at("distance_err_median"));
    r.distance_err_max = num_of(j.at("distance_err_max"));
    r.depth_err_median = num_of(j.at("depth_err_median"));
    r.depth_err_max = num_of(j.at("depth_err_max"));
    r.direction_err_max = num_of(j.at("direction_err_max"));
    for (const Json& b : j.at("by_distance"))
        r.by_distance.push_back({b.at(0).get<int>(), b.at(1).get<long>(), b.at(2).get<long>(), b.at(3).get<long>()});
    if (j.contains("on_boundary") && !j.at("on_boundary").is_null()) {
        const Json& o = j.at("on_boundary");
        r.on_boundary =
            AuditRow::OnBoundary{o.at(0).get<long>(), o.at(1).get<long>(), o.at(2).get<long>(), o.at(3).get<long>(),
                                 o.at(4).get<long>(), o.at(5).get<long>(), o.at(6).get<long>()};
    }
    if (j.contains("failures"))
        for (const Json& f : j.at("failures")) {
            r.failures.push_back(
                {num_of(f.at(0)), num_of(f.at(1)), f.at(2).get<int>(), verdict_code(f.at(3).get<int>())});
            if (f.size() > 4) {
                r.failures.back().reason = f.at(4).at(0).get<std::string>();
                r.failures.back().claim = f.at(4).at(1).get<std::string>();
            }
        }
    if (j.contains("not_answered")) r.not_answered = j.at("not_answered").get<long>();
    if (j.contains("not_run")) r.not_run = j.at("not_run").get<std::string>();
    if (j.contains("extra_claims")) r.extra_claims = j.at("extra_claims").get<long>();
    r.measures_wrong = j.at("measures_wrong").get<long>();
    for (const Json& f : j.at("measure_failures"))
        r.measure_failures.push_back({num_of(f.at(0)), num_of(f.at(1)), f.at(2).get<bool>(), num_of(f.at(3)),
                                      num_of(f.at(4)), f.at(5).get<int>(), f.at(6).get<int>()});
    if (j.contains("settings"))
        for (const Json& x : j.at("settings")) r.settings.push_back({x.at(0).get<std::string>(), num_of(x.at(1))});
    return r;
}

// A golden output file's bytes, or "" when it is missing or not a regular file (its shard is then
// redone, and writing it refuses anything but a regular file). Never blocks on a planted FIFO.
std::string slurp_or_empty(const std::string& path) {
    try {
        return read_regular_file(path, "golden output file", kMaxRunFileBytes);
    } catch (const InputError&) {
        return "";
    }
}

// Runs f with every file it reads recorded as [path, SHA-256 of the bytes read], in order.
template <class F>
Json reading(F&& f) {
    Json files = Json::array();
    InputObserver watch([&](const std::string& path, const std::string& bytes) {
        files.push_back(Json::array({path, sha256_hex(bytes)}));
        note_inputs({path});  // no output of the run may replace it
    });
    f();
    return files;
}

}  // namespace

std::string golden_stem(const std::string& path) {
    std::string b = path.substr(path.find_last_of('/') + 1);
    if (b.size() > 5 && b.compare(b.size() - 5, 5, ".json") == 0) b.resize(b.size() - 5);
    // A scene golden wrote (NAME.scene.json) gives NAME again.
    if (b.size() > 6 && b.compare(b.size() - 6, 6, ".scene") == 0) b.resize(b.size() - 6);
    return b;
}

std::vector<std::pair<std::string, std::string>> golden_files(const std::string& stem, const ExactScene& s,
                                                              const GoldenPoints& points,
                                                              const std::function<void(Json&)>& fields) {
    GoldenAnswers a = open_engine(std::make_shared<const ExactScene>(s), stem)->golden(points);
    Json j = std::move(a.curve);
    fields(j);
    j["queries"] = std::move(a.queries);
    return {{stem + ".scene.json", dump(scene_file_json(s))},
            {stem + ".golden.json", dump(j)},
            {stem + ".golden.csv", a.csv},
            {stem + ".golden.rational.csv", a.rational_csv}};
}

std::vector<std::pair<std::string, std::string>> golden_scene(const std::string& family, int i,
                                                              std::uint64_t scene_seed, std::uint64_t run_seed,
                                                              const Q& eps, const GoldenPoints& points) {
    Rng g(scene_seed);
    const ExactScene s = make_family_scene(family, eps, g);
    return golden_files(family + "-" + std::to_string(i), s, points, [&](Json& j) {
        j["family"] = family;
        j["eps"] = to_exact_string(eps);
        j["index"] = i;
        j["seed"] = std::to_string(run_seed);
    });
}

namespace {
// Where --failures keeps a family scene with wrong verdicts: NAME.eps-P_Q.scene.json (ε = P/Q:
// a sweep audits scene NAME at several ε, each a different scene).
std::string family_scene_file(const std::string& dir, const std::string& name, const Q& eps) {
    std::string e = to_exact_string(eps);
    std::replace(e.begin(), e.end(), '/', '_');
    return dir + "/" + name + ".eps-" + e + ".scene.json";
}
}  // namespace

std::string run_shard(const CampaignArgs& a, const Shard& s) {
    Json j;
    j["shard"] = s.index;
    if (a.golden && s.scene_file >= 0) {  // a scene of the user's: its golden data beside its own name
        const std::string& p = a.scenes[static_cast<size_t>(s.scene_file)];
        ExactScene sc;
        j["inputs"] = reading([&] { sc = load_scene(p, a.opt); });
        Json files = Json::array();
        std::vector<std::pair<std::string, std::string>> out;
        try {
            out = golden_files(golden_stem(p), sc, a.points, [&](Json& g) {
                // The scene's copy beside it (NAME.scene.json), not the path as typed: the same
                // bytes however the path was spelled, and wherever the files were written.
                g["scene_file"] = golden_stem(p) + ".scene.json";
            });
        } catch (const InputError& e) {
            // A scene read well whose answers pass a limit (its judgements' work, a region's union
            // not formed): no files for it, said when the run ends, and the other scenes go on.
            j["not_written"] = Json::array({p, e.what()});
        }
        for (const auto& [name, text] : out) {
            write_file_atomically(a.dir + "/" + name, text);
            files.push_back(Json::array({name, sha256_hex(text)}));
        }
        j["files"] = files;
        return dump(j);
    }
    if (a.golden) {
        const Q eps = parse_exact(a.eps_text);
        Json files = Json::array();
        for (int i = s.first; i < s.last; ++i)
            for (const auto& [name, text] :
                 golden_scene(a.family, i, scene_seed(a.seed, 0, i), a.seed, eps, a.points)) {
                write_file_atomically(a.dir + "/" + name, text);
                files.push_back(Json::array({name, sha256_hex(text)}));
            }
        j["files"] = files;
        return dump(j);
    }
    std::vector<AuditRow> rows;
    if (s.scene_file >= 0) {
        const std::string& p = a.scenes[static_cast<size_t>(s.scene_file)];
        ExactScene sc;
        // The scene file and the meshes it names, as read: a resumed run checks them against the
        // run's inputs, so that no shard computed from older contents is merged.
        const auto given = a.given.find(p);
        if (given != a.given.end()) {  // read already (its meshes noted as inputs then)
            sc = given->second;
            if (!a.failures.empty())
                write_file_atomically(a.failures + "/" + p + ".scene.json", dump(scene_file_json(sc)));
        } else {
            j["inputs"] = reading([&] { sc = load_scene(p, a.opt); });  // its errors name the file already
        }
        try {
            rows = a.auditor.run(p, sc, Q(0), a.methods, a.grid, a.by_distance, a.measures, a.settings);
        } catch (const InputError& e) {
            throw InputError(p + ": " + e.what());
        }
    } else {
        const Q eps(1, Z(1) << s.k);
        const std::string& family = s.atlas >= 0 ? atlas_classes()[static_cast<size_t>(s.atlas)].family : a.family;
        for (int i = s.first; i < s.last; ++i) {
            Rng g(scene_seed(a.seed, s.k, i));
            const std::string name = family + "-" + std::to_string(i);
            const ExactScene sc = make_family_scene(family, eps, g);
            auto r = a.auditor.run(name, sc, eps, a.methods, a.grid, a.by_distance, a.measures, a.settings);
            // A family scene has no file: with --failures, the reproducers get one.
            if (!a.failures.empty() && std::any_of(r.begin(), r.end(), [](const AuditRow& x) {
                    return !x.failures.empty() || !x.measure_failures.empty();
                }))
                write_file_atomically(family_scene_file(a.failures, name, eps), dump(scene_file_json(sc)));
            rows.insert(rows.end(), r.begin(), r.end());
        }
    }
    Json rj = Json::array();
    for (const AuditRow& r : rows) rj.push_back(row_json(r));
    j["rows"] = rj;
    return dump(j);
}

bool shard_well_formed(const CampaignArgs& a, const Shard& s, const std::string& shard_text) {
    try {
        const Json j = Json::parse(shard_text);
        if (!j.is_object() || j.at("shard").get<int>() != s.index) return false;
        auto two_strings = [](const Json& f) {
            return f.is_array() && f.size() == 2 && f.at(0).is_string() && f.at(1).is_string();
        };
        if (j.contains("inputs"))
            for (const Json& f : j.at("inputs"))
                if (!two_strings(f)) return false;
        if (a.golden) {
            for (const Json& f : j.at("files"))
                if (!two_strings(f)) return false;
            return !j.contains("not_written") || two_strings(j["not_written"]);
        }
        for (const Json& r : j.at("rows")) (void)row_of(r);
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

bool shard_outputs_intact(const CampaignArgs& a, const std::string& shard_text) {
    if (!a.golden) return true;
    try {
        const Json j = Json::parse(shard_text);
        for (const Json& f : j.at("files"))
            if (sha256_hex(slurp_or_empty(a.dir + "/" + f.at(0).get<std::string>())) != f.at(1).get<std::string>())
                return false;
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

void write_failures(const CampaignArgs& a, const std::vector<AuditRow>& rows) {
    // Each row's scene: its file (an audit of SCENES names rows by the path), or the family
    // scene's copy run_shard wrote beside the claims.
    std::set<std::string> files(a.scenes.begin(), a.scenes.end()), used;
    Json index = Json::array();
    const std::string numbers =
        a.opt.numbers == Numbers::Double ? "" : std::string(" --numbers ") + numbers_name(a.opt.numbers);
    // The measure tolerance as certify-fp reads it back: the shortest decimal of the double.
    char tol[32];
    const auto end = std::to_chars(tol, tol + sizeof tol, a.settings.measure_tolerance).ptr;
    const std::string tolerance(tol, end);
    const std::string program = shell_word(a.program);
    // A double asked, as the claims file holds it: a JSON number, which certify-fp reads back as
    // that double under --numbers double; under float32 or exact its exact value as a string (a
    // JSON number would be read as a float, or as the decimal written).
    auto asked = [&a](double x) {
        return a.opt.numbers == Numbers::Double ? Json(x) : Json(to_exact_string(exact_from_double(x)));
    };
    for (const AuditRow& r : rows) {
        if (!r.not_run.empty())  // nothing to replay: the method did not run there, and why
            index.push_back(Json{{"scene", r.scene}, {"method", r.method}, {"not_run", r.not_run}});
        if (r.failures.empty() && r.measure_failures.empty()) continue;
        const bool given = a.given.count(r.scene) > 0, file = files.count(r.scene) > 0 && !given;
        const std::string scene = file    ? r.scene
                                  : given ? a.failures + "/" + r.scene + ".scene.json"
                                          : family_scene_file(a.failures, r.scene, r.eps);
        // NAME.METHOD.claims.json (verdicts) and NAME.METHOD.measures.claims.json (distances and
        // depths), NAME the scene file's stem; a second scene of that stem gets -2, ...
        std::string method;
        for (char ch : r.method) method += std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' ? ch : '_';
        std::string stem = std::filesystem::path(scene).filename().string();  // NAME.json, NAME.eps-P_Q.scene.json
        stem.resize(stem.size() -
                    (file ? std::filesystem::path(scene).extension().string().size() : 11));  // ".scene.json"
        std::string base = stem + "." + method;
        for (int k = 2; !used.insert(base).second; ++k) base = stem + "-" + std::to_string(k) + "." + method;
        // A program's claims that were no answer: NAME.METHOD.no-answers.json, each pair asked with
        // what the program wrote for it and why that is no answer (nothing to replay: no verdict).
        Json no_answers = Json::array();
        long wrong_verdicts = 0;
        for (const AuditRow::Failure& f : r.failures)
            if (f.said == AuditRow::kSaidNoAnswer)
                no_answers.push_back(Json{{"rho1", f.rho1},
                                          {"rho2", f.rho2},
                                          {"said", f.claim.empty() ? Json() : Json::parse(f.claim)},
                                          {"reason", f.reason}});
            else
                ++wrong_verdicts;
        if (!no_answers.empty()) {
            const std::string name = base + ".no-answers.json";
            const size_t listed = no_answers.size();
            write_file_atomically(
                a.failures + "/" + name,
                dump(Json{{"format", "scalecert-no-answers-1"}, {"scene", scene}, {"answers", std::move(no_answers)}}));
            index.push_back(Json{{"scene", scene},
                                 {"method", r.method},
                                 {"no_answers", a.failures + "/" + name},
                                 {"listed", listed},
                                 {"not_answered", r.not_answered}});
        }
        if (wrong_verdicts > 0) {
            const std::string name = base + ".claims.json";
            Json claims = Json::array();
            for (const AuditRow::Failure& f : r.failures)
                if (f.said != AuditRow::kSaidNoAnswer)
                    claims.push_back(Json{{"kind", "verdict"},
                                          {"rho1", asked(f.rho1)},
                                          {"rho2", asked(f.rho2)},
                                          {"verdict", AuditRow::said_word(f.said)}});
            const size_t claims_listed = claims.size();
            write_file_atomically(a.failures + "/" + name,
                                  dump(Json{{"format", "scalecert-claims-1"}, {"claims", std::move(claims)}}));
            index.push_back(Json{{"scene", scene},
                                 {"method", r.method},
                                 {"claims", a.failures + "/" + name},
                                 {"listed", claims_listed},
                                 {"wrong", r.wrong() - r.not_answered},
                                 {"replay", program + " certify-fp " + shell_word(scene) + " " +
                                                shell_word(a.failures + "/" + name) + numbers}});
        }
        if (!r.measure_failures.empty()) {
            const std::string name = base + ".measures.claims.json";
            Json claims = Json::array();
            for (const AuditRow::MeasureFailure& f : r.measure_failures) {
                Json c{{"kind", f.depth ? "penetration_depth" : "distance"},
                       {"rho1", asked(f.rho1)},
                       {"rho2", asked(f.rho2)},
                       {"value", asked(f.value)}};
                if (f.part1 >= 0) c["parts"] = Json::array({f.part1, f.part2});
                claims.push_back(std::move(c));
            }
            write_file_atomically(a.failures + "/" + name,
                                  dump(Json{{"format", "scalecert-claims-1"}, {"claims", std::move(claims)}}));
            index.push_back(
                Json{{"scene", scene},
                     {"method", r.method},
                     {"claims", a.failures + "/" + name},
                     {"listed", r.measure_failures.size()},
                     {"wrong", r.measures_wrong},
                     {"tolerance", a.settings.measure_tolerance},
                     {"replay", program + " certify-fp " + shell_word(scene) + " " +
                                    shell_word(a.failures + "/" + name) + " --tolerance " + tolerance + numbers}});
        }
    }
    write_file_atomically(a.failures + "/index.json",
                          dump(Json{{"format", "scalecert-audit-failures-1"}, {"reproducers", std::move(index)}}));
}

long finish_campaign(const CampaignArgs& a, const std::vector<std::string>& shard_texts) {
    if (a.golden) {
        const long asked = static_cast<long>(a.scenes.size()) + (a.family.empty() ? 0 : a.count);
        std::vector<std::string> skipped;  // "SCENE: why"
        for (const std::string& t : shard_texts) {
            const Json doc = Json::parse(t);
            if (doc.contains("not_written"))
                skipped.push_back(doc["not_written"][0].get<std::string>() + ": " +
                                  doc["not_written"][1].get<std::string>());
        }
        // Nothing written at all: the run failed, as a single scene's did (one line, exit 2).
        if (!skipped.empty() && static_cast<long>(skipped.size()) == asked)
            throw InputError(skipped.front() + (skipped.size() > 1 ? " (and " + std::to_string(skipped.size() - 1) +
                                                                         " more scenes: none written)"
                                                                   : ""));
        for (const std::string& why : skipped) say_note("no golden data written for " + why);
        return asked - static_cast<long>(skipped.size());
    }
    std::vector<AuditRow> rows;
    for (const std::string& t : shard_texts) {
        const Json doc = Json::parse(t);  // (kept: a range over a temporary's member dangles)
        for (const Json& r : doc.at("rows")) rows.push_back(row_of(r));
    }
    // A method that did not run on a scene is said on stderr too (the exit status stays 0: no bad
    // input), so that a run that reads only the exit status and the reproducers can see it.
    for (const AuditRow& r : rows)
        if (!r.not_run.empty()) say_note(r.scene + ": " + r.method + " did not run: " + r.not_run);
    if (!a.failures.empty()) write_failures(a, rows);
    const std::string json = dump(audit_json(rows, !a.no_timing));
    const std::string csv = audit_csv(rows, !a.no_timing);
    if (a.out.empty()) {
        if (!a.csv.empty()) write_file_atomically(a.csv, csv);
        std::fwrite(json.data(), 1, json.size(), stdout);
        std::fflush(stdout);
        if (std::ferror(stdout)) throw InputError("cannot write to standard output");
    } else if (a.csv.empty()) {
        write_file_atomically(a.out, json);
    } else {
        write_files_atomically({{a.csv, csv}, {a.out, json}});  // both or neither
    }
    return static_cast<long>(rows.size());
}

long run_campaign(const CampaignArgs& a) {
    std::vector<std::string> texts;
    for (const Shard& s : plan(a)) texts.push_back(run_shard(a, s));
    return finish_campaign(a, texts);
}

void make_output_dir(const std::string& dir) {
    std::error_code ec;
    // The folders it creates, outermost first, for the output journal (files.hpp).
    std::vector<std::string> created;
    for (std::filesystem::path p = std::filesystem::path(dir).lexically_normal();
         !p.empty() && !std::filesystem::exists(p, ec); p = p.parent_path()) {
        created.insert(created.begin(), p.string());
        if (p == p.parent_path()) break;
    }
    std::filesystem::create_directories(dir, ec);
    for (const std::string& c : created) journal_dir(c);
    if (ec || !std::filesystem::is_directory(dir))
        throw InputError(dir + ": cannot create the output directory (" + (ec ? ec.message() : "not a directory") +
                         ")");
}

void write_golden(const std::string& family, int count, std::uint64_t seed, const Q& eps, const std::string& dir,
                  const GoldenPoints& points) {
    CampaignArgs a;
    a.points = points;
    a.golden = true;
    a.family = family;
    a.count = count;
    a.seed = seed;
    a.eps_text = to_exact_string(eps);
    a.dir = dir;
    validate(a);  // an unknown family is refused before the directory is made
    make_output_dir(dir);
    run_campaign(a);
}

Json campaign_inputs(const CampaignArgs& a) {
    Json files = Json::array();
    for (const std::string& p : a.scenes) {  // (golden and audit alike)
        if (p == "-")
            throw InputError(
                "standard input cannot be a scene of a resumable run (its contents could not be checked on --resume)");
        for (const Json& f : reading([&] { load_scene(p, a.opt); })) files.push_back(f);
    }
    return files;
}

std::string stale_input(const Json& inputs, const std::string& shard_text) {
    Json j;
    try {
        j = Json::parse(shard_text);
    } catch (const std::exception&) {
        return "";  // not JSON: the caller's hash check redoes it
    }
    if (!j.is_object() || !j.contains("inputs")) return "";
    for (const Json& f : j.at("inputs")) {
        const std::string path = f.at(0).get<std::string>(), hash = f.at(1).get<std::string>();
        bool known = false;
        for (const Json& g : inputs)
            if (g.at(0).get<std::string>() == path) {
                if (g.at(1).get<std::string>() != hash) return path;
                known = true;
            }
        if (!known) return path;
    }
    return "";
}

std::string campaign_identity(const CampaignArgs& a, const Json& inputs) {
    Json j;
    j["command"] = a.golden ? "golden" : "audit";
    j["family"] = a.family;
    j["count"] = a.count;
    j["seed"] = std::to_string(a.seed);
    j["shards"] = plan(a).size();
    if (a.golden) {
        j["eps"] = to_exact_string(parse_exact(a.eps_text));
        j["dir"] = a.dir;
        j["verticals"] = a.points.verticals;
        j["offsets"] = a.points.offsets;
    } else {
        j["scenes"] = a.scenes;
        j["methods"] = a.methods;
        j["grid"] = a.grid;
        j["sweep"] = Json::array({a.sweep_from, a.sweep_to});
        j["atlas"] = a.atlas;
        if (!a.golden) j["measures"] = a.measures;
        j["by_distance"] = a.by_distance;
    }
    j["numbers"] = numbers_name(a.opt.numbers);
    j["shard_size"] = a.shard_size;
    j["inputs"] = inputs;  // [path, SHA-256] of every scene file and mesh file read
    return j.dump();
}

}  // namespace scalecert::internal

namespace scalecert {

void write_golden(const std::string& family, int count, std::uint64_t seed, const Rational& eps, const std::string& dir,
                  const GoldenOptions& options) {
    Rational e = eps;
    e.canonicalize();
    internal::write_golden(family, count, seed, e, dir, {options.verticals, options.offsets});
}

std::vector<std::string> families() { return internal::family_names(); }

}  // namespace scalecert
