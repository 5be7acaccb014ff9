// load_model: MuJoCo lives in a module loaded on first use (mujoco_module.cpp), looked for in this
// order: $SCALECERT_MUJOCO_MODULE; the build tree's copy; <executable's directory>/../<libdir>/
// scalecert/ (an installed command); the install prefix.
#include "baselines/mujoco_held.hpp"
#include "numeric/exact.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>

namespace scalecert::internal::mj {

const char* geom_type_name(int type) {
    static const char* const names[] = {"plane", "hfield", "sphere", "capsule", "ellipsoid", "cylinder", "box", "mesh"};
    return type >= 0 && type < 8 ? names[type] : "unknown";
}

namespace {
LoadFn module() {
    static LoadFn load = nullptr;
    static std::once_flag once;
    static std::string error;
    std::call_once(once, [] {
        std::vector<std::string> paths;
        if (const char* e = std::getenv("SCALECERT_MUJOCO_MODULE")) paths.push_back(e);
#ifdef SCALECERT_MUJOCO_BUILD
        paths.push_back(SCALECERT_MUJOCO_BUILD);
#endif
        std::error_code ec;
        const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
        if (!ec)
            paths.push_back(
                (exe.parent_path() / ".." / SCALECERT_LIBDIR / "scalecert" / "libscalecert_mujoco.so").string());
        paths.push_back(SCALECERT_MUJOCO_INSTALLED);
        for (const std::string& p : paths) {
            if (::access(p.c_str(), R_OK) != 0) continue;
            void* h = ::dlopen(p.c_str(), RTLD_NOW | RTLD_LOCAL);
            if (!h) {
                error = dlerror();
                continue;
            }
            load = reinterpret_cast<LoadFn>(::dlsym(h, "scalecert_mujoco_load"));
            if (load) return;
            error = p + ": lacks the entry point";
        }
        if (error.empty())
            error =
                "libscalecert_mujoco.so not found (build with Debian's libmujoco-dev installed, or set "
                "SCALECERT_MUJOCO_MODULE)";
    });
    if (!load) throw InputError("MuJoCo cannot be loaded: " + error);
    return load;
}
}  // namespace

std::unique_ptr<Loaded> load_model(const std::string& path) {
    const LoadFn load = module();
    std::string error;
    std::unique_ptr<Loaded> m(load(path.c_str(), &error));
    if (!m) {
        // MuJoCo's message may run over lines: one line here.
        for (char& c : error)
            if (c == '\n' || c == '\r') c = ' ';
        while (!error.empty() && error.back() == ' ') error.pop_back();
        throw InputError(path + ": MuJoCo: " + error);
    }
    return m;
}

}  // namespace scalecert::internal::mj
