#include "io/module.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

namespace scalecert::internal {

std::vector<std::string> module_paths(const char* env, const std::string& built, const std::string& libdir,
                                      const std::string& file, const std::string& installed) {
    std::vector<std::string> paths;
    if (const char* e = std::getenv(env)) paths.push_back(e);
    if (!built.empty()) paths.push_back(built);
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) paths.push_back((exe.parent_path() / ".." / libdir / "scalecert" / file).string());
    paths.push_back(installed);
    return paths;
}

std::vector<void*> open_module(const std::vector<std::string>& paths, const std::vector<const char*>& symbols,
                               std::string* error) {
    for (const std::string& p : paths) {
        if (::access(p.c_str(), R_OK) != 0) continue;
        void* h = ::dlopen(p.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!h) {
            *error = dlerror();
            continue;
        }
        std::vector<void*> out;
        for (const char* s : symbols)
            if (void* f = ::dlsym(h, s)) out.push_back(f);
        if (out.size() == symbols.size()) return out;
        *error = p + ": lacks the entry points";
    }
    return {};
}

}  // namespace scalecert::internal
