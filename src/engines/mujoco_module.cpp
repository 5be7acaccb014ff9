// The MuJoCo module (libscalecert_mujoco.so): loads a model with Debian's libmujoco and reports
// what it holds and, at a qpos, what mj_forward computed, in mujoco_held.hpp's plain types. Loaded
// on first use by mujoco_loader.cpp, so the core never links MuJoCo.
#include "engines/mujoco_held.hpp"

#include <mujoco/mujoco.h>

#include <fcntl.h>
#include <unistd.h>

#include <csetjmp>
#include <cctype>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <array>
#include <map>
#include <set>
#include <mutex>
#include <sstream>

namespace {
using namespace scalecert::internal::mj;

// MuJoCo's warnings go to its log file and stdout by default: here they are kept, said by the
// command as notes.
std::vector<std::string>* g_warnings = nullptr;
void keep_warning(const char* msg) {
    if (g_warnings) g_warnings->push_back(msg);
}

// MuJoCo's errors (a stack overflow in mj_forward, an allocation that failed) would print, write
// MUJOCO_LOG.TXT, wait for Enter and exit: here each MuJoCo call that can fail runs under
// `guarded`, and the error jumps back to it with the message (only MuJoCo's C frames lie between).
std::jmp_buf* g_jump = nullptr;
std::string g_error;
void on_error(const char* msg) {
    g_error = msg ? msg : "MuJoCo failed";
    if (g_jump) std::longjmp(*g_jump, 1);
    std::fprintf(stderr, "scalecert: error: MuJoCo: %s\n", g_error.c_str());
    std::_Exit(3);  // an error outside a guarded call: a bug of this module
}
// Runs f (a MuJoCo call); false with the error in *error when MuJoCo raised one.
template <class F>
bool guarded(F f, std::string* error) {
    std::jmp_buf jump;
    g_jump = &jump;
    if (setjmp(jump) == 0) {
        f();
        g_jump = nullptr;
        return true;
    }
    g_jump = nullptr;
    *error = g_error;
    return false;
}
void install_handlers() {
    static std::once_flag once;
    std::call_once(once, [] {
        mju_user_warning = keep_warning;
        mju_user_error = on_error;
    });
}

class MujocoModel final : public Loaded {
  public:
    MujocoModel(mjModel* m, mjData* d) : m_(m), d_(d) { read_info(); }
    ~MujocoModel() override {
        mj_deleteData(d_);
        mj_deleteModel(m_);
    }
    const ModelInfo& info() const override { return info_; }
    State forward(const std::vector<double>& qpos) override {
        State s;
        g_warnings = &s.warnings;
        mj_resetData(m_, d_);
        for (int k = 0; k < m_->nq; ++k) d_->qpos[k] = qpos[static_cast<size_t>(k)];
        const bool ran = guarded([this] { mj_forward(m_, d_); }, &s.error);
        g_warnings = nullptr;
        if (!ran) return s;
        s.xpos.assign(d_->geom_xpos, d_->geom_xpos + 3 * m_->ngeom);
        s.xmat.assign(d_->geom_xmat, d_->geom_xmat + 9 * m_->ngeom);
        for (int i = 0; i < d_->ncon; ++i) {
            const mjContact& c = d_->contact[i];
            Contact o;
            o.g1 = c.geom1;
            o.g2 = c.geom2;
            o.dist = c.dist;
            std::memcpy(o.pos, c.pos, sizeof o.pos);
            std::memcpy(o.frame, c.frame, sizeof o.frame);
            o.includemargin = c.includemargin;
            o.exclude = c.exclude;
            s.contacts.push_back(o);
        }
        return s;
    }

  private:
    void read_info() {
        ModelInfo& f = info_;
        f.nq = m_->nq;
        f.qpos0.assign(m_->qpos0, m_->qpos0 + m_->nq);
        for (int k = 0; k < m_->nkey; ++k)
            f.keys.emplace_back(m_->key_qpos + k * m_->nq, m_->key_qpos + (k + 1) * m_->nq);
        for (int b = 0; b < m_->nbody; ++b) {
            f.body_parent.push_back(m_->body_parentid[b]);
            f.body_weld.push_back(m_->body_weldid[b]);
            const char* n = mj_id2name(m_, mjOBJ_BODY, b);
            f.body_names.push_back(n ? n : "");
        }
        for (int g = 0; g < m_->ngeom; ++g) {
            Geom o;
            const char* n = mj_id2name(m_, mjOBJ_GEOM, g);
            o.name = n ? n : "";
            o.type = m_->geom_type[g];
            o.body = m_->geom_bodyid[g];
            o.contype = m_->geom_contype[g];
            o.conaffinity = m_->geom_conaffinity[g];
            for (int k = 0; k < 3; ++k) o.size[k] = m_->geom_size[3 * g + k];
            o.margin = m_->geom_margin[g];
            o.gap = m_->geom_gap[g];
            if (o.type == mjGEOM_MESH && m_->geom_dataid[g] >= 0) {
                const int mesh = m_->geom_dataid[g];
                o.mesh = mesh;
                const float* v = m_->mesh_vert + 3 * m_->mesh_vertadr[mesh];
                o.vertices.assign(v, v + 3 * m_->mesh_vertnum[mesh]);
            }
            f.geoms.push_back(std::move(o));
        }
        for (int p = 0; p < m_->npair; ++p)
            f.pairs.push_back({m_->pair_geom1[p], m_->pair_geom2[p], m_->pair_margin[p], m_->pair_gap[p]});
        f.excludes.assign(m_->exclude_signature, m_->exclude_signature + m_->nexclude);
        f.disableflags = m_->opt.disableflags;
        f.enableflags = m_->opt.enableflags;
        f.o_margin = m_->opt.o_margin;
        f.collision = m_->opt.collision;
    }
    mjModel* m_;
    mjData* d_;
    ModelInfo info_;
};
}  // namespace

namespace {
// mj_loadXML with stdout and stderr silenced: MuJoCo's mesh compiler (qhull) prints to both; the
// command says one line.
mjModel* load_silenced(const char* path, char* err, int size) {
    std::fflush(stdout);
    std::fflush(stderr);
    const int out = ::dup(1), errfd = ::dup(2), null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) {
        ::dup2(null, 1);
        ::dup2(null, 2);
        ::close(null);
    }
    mjModel* m = nullptr;
    std::string failed;
    install_handlers();
    if (!guarded([&] { m = mj_loadXML(path, nullptr, err, size); }, &failed)) {
        m = nullptr;
        std::snprintf(err, static_cast<size_t>(size), "%s", failed.c_str());
    }
    std::fflush(stdout);
    std::fflush(stderr);
    if (out >= 0) ::dup2(out, 1), ::close(out);
    if (errfd >= 0) ::dup2(errfd, 2), ::close(errfd);
    return m;
}

// A temporary file of `text`, removed when this goes.
struct TempFile {
    std::string path;
    explicit TempFile(const std::string& text) {
        char name[] = "/tmp/scalecert-mujoco-XXXXXX";
        const int fd = ::mkstemp(name);
        if (fd < 0) return;
        path = name;
        size_t done = 0;
        while (done < text.size()) {
            const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
            if (n <= 0) break;
            done += static_cast<size_t>(n);
        }
        ::close(fd);
    }
    ~TempFile() {
        if (!path.empty()) ::unlink(path.c_str());
    }
};

std::string read_text(const std::string& path) {
    std::string out;
    if (FILE* f = std::fopen(path.c_str(), "rb")) {
        char buf[65536];
        for (size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) out.append(buf, n);
        std::fclose(f);
    }
    return out;
}

// The tags of an XML text MuJoCo wrote (mj_saveLastXML: double-quoted attributes, no comments in
// tags): each tag's name ("/default" for a closing one), its attributes, and whether it closes
// itself.
struct Tag {
    std::string name;
    std::map<std::string, std::string> attr;
    bool self_closing = false;
};
std::string unescaped(const std::string& v) {
    std::string out;
    for (size_t i = 0; i < v.size(); ++i) {
        if (v[i] != '&') {
            out += v[i];
            continue;
        }
        static const std::pair<const char*, char> named[] = {
            {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
        bool done = false;
        for (const auto& [e, c] : named)
            if (v.compare(i, std::strlen(e), e) == 0) {
                out += c;
                i += std::strlen(e) - 1;
                done = true;
                break;
            }
        if (!done) out += '&';
    }
    return out;
}
std::vector<Tag> tags_of(const std::string& text) {
    std::vector<Tag> out;
    for (size_t i = text.find('<'); i != std::string::npos; i = text.find('<', i + 1)) {
        if (text.compare(i, 4, "<!--") == 0) {
            i = text.find("-->", i);
            if (i == std::string::npos) break;
            continue;
        }
        if (text.compare(i, 2, "<?") == 0) continue;
        size_t j = i + 1;
        Tag t;
        while (j < text.size() && !std::isspace(static_cast<unsigned char>(text[j])) && text[j] != '>' &&
               !(text[j] == '/' && j > i + 1))
            t.name += text[j++];
        for (;;) {
            while (j < text.size() && std::isspace(static_cast<unsigned char>(text[j]))) ++j;
            if (j >= text.size()) return out;
            if (text[j] == '>') break;
            if (text[j] == '/') {
                t.self_closing = true;
                ++j;
                continue;
            }
            const size_t eq = text.find('=', j);
            if (eq == std::string::npos) return out;
            const std::string key = text.substr(j, eq - j);
            const size_t q = eq + 1;
            if (q >= text.size() || (text[q] != '"' && text[q] != '\'')) return out;
            const size_t e = text.find(text[q], q + 1);
            if (e == std::string::npos) return out;
            t.attr[key] = unescaped(text.substr(q + 1, e - q - 1));
            j = e + 1;
        }
        i = j;
        out.push_back(std::move(t));
    }
    return out;
}
std::string escaped(const std::string& v) {
    std::string out;
    for (char c : v) out += c == '&' ? "&amp;" : c == '<' ? "&lt;" : c == '"' ? "&quot;" : std::string(1, c);
    return out;
}
bool three_numbers(const std::string& text, double* out) {
    std::istringstream in(text);
    for (int k = 0; k < 3; ++k)
        if (!(in >> out[k])) return false;
    std::string rest;
    return !(in >> rest);
}
}  // namespace

// The model's meshes as it wrote them (MuJoCo writes the model back, mj_saveLastXML, with its
// includes inlined and its defaults as classes), and the frame MuJoCo moved each to, read off a
// model of that mesh alone at the origin: its geom's pos and quat are the mesh's.
extern "C" __attribute__((visibility("default"))) bool scalecert_mujoco_mesh_sources(const char* path,
                                                                                     std::vector<MeshSource>* out,
                                                                                     std::string* error) {
    char err[1000] = "";
    mjModel* m = load_silenced(path, err, sizeof err);
    if (!m) {
        *error = err[0] ? err : "MuJoCo could not load it";
        return false;
    }
    const TempFile saved("");
    bool wrote = false;
    std::string failed;
    if (!saved.path.empty()) guarded([&] { wrote = mj_saveLastXML(saved.path.c_str(), m, err, sizeof err); }, &failed);
    const std::string text = wrote ? read_text(saved.path) : "";
    out->assign(static_cast<size_t>(m->nmesh), MeshSource{});
    for (int k = 0; k < m->nmesh; ++k) {
        const char* n = mj_id2name(m, mjOBJ_MESH, k);
        (*out)[static_cast<size_t>(k)].name = n ? n : "";
        (*out)[static_cast<size_t>(k)].why_not = "MuJoCo did not write the model back (mj_saveLastXML)";
    }
    const int nmesh = m->nmesh;
    // Each mesh's float32 vertices as the model holds them: a probe must reproduce them exactly.
    std::vector<std::vector<float>> held(static_cast<size_t>(nmesh));
    for (int k = 0; k < nmesh; ++k)
        held[static_cast<size_t>(k)].assign(m->mesh_vert + 3 * m->mesh_vertadr[k],
                                            m->mesh_vert + 3 * (m->mesh_vertadr[k] + m->mesh_vertnum[k]));
    mj_deleteModel(m);
    if (!wrote) return true;
    // The mesh scale of each default class (a class takes its parent's unless it sets its own), the
    // compiler's folders, and the <mesh> assets in order: MuJoCo numbers meshes so.
    std::map<std::string, std::string> class_scale;
    std::vector<std::string> classes;
    std::string meshdir, assetdir;
    std::vector<std::map<std::string, std::string>> meshes;
    bool in_asset = false;
    for (const Tag& t : tags_of(text)) {
        if (t.name == "default" && !t.self_closing) {
            const std::string c = t.attr.count("class") ? t.attr.at("class") : "main";
            class_scale[c] = classes.empty() ? "" : class_scale[classes.back()];
            classes.push_back(c);
        } else if (t.name == "/default" && !classes.empty()) {
            classes.pop_back();
        } else if (t.name == "compiler") {
            if (t.attr.count("meshdir")) meshdir = t.attr.at("meshdir");
            if (t.attr.count("assetdir")) assetdir = t.attr.at("assetdir");
        } else if (t.name == "asset") {
            in_asset = !t.self_closing;
        } else if (t.name == "/asset") {
            in_asset = false;
        } else if (t.name == "mesh" && !classes.empty() && !in_asset) {
            if (t.attr.count("scale")) class_scale[classes.back()] = t.attr.at("scale");
        } else if (t.name == "mesh" && in_asset) {
            meshes.push_back(t.attr);
        }
    }
    if (static_cast<int>(meshes.size()) != nmesh) {
        for (MeshSource& s : *out) s.why_not = "its <mesh> assets could not be matched to the model's meshes";
        return true;
    }
    if (meshdir.empty()) meshdir = assetdir;
    if (!meshdir.empty() && meshdir.back() != '/') meshdir += '/';
    // The model's folder as an absolute path: the probe models live elsewhere.
    std::string modeldir = path;
    const size_t slash = modeldir.rfind('/');
    modeldir = slash == std::string::npos ? "." : modeldir.substr(0, slash + 1);
    if (char* real = ::realpath(modeldir.c_str(), nullptr)) {
        modeldir = std::string(real) + "/";
        std::free(real);
    }
    for (size_t k = 0; k < meshes.size(); ++k) {
        const auto& a = meshes[k];
        MeshSource& s = (*out)[k];
        s.why_not.clear();
        if (a.count("vertex") || !a.count("file")) {
            s.why_not = "its vertices are written in the model, not read from a file";
            continue;
        }
        if (a.count("refpos") || a.count("refquat")) {
            s.why_not = "it has refpos or refquat";
            continue;
        }
        const std::string& f = a.at("file");
        s.file = !f.empty() && f[0] == '/'               ? f
                 : !meshdir.empty() && meshdir[0] == '/' ? meshdir + f
                                                         : modeldir + meshdir + f;
        std::string scale = a.count("scale") ? a.at("scale") : "";
        if (scale.empty()) {
            const std::string c = a.count("class") ? a.at("class") : "main";
            scale = class_scale.count(c) ? class_scale.at(c) : "";
        }
        if (!scale.empty() && !three_numbers(scale, s.scale)) {
            s.why_not = "its scale \"" + scale + "\" is not three numbers";
            continue;
        }
        char probe_xml[200];
        std::snprintf(probe_xml, sizeof probe_xml, "\" scale=\"%.17g %.17g %.17g\"/>", s.scale[0], s.scale[1],
                      s.scale[2]);
        const TempFile probe("<mujoco><asset><mesh name=\"m\" file=\"" + escaped(s.file) + probe_xml +
                             "</asset><worldbody><geom type=\"mesh\" mesh=\"m\"/></worldbody></mujoco>");
        mjModel* p = probe.path.empty() ? nullptr : load_silenced(probe.path.c_str(), err, sizeof err);
        if (!p || p->ngeom != 1) {
            s.why_not = std::string("MuJoCo could not load the mesh alone: ") + err;
            if (p) mj_deleteModel(p);
            continue;
        }
        for (int i = 0; i < 3; ++i) s.pos[i] = p->geom_pos[i];
        for (int i = 0; i < 4; ++i) s.quat[i] = p->geom_quat[i];
        // The model written back rounds numbers (a scale to 6 digits), and its defaults may not be
        // read back whole: the probe's vertices must be the model's, float for float.
        const std::vector<float> probe_vertices(p->mesh_vert, p->mesh_vert + 3 * p->nmeshvert);
        std::set<std::array<float, 3>> distinct;
        for (size_t i = 0; i + 2 < held[k].size(); i += 3)
            distinct.insert({held[k][i], held[k][i + 1], held[k][i + 2]});
        s.vertices = static_cast<long>(distinct.size());
        if (p->nmesh != 1 || probe_vertices != held[k])
            s.why_not =
                "MuJoCo's vertices for it alone differ from the model's (its scale or class, as MuJoCo writes "
                "the model back, is not the model's exactly)";
        mj_deleteModel(p);
    }
    return true;
}

extern "C" __attribute__((visibility("default"))) Loaded* scalecert_mujoco_load(const char* path, std::string* error) {
    install_handlers();
    char err[1000] = "";
    mjModel* m = load_silenced(path, err, sizeof err);
    if (!m) {
        *error = err[0] ? err : "MuJoCo could not load it";
        return nullptr;
    }
    mjData* d = nullptr;
    std::string failed;
    if (!guarded([&] { d = mj_makeData(m); }, &failed) || !d) {
        mj_deleteModel(m);
        *error = failed.empty() ? "MuJoCo could not make its data" : failed;
        return nullptr;
    }
    return new MujocoModel(m, d);
}
