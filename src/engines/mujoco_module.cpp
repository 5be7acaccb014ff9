// The MuJoCo module (libscalecert_mujoco.so): loads a model with Debian's libmujoco and reports
// what it holds and, at a qpos, what mj_forward computed, in mujoco_held.hpp's plain types. Loaded
// on first use by mujoco_loader.cpp, so the core never links MuJoCo.
#include "engines/mujoco_held.hpp"

#include <mujoco/mujoco.h>

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <mutex>

namespace {
using namespace scalecert::internal::mj;

// MuJoCo's warnings go to its log file and stdout by default: here they are kept, said by the
// command as notes.
std::vector<std::string>* g_warnings = nullptr;
void keep_warning(const char* msg) {
    if (g_warnings) g_warnings->push_back(msg);
}

class MujocoModel final : public Loaded {
  public:
    MujocoModel(mjModel* m) : m_(m), d_(mj_makeData(m)) { read_info(); }
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
        mj_forward(m_, d_);
        g_warnings = nullptr;
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

extern "C" __attribute__((visibility("default"))) Loaded* scalecert_mujoco_load(const char* path, std::string* error) {
    static std::once_flag once;
    std::call_once(once, [] { mju_user_warning = keep_warning; });
    char err[1000] = "";
    // MuJoCo's mesh compiler (qhull) prints to stdout and stderr; the command says one line.
    std::fflush(stdout);
    std::fflush(stderr);
    const int out = ::dup(1), errfd = ::dup(2), null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) {
        ::dup2(null, 1);
        ::dup2(null, 2);
        ::close(null);
    }
    mjModel* m = mj_loadXML(path, nullptr, err, sizeof err);
    std::fflush(stdout);
    std::fflush(stderr);
    if (out >= 0) ::dup2(out, 1), ::close(out);
    if (errfd >= 0) ::dup2(errfd, 2), ::close(errfd);
    if (!m) {
        *error = err[0] ? err : "MuJoCo could not load it";
        return nullptr;
    }
    return new MujocoModel(m);
}
