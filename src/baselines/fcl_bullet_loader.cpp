// make_fcl and make_bullet: the FCL/Bullet baselines live in a module loaded on first use (see
// fcl_bullet.cpp), looked for in this order: $SCALECERT_FCL_BULLET_MODULE; the build tree's copy;
// <executable's directory>/../<libdir>/scalecert/ (an installed command); the install prefix.
#include "baselines/baselines.hpp"
#include "io/module.hpp"

#include <mutex>
#include <stdexcept>

namespace scalecert::internal::fp {

namespace {
using MakeFcl = Method* (*)(const Model*, const FpScene*, bool);
using MakeBullet = Method* (*)(const FpScene*);
using MakeCompound = Method* (*)(const CompoundFp*, int);
using MakeRounded = Method* (*)(const RoundedFp*, int);

struct Module {
    MakeFcl fcl = nullptr;
    MakeBullet bullet = nullptr;
    MakeCompound compound = nullptr;
    MakeRounded rounded = nullptr;
};

const Module& module() {
    static Module mod;
    static std::once_flag once;
    static std::string error;
    std::call_once(once, [] {
        const std::vector<void*> f = open_module(
            module_paths("SCALECERT_FCL_BULLET_MODULE", SCALECERT_FCL_BULLET_BUILD, SCALECERT_LIBDIR,
                         "libscalecert_fcl_bullet.so", SCALECERT_FCL_BULLET_INSTALLED),
            {"scalecert_make_fcl", "scalecert_make_bullet", "scalecert_make_compound", "scalecert_make_rounded"},
            &error);
        if (f.empty()) {
            if (error.empty()) error = "libscalecert_fcl_bullet.so not found (set SCALECERT_FCL_BULLET_MODULE)";
            return;
        }
        mod.fcl = reinterpret_cast<MakeFcl>(f[0]);
        mod.bullet = reinterpret_cast<MakeBullet>(f[1]);
        mod.compound = reinterpret_cast<MakeCompound>(f[2]);
        mod.rounded = reinterpret_cast<MakeRounded>(f[3]);
    });
    if (!mod.fcl || !mod.bullet || !mod.compound || !mod.rounded)
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
std::unique_ptr<Method> make_rounded_fcl_bullet(const RoundedFp& s, int kind) {
    return std::unique_ptr<Method>(module().rounded(&s, kind));
}

}  // namespace scalecert::internal::fp
