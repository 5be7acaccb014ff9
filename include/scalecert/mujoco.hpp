// MuJoCo as the program runs it: the program's own mjModel and mjData as scalecert's held arrays
// (MujocoHeldModel, MujocoHeldData), for judge_mujoco_held (docs/library.md, "MuJoCo's own
// arrays"). Header-only; include it where the program has MuJoCo (2.2.2's mjModel and mjData
// fields), and link scalecert::core and MuJoCo.
//
//   mj_step(m, d);
//   states.push_back(scalecert::mujoco_held(m, d));
//   ...
//   auto j = scalecert::judge_mujoco_held(scalecert::mujoco_held(m), states);
#pragma once
#include "scalecert/scalecert.hpp"

#include <mujoco/mujoco.h>

#include <string>
#include <vector>

namespace scalecert {

// What the model holds: geoms, bodies, meshes' float32 vertices, <pair>s, <exclude>s, options.
inline MujocoHeldModel mujoco_held(const mjModel* m) {
    MujocoHeldModel h;
    h.nq = m->nq;
    const int ng = m->ngeom, nb = m->nbody;
    h.geom_type.assign(m->geom_type, m->geom_type + ng);
    h.geom_bodyid.assign(m->geom_bodyid, m->geom_bodyid + ng);
    h.geom_contype.assign(m->geom_contype, m->geom_contype + ng);
    h.geom_conaffinity.assign(m->geom_conaffinity, m->geom_conaffinity + ng);
    h.geom_dataid.assign(m->geom_dataid, m->geom_dataid + ng);
    h.geom_size.assign(m->geom_size, m->geom_size + 3 * ng);
    h.geom_margin.assign(m->geom_margin, m->geom_margin + ng);
    h.geom_gap.assign(m->geom_gap, m->geom_gap + ng);
    for (int g = 0; g < ng; ++g) {
        const char* n = mj_id2name(m, mjOBJ_GEOM, g);
        h.geom_names.push_back(n ? n : "");
    }
    h.body_parentid.assign(m->body_parentid, m->body_parentid + nb);
    h.body_weldid.assign(m->body_weldid, m->body_weldid + nb);
    for (int b = 0; b < nb; ++b) {
        const char* n = mj_id2name(m, mjOBJ_BODY, b);
        h.body_names.push_back(n ? n : "");
    }
    h.mesh_vertadr.assign(m->mesh_vertadr, m->mesh_vertadr + m->nmesh);
    h.mesh_vertnum.assign(m->mesh_vertnum, m->mesh_vertnum + m->nmesh);
    h.mesh_vert.assign(m->mesh_vert, m->mesh_vert + 3 * m->nmeshvert);
    h.pair_geom1.assign(m->pair_geom1, m->pair_geom1 + m->npair);
    h.pair_geom2.assign(m->pair_geom2, m->pair_geom2 + m->npair);
    h.pair_margin.assign(m->pair_margin, m->pair_margin + m->npair);
    h.pair_gap.assign(m->pair_gap, m->pair_gap + m->npair);
    h.exclude_signature.assign(m->exclude_signature, m->exclude_signature + m->nexclude);
    h.opt_disableflags = m->opt.disableflags;
    h.opt_enableflags = m->opt.enableflags;
    h.opt_collision = m->opt.collision;
    h.opt_o_margin = m->opt.o_margin;
    return h;
}

// What mj_forward or mj_step left in the data: qpos, the geoms' frames and the contacts.
inline MujocoHeldData mujoco_held(const mjModel* m, const mjData* d) {
    MujocoHeldData h;
    h.qpos.assign(d->qpos, d->qpos + m->nq);
    h.geom_xpos.assign(d->geom_xpos, d->geom_xpos + 3 * m->ngeom);
    h.geom_xmat.assign(d->geom_xmat, d->geom_xmat + 9 * m->ngeom);
    for (int i = 0; i < d->ncon; ++i) {
        const mjContact& c = d->contact[i];
        MujocoHeldContact o;
        o.geom1 = c.geom1;
        o.geom2 = c.geom2;
        o.dist = c.dist;
        for (int k = 0; k < 3; ++k) o.pos[static_cast<size_t>(k)] = c.pos[k];
        for (int k = 0; k < 9; ++k) o.frame[static_cast<size_t>(k)] = c.frame[k];
        o.includemargin = c.includemargin;
        o.exclude = c.exclude;
        h.contact.push_back(o);
    }
    h.contact_buffer_full = m->nconmax > 0 && d->ncon >= m->nconmax;
    return h;
}

}  // namespace scalecert
