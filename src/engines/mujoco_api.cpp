// The public judge_mujoco and judge_mujoco_held (scalecert.hpp): scalecert mujoco's judgement from
// the library, of a model file run by MuJoCo's module or of the arrays a program's MuJoCo holds.
#include "engines/mujoco_judge.hpp"
#include "scalecert/scalecert.hpp"

#include <cmath>

namespace scalecert {

namespace {
void check_options(const MujocoOptions& options) {
    if (sgn(options.tolerance) < 0) throw InputError("tolerance must be >= 0");
    if (sgn(options.abs_tolerance) < 0) throw InputError("abs_tolerance must be >= 0");
}

MujocoJudgement judged(internal::mj::Loaded& m, const std::vector<std::vector<double>>& states,
                       const std::vector<std::string>& labels, const MujocoOptions& options,
                       const std::string& source) {
    using namespace internal;
    const mj::MujocoResult r = mj::judge_states(m, states, labels,
                                                mj::MujocoOptions{Tolerance{options.tolerance, options.abs_tolerance},
                                                                  source, options.failures, options.intended});
    return {dump(r.report), r.text, r.wrong, r.report["summary"]["judgements"].get<long>()};
}

// The held arrays as the judge reads them, and their states in the order given.
class Held final : public internal::mj::Loaded {
  public:
    Held(internal::mj::ModelInfo info, std::vector<internal::mj::State> states)
        : info_(std::move(info)), states_(std::move(states)) {}
    const internal::mj::ModelInfo& info() const override { return info_; }
    internal::mj::State forward(const std::vector<double>&) override { return states_.at(next_++); }

  private:
    internal::mj::ModelInfo info_;
    std::vector<internal::mj::State> states_;
    size_t next_ = 0;
};

template <class V>
void need_size(const V& v, size_t n, const std::string& name, const char* of) {
    if (v.size() != n)
        throw InputError("held model: " + name + " has " + std::to_string(v.size()) + " entries, " + of + " gives " +
                         std::to_string(n));
}
void need_index(int i, size_t n, const std::string& name) {
    if (i < 0 || static_cast<size_t>(i) >= n)
        throw InputError("held model: " + name + " = " + std::to_string(i) + " is out of range (0.." +
                         std::to_string(n) + ")");
}
template <class V>
void need_finite(const V& v, const std::string& name) {
    for (size_t i = 0; i < v.size(); ++i)
        if (!std::isfinite(static_cast<double>(v[i])))
            throw InputError(name + "[" + std::to_string(i) + "]: not a finite number");
}

internal::mj::ModelInfo held_info(const MujocoHeldModel& m) {
    internal::mj::ModelInfo f;
    const size_t ngeom = m.geom_type.size(), nbody = m.body_parentid.size(), nmesh = m.mesh_vertadr.size(),
                 npair = m.pair_geom1.size();
    if (m.nq < 0) throw InputError("held model: nq < 0");
    const char* g = "geom_type";
    need_size(m.geom_bodyid, ngeom, "geom_bodyid", g);
    need_size(m.geom_contype, ngeom, "geom_contype", g);
    need_size(m.geom_conaffinity, ngeom, "geom_conaffinity", g);
    need_size(m.geom_dataid, ngeom, "geom_dataid", g);
    need_size(m.geom_size, 3 * ngeom, "geom_size", "3 x geom_type");
    need_size(m.geom_margin, ngeom, "geom_margin", g);
    need_size(m.geom_gap, ngeom, "geom_gap", g);
    if (!m.geom_names.empty()) need_size(m.geom_names, ngeom, "geom_names", g);
    need_size(m.body_weldid, nbody, "body_weldid", "body_parentid");
    if (!m.body_names.empty()) need_size(m.body_names, nbody, "body_names", "body_parentid");
    need_size(m.mesh_vertnum, nmesh, "mesh_vertnum", "mesh_vertadr");
    if (m.mesh_vert.size() % 3) throw InputError("held model: mesh_vert's length is not a multiple of 3");
    need_size(m.pair_geom2, npair, "pair_geom2", "pair_geom1");
    need_size(m.pair_margin, npair, "pair_margin", "pair_geom1");
    need_size(m.pair_gap, npair, "pair_gap", "pair_geom1");
    need_finite(m.geom_size, "geom_size");
    need_finite(m.geom_margin, "geom_margin");
    need_finite(m.geom_gap, "geom_gap");
    need_finite(m.mesh_vert, "mesh_vert");
    need_finite(m.pair_margin, "pair_margin");
    need_finite(m.pair_gap, "pair_gap");
    if (!std::isfinite(m.opt_o_margin)) throw InputError("opt_o_margin: not a finite number");
    if (m.opt_collision < 0 || m.opt_collision > 2) throw InputError("opt_collision: 0, 1 or 2");
    f.nq = m.nq;
    for (size_t b = 0; b < nbody; ++b) {
        need_index(m.body_parentid[b], nbody, "body_parentid[" + std::to_string(b) + "]");
        need_index(m.body_weldid[b], nbody, "body_weldid[" + std::to_string(b) + "]");
        f.body_parent.push_back(m.body_parentid[b]);
        f.body_weld.push_back(m.body_weldid[b]);
        f.body_names.push_back(m.body_names.empty() ? "" : m.body_names[b]);
    }
    const size_t nvert = m.mesh_vert.size() / 3;
    for (size_t i = 0; i < ngeom; ++i) {
        const std::string at = "[" + std::to_string(i) + "]";
        internal::mj::Geom o;
        o.name = m.geom_names.empty() ? "" : m.geom_names[i];
        if (m.geom_type[i] < 0 || m.geom_type[i] > internal::mj::kMesh)
            throw InputError("held model: geom_type" + at + " = " + std::to_string(m.geom_type[i]) +
                             " is no MuJoCo 2.2.2 geom type (0 to 7)");
        o.type = m.geom_type[i];
        need_index(m.geom_bodyid[i], nbody, "geom_bodyid" + at);
        o.body = m.geom_bodyid[i];
        o.contype = m.geom_contype[i];
        o.conaffinity = m.geom_conaffinity[i];
        for (size_t k = 0; k < 3; ++k) o.size[k] = m.geom_size[3 * i + k];
        o.margin = m.geom_margin[i];
        o.gap = m.geom_gap[i];
        if (o.type == internal::mj::kMesh && m.geom_dataid[i] >= 0) {
            need_index(m.geom_dataid[i], nmesh, "geom_dataid" + at);
            const size_t k = static_cast<size_t>(m.geom_dataid[i]);
            const int adr = m.mesh_vertadr[k], num = m.mesh_vertnum[k];
            if (adr < 0 || num < 0 || static_cast<size_t>(adr) + static_cast<size_t>(num) > nvert)
                throw InputError("held model: mesh " + std::to_string(k) + "'s vertices (mesh_vertadr " +
                                 std::to_string(adr) + ", mesh_vertnum " + std::to_string(num) + ") pass mesh_vert's " +
                                 std::to_string(nvert));
            o.vertices.assign(m.mesh_vert.begin() + 3 * adr, m.mesh_vert.begin() + 3 * (adr + num));
        }
        f.geoms.push_back(std::move(o));
    }
    for (size_t p = 0; p < npair; ++p) {
        need_index(m.pair_geom1[p], ngeom, "pair_geom1[" + std::to_string(p) + "]");
        need_index(m.pair_geom2[p], ngeom, "pair_geom2[" + std::to_string(p) + "]");
        f.pairs.push_back({m.pair_geom1[p], m.pair_geom2[p], m.pair_margin[p], m.pair_gap[p]});
    }
    f.excludes = m.exclude_signature;
    f.disableflags = m.opt_disableflags;
    f.enableflags = m.opt_enableflags;
    f.collision = m.opt_collision;
    f.o_margin = m.opt_o_margin;
    return f;
}
}  // namespace

MujocoJudgement judge_mujoco(const std::string& model, const std::vector<std::vector<double>>& qpos,
                             const MujocoOptions& options) {
    check_options(options);
    const std::unique_ptr<internal::mj::Loaded> m = internal::mj::load_model(model);
    std::vector<std::string> labels;
    const std::vector<std::vector<double>> states = internal::mj::choose_states(m->info(), qpos, labels, options.key);
    return judged(*m, states, labels, options, model);
}

MujocoJudgement judge_mujoco_held(const MujocoHeldModel& model, const std::vector<MujocoHeldData>& data,
                                  const MujocoOptions& options, const std::string& source) {
    check_options(options);
    if (data.empty()) throw InputError("held data: no state to judge");
    internal::mj::ModelInfo info = held_info(model);
    const size_t ngeom = info.geoms.size();
    std::vector<internal::mj::State> states;
    std::vector<std::vector<double>> qpos;
    std::vector<std::string> labels;
    for (size_t i = 0; i < data.size(); ++i) {
        const MujocoHeldData& d = data[i];
        const std::string at = "held data[" + std::to_string(i) + "]: ";
        if (d.qpos.size() != static_cast<size_t>(model.nq))
            throw InputError(at + "qpos has " + std::to_string(d.qpos.size()) + " numbers, nq is " +
                             std::to_string(model.nq));
        if (d.geom_xpos.size() != 3 * ngeom || d.geom_xmat.size() != 9 * ngeom)
            throw InputError(at + "geom_xpos and geom_xmat must hold 3 and 9 numbers a geom (" + std::to_string(ngeom) +
                             " geoms)");
        internal::mj::State s;
        if (d.contact_buffer_full) s.warnings.push_back("the contact buffer is full (the program's data said so)");
        s.xpos = d.geom_xpos;
        s.xmat = d.geom_xmat;
        for (size_t k = 0; k < d.contact.size(); ++k) {
            const MujocoHeldContact& c = d.contact[k];
            need_index(c.geom1, ngeom, at + "contact[" + std::to_string(k) + "].geom1");
            need_index(c.geom2, ngeom, at + "contact[" + std::to_string(k) + "].geom2");
            internal::mj::Contact o;
            o.g1 = c.geom1;
            o.g2 = c.geom2;
            o.dist = c.dist;
            for (size_t j = 0; j < 3; ++j) o.pos[j] = c.pos[j];
            for (size_t j = 0; j < 9; ++j) o.frame[j] = c.frame[j];
            o.includemargin = c.includemargin;
            o.exclude = c.exclude;
            s.contacts.push_back(o);
        }
        states.push_back(std::move(s));
        qpos.push_back(d.qpos);
        labels.push_back("data[" + std::to_string(i) + "]");
    }
    Held held(std::move(info), std::move(states));
    return judged(held, qpos, labels, options, source);
}

}  // namespace scalecert
