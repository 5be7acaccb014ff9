// The documents' JSON (nlohmann's, keys in insertion order), how every document is written, and
// the scene writers: a scene exactly, every number an exact string (certificates/FORMAT.md).
#pragma once
#include "io/scene.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace scalecert::internal {

using Json = nlohmann::ordered_json;

// A document as scalecert writes it: indented by one space, ending in a newline.
std::string dump(const Json& j);

// The scene exactly, in the scene-file format of two convex objects (seeds explicit).
Json scene_json(const ExactScene& s);
// The scene with every object as a list of parts (a plain object is one part), as the compound
// certificates state it (without the parts' names: the checker reads these); with_names: each
// named part with its "name", as a scene file gives it.
Json compound_scene_json(const ExactScene& sc, bool with_names = false);
// A scene's file: scene_json for two convex objects, compound_scene_json with the parts' names when
// one is made of parts (read back, it gives the same scene and so the same bytes).
Json scene_file_json(const ExactScene& sc);

}  // namespace scalecert::internal
