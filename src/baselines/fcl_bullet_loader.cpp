// make_fcl and make_bullet: the FCL/Bullet baselines live in a module loaded on first use (see
// fcl_bullet.cpp), looked for in this order: $SCALECERT_FCL_BULLET_MODULE; the build tree's copy;
// <executable's directory>/../<libdir>/scalecert/ (an installed command); the install prefix.
#include "baselines/baselines.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>

namespace scalecert::internal::fp {

namespace {
using MakeFcl = Method* (*)(const Model*, const FpScene*, bool);
using MakeBullet = Method* (*)(const FpScene*);
using MakeCompound = Method* (*)(const CompoundFp*, int);

struct Module {
    MakeFcl fcl = nullptr;
    MakeBullet bullet = nullptr;
    MakeCompound compound = nullptr;
};

const Module& module() {
    static Module mod;
    static std::once_flag once;
    static std::string error;
    std::call_once(once, [] {
        std::vector<std::string> paths;
        if (const char* e = std::getenv("SCALECERT_FCL_BULLET_MODULE")) paths.push_back(e);
        paths.push_back(SCALECERT_FCL_BULLET_BUILD);
        std::error_code ec;
        const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
        if (!ec)
            paths.push_back(
                (exe.parent_path() / ".." / SCALECERT_LIBDIR / "scalecert" / "libscalecert_fcl_bullet.so").string());
        paths.push_back(SCALECERT_FCL_BULLET_INSTALLED);
        for (const std::string& p : paths) {
            if (::access(p.c_str(), R_OK) != 0) continue;
            void* h = ::dlopen(p.c_str(), RTLD_NOW | RTLD_LOCAL);
            if (!h) {
                error = dlerror();
                continue;
            }
            mod.fcl = reinterpret_cast<MakeFcl>(::dlsym(h, "scalecert_make_fcl"));
            mod.bullet = reinterpret_cast<MakeBullet>(::dlsym(h, "scalecert_make_bullet"));
            mod.compound = reinterpret_cast<MakeCompound>(::dlsym(h, "scalecert_make_compound"));
            if (mod.fcl && mod.bullet && mod.compound) return;
            error = p + ": lacks the entry points";
        }
        if (error.empty()) error = "libscalecert_fcl_bullet.so not found (set SCALECERT_FCL_BULLET_MODULE)";
    });
    if (!mod.fcl || !mod.bullet || !mod.compound)
        throw std::runtime_error("the FCL/Bullet baselines cannot be loaded: " + error);
    return mod;
}
}  // namespace

std::unique_ptr<Method> make_fcl(const Model& m, const FpScene& s, bool libccd) {
    return std::unique_ptr<Method>(module().fcl(&m, &s, libccd));
}
std::unique_ptr<Method> make_bullet(const FpScene& s) { return std::unique_ptr<Method>(module().bullet(&s)); }
std::unique_ptr<Method> make_fcl_bullet_compound(const CompoundFp& s, int kind) {
    return std::unique_ptr<Method>(module().compound(&s, kind));
}

}  // namespace scalecert::internal::fp
