// load_model: MuJoCo lives in a module loaded on first use (mujoco_module.cpp), looked for in this
// order: $SCALECERT_MUJOCO_MODULE; the build tree's copy; <executable's directory>/../<libdir>/
// scalecert/ (an installed command); the install prefix.
#include "engines/mujoco_held.hpp"
#include "io/files.hpp"
#include "io/module.hpp"
#include "numeric/exact.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <optional>

namespace scalecert::internal::mj {

const char* geom_type_name(int type) {
    static const char* const names[] = {"plane", "hfield", "sphere", "capsule", "ellipsoid", "cylinder", "box", "mesh"};
    return type >= 0 && type < 8 ? names[type] : "unknown";
}

namespace {
struct Module {
    LoadFn load = nullptr;
    MeshSourcesFn mesh_sources = nullptr;
};
const Module& module() {
    static Module mod;
    LoadFn& load = mod.load;
    static std::once_flag once;
    static std::string error;
    std::call_once(once, [] {
#ifdef SCALECERT_MUJOCO_BUILD
        const std::string built = SCALECERT_MUJOCO_BUILD;
#else
        const std::string built;
#endif
        const std::vector<void*> f = open_module(module_paths("SCALECERT_MUJOCO_MODULE", built, SCALECERT_MUJOCO_LIBDIR,
                                                              "libscalecert_mujoco.so", SCALECERT_MUJOCO_INSTALLED),
                                                 {"scalecert_mujoco_load", "scalecert_mujoco_mesh_sources"}, &error);
        if (!f.empty()) {
            load = reinterpret_cast<LoadFn>(f[0]);
            mod.mesh_sources = reinterpret_cast<MeshSourcesFn>(f[1]);
            return;
        }
        if (error.empty())
            error =
                "libscalecert_mujoco.so not found (build with Debian's libmujoco-dev installed, or set "
                "SCALECERT_MUJOCO_MODULE)";
    });
    if (!load) throw InputError("MuJoCo cannot be loaded: " + error);
    return mod;
}

// MuJoCo's message, which may run over lines, as one line.
std::string one_line(std::string error) {
    for (char& c : error)
        if (c == '\n' || c == '\r') c = ' ';
    while (!error.empty() && error.back() == ' ') error.pop_back();
    return error;
}
}  // namespace

namespace {
// MuJoCo opens the files a model names itself (meshes, height fields, textures, <include>s), and
// would wait on a FIFO forever. Every file="..." of the model and of its includes is looked for
// where MuJoCo looks (beside the model, under the compiler's meshdir, texturedir and assetdir) and
// refused in one line where it is there and not a regular file. (A text scan, not an XML parse: a
// name it reads too many only costs a stat.)
// An attribute value with XML's character references decoded (&amp; &lt; &gt; &quot; &apos;,
// &#N; and &#xN;), as MuJoCo's XML reader reads it.
std::string xml_decoded(const std::string& v) {
    std::string out;
    for (size_t i = 0; i < v.size(); ++i) {
        const size_t semi = v[i] == '&' ? v.find(';', i) : std::string::npos;
        if (semi == std::string::npos || semi - i > 12) {
            out += v[i];
            continue;
        }
        const std::string name = v.substr(i + 1, semi - i - 1);
        long code = -1;
        if (name == "amp")
            code = '&';
        else if (name == "lt")
            code = '<';
        else if (name == "gt")
            code = '>';
        else if (name == "quot")
            code = '"';
        else if (name == "apos")
            code = '\'';
        else if (name.size() > 1 && name[0] == '#') {
            char* end = nullptr;
            code = name[1] == 'x' || name[1] == 'X' ? std::strtol(name.c_str() + 2, &end, 16)
                                                    : std::strtol(name.c_str() + 1, &end, 10);
            if (!end || *end) code = -1;
        }
        if (code < 0 || code > 0x10FFFF) {
            out += v[i];
            continue;
        }
        // UTF-8, as the file name's bytes.
        if (code < 0x80)
            out += static_cast<char>(code);
        else if (code < 0x800)
            out += static_cast<char>(0xC0 | (code >> 6)), out += static_cast<char>(0x80 | (code & 0x3F));
        else if (code < 0x10000)
            out += static_cast<char>(0xE0 | (code >> 12)), out += static_cast<char>(0x80 | ((code >> 6) & 0x3F)),
                out += static_cast<char>(0x80 | (code & 0x3F));
        else
            out += static_cast<char>(0xF0 | (code >> 18)), out += static_cast<char>(0x80 | ((code >> 12) & 0x3F)),
                out += static_cast<char>(0x80 | ((code >> 6) & 0x3F)), out += static_cast<char>(0x80 | (code & 0x3F));
        i = semi;
    }
    return out;
}

void refuse_files_that_block(const std::string& path, int depth = 0,
                             std::vector<std::filesystem::path> inherited = {}) {
    const std::string text = read_input(path, "model file", kMaxSceneBytes);
    note_inputs({path});
    if (depth > 16) throw InputError(path + ": <include>s nested past 16 levels");
    const std::filesystem::path dir = std::filesystem::path(path).parent_path();
    // The next value of attribute `name` from `from` on: name, spaces, '=', spaces, then a value
    // in double or single quotes (XML allows both); `at` is left after it.
    auto attribute = [&](const std::string& name, size_t from, size_t& at) -> std::optional<std::string> {
        auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
        for (size_t k = text.find(name, from); k != std::string::npos; k = text.find(name, k + 1)) {
            if (k > 0 && !space(text[k - 1])) continue;  // part of another name
            size_t i = k + name.size();
            while (i < text.size() && space(text[i])) ++i;
            if (i == text.size() || text[i] != '=') continue;
            for (++i; i < text.size() && space(text[i]); ++i) {}
            if (i == text.size() || (text[i] != '"' && text[i] != '\'')) continue;
            const size_t e = text.find(text[i], i + 1);
            if (e == std::string::npos) return std::nullopt;
            at = e;
            return xml_decoded(text.substr(i + 1, e - i - 1));
        }
        return std::nullopt;
    };
    // The folders a file may be looked for in: this file's, the compiler's (given here or by the
    // model that includes this file), and, for <compiler strippath>, each name's last part too.
    std::vector<std::filesystem::path> dirs = std::move(inherited);
    dirs.push_back(dir);
    for (const char* d : {"meshdir", "texturedir", "assetdir"})
        for (size_t at = 0; auto v = attribute(d, at, at);) dirs.push_back(dir / *v);
    for (size_t at = 0; auto f = attribute("file", at, at);) {
        std::vector<std::filesystem::path> candidates;
        for (const std::filesystem::path& d : dirs) {
            candidates.push_back(std::filesystem::path(*f).is_absolute() ? std::filesystem::path(*f) : d / *f);
            candidates.push_back(d / std::filesystem::path(*f).filename());
            const size_t back = f->find_last_of("/\\");  // strippath cuts at either slash
            if (back != std::string::npos) candidates.push_back(d / f->substr(back + 1));
        }
        for (const std::filesystem::path& p : candidates) {
            std::error_code ec;
            const auto st = std::filesystem::status(p, ec);
            if (ec || !std::filesystem::exists(st)) continue;
            if (!std::filesystem::is_regular_file(st))
                throw InputError(path + ": " + in_quotes(*f) + " (" + p.string() +
                                 ") is not a regular file: MuJoCo would open it (only regular files are read)");
            note_inputs({p.string()});  // an output naming it would replace the model's own file
            const size_t tag = text.rfind('<', at);
            if (tag != std::string::npos && text.compare(tag, 8, "<include") == 0)
                refuse_files_that_block(p.string(), depth + 1, dirs);
        }
    }
}
}  // namespace

std::unique_ptr<Loaded> load_model(const std::string& path) {
    refuse_files_that_block(path);
    const LoadFn load = module().load;
    std::string error;
    std::unique_ptr<Loaded> m(load(path.c_str(), &error));
    if (!m) throw InputError(path + ": MuJoCo: " + one_line(error));
    return m;
}

std::vector<MeshSource> mesh_sources(const std::string& path) {
    refuse_files_that_block(path);
    std::vector<MeshSource> out;
    std::string error;
    if (!module().mesh_sources(path.c_str(), &out, &error)) throw InputError(path + ": MuJoCo: " + one_line(error));
    return out;
}

}  // namespace scalecert::internal::mj
