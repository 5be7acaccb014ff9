// The library's own access to a public Scene (the Python module's claim certification): not part
// of the API, so the public header names none of it.
#pragma once
#include <scalecert/scalecert.hpp>

#include "curve/contact_lines.hpp"

#include <memory>
#include <string>

namespace scalecert {

struct SceneAccess {
    // Validates a scene as read: rank and seeds proved from a few extreme points on large scenes
    // (scan.hpp), else by the hull model, built now (its errors are the scene's).
    static std::shared_ptr<Scene::Data> validated(internal::ExactScene sc, const std::string& name);
    static Scene make(std::shared_ptr<Scene::Data> d) { return Scene(std::move(d)); }
    // The hull model (polyhedra, every contact line), built on first use and shared.
    static std::shared_ptr<const internal::HullModel> hull_model(const Scene& s);
};

}  // namespace scalecert
