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
    // Two large OFF files of integers read straight into machine integers, as the command reads
    // them, when the walk will answer (Session::plan) and proves the seeds inside: the scene with
    // no exact form until asked for. Null otherwise, and on any problem, which the exact reading
    // then words.
    static std::shared_ptr<Scene::Data> from_integers(const std::string& p1_path, const std::string& p2_path,
                                                      const Interval& i1, const Interval& i2, Numbers numbers);
};

}  // namespace scalecert
