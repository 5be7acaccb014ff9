// The library's own access to a public Scene (api.cpp's constructors): not part of the API, so
// the public header names none of it.
#pragma once
#include <scalecert/scalecert.hpp>

#include "curve/contact_lines.hpp"

#include <memory>
#include <string>

namespace scalecert {

struct SceneAccess {
    // Validates a scene as read. Two convex objects: rank and seeds proved from a few extreme
    // points on large scenes (scan.hpp), else by the hull model, built now (its errors are the
    // scene's). Objects made of parts: each part's hull is built where it is first needed.
    static std::shared_ptr<Scene::Data> validated(internal::ExactScene sc, const std::string& name);
};

}  // namespace scalecert
