// Modules loaded on first use (the FCL/Bullet baselines, MuJoCo): the floating-point libraries
// live in shared objects the core never links, found and opened here.
#pragma once
#include <string>
#include <vector>

namespace scalecert::internal {

// Where module `file` is looked for, in order: $<env> (a path), the build tree's copy (`built`,
// may be empty), <this executable's folder>/../<libdir>/scalecert/<file> (an installed command),
// and `installed` (the install prefix's).
std::vector<std::string> module_paths(const char* env, const std::string& built, const std::string& libdir,
                                      const std::string& file, const std::string& installed);
// The first of `paths` that is there, opens, and has every one of `symbols`: their addresses, in
// order; empty when none does, with the last reason in *error ("" when no path was there).
std::vector<void*> open_module(const std::vector<std::string>& paths, const std::vector<const char*>& symbols,
                               std::string* error);

}  // namespace scalecert::internal
