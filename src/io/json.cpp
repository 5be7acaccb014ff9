#include "io/json.hpp"

namespace scalecert::internal {

// (A string of invalid UTF-8 — a file name or a command as the user gave them — is written with
// U+FFFD for each bad byte, not refused: the text is the user's, the document ours.)
std::string dump(const Json& j) { return j.dump(1, ' ', false, Json::error_handler_t::replace) + "\n"; }

namespace {
Json points_json(const std::vector<Vec3q>& pts) {
    Json a = Json::array();
    for (const Vec3q& v : pts)
        a.push_back(Json::array({to_exact_string(v[0]), to_exact_string(v[1]), to_exact_string(v[2])}));
    return a;
}
}  // namespace

Json scene_json(const ExactScene& sc) {
    Json s;
    const char* names[2] = {"P1", "P2"};
    for (int i = 0; i < 2; ++i) {
        Json verts = Json::array();
        for (const Vec3q& v : sc.P[i].points)
            verts.push_back(Json::array({to_exact_string(v[0]), to_exact_string(v[1]), to_exact_string(v[2])}));
        const Vec3q& sd = sc.P[i].seed;
        s[names[i]] =
            Json{{"vertices", verts},
                 {"seed", Json::array({to_exact_string(sd[0]), to_exact_string(sd[1]), to_exact_string(sd[2])})}};
        // Objects with a radius carry it (both, on a scene where either has one > 0).
        if (sc.rounded()) s[names[i]]["radius"] = to_exact_string(sc.P[i].radius);
    }
    s["I1"] = Json::array({to_exact_string(sc.lo[0]), to_exact_string(sc.hi[0])});
    s["I2"] = Json::array({to_exact_string(sc.lo[1]), to_exact_string(sc.hi[1])});
    return s;
}

Json compound_scene_json(const ExactScene& sc, bool with_names) {
    Json s;
    const char* names[2] = {"P1", "P2"};
    for (int i = 0; i < 2; ++i) {
        const PolyInput& in = sc.P[i];
        Json parts = Json::array();
        // Parts with radii carry them (every part, on a scene where some object has one > 0).
        if (in.parts.empty()) {
            parts.push_back(Json{{"vertices", points_json(in.points)}});
            if (sc.rounded()) parts.back()["radius"] = to_exact_string(in.radius);
        }
        for (size_t k = 0; k < in.parts.size(); ++k) {
            Json p;
            if (with_names && !part_name(in, k).empty()) p["name"] = part_name(in, k);
            p["vertices"] = points_json(in.parts[k]);
            if (sc.rounded()) p["radius"] = to_exact_string(in.part_radius(k));
            parts.push_back(std::move(p));
        }
        s[names[i]] = Json{{"parts", parts},
                           {"seed", Json::array({to_exact_string(in.seed[0]), to_exact_string(in.seed[1]),
                                                 to_exact_string(in.seed[2])})}};
    }
    for (int i = 0; i < 2; ++i)
        s[i == 0 ? "I1" : "I2"] = Json::array({to_exact_string(sc.lo[i]), to_exact_string(sc.hi[i])});
    return s;
}

Json scene_file_json(const ExactScene& sc) {
    return sc.made_of_parts() ? compound_scene_json(sc, true) : scene_json(sc);
}

}  // namespace scalecert::internal
