// The arrays MuJoCo holds for a model at states, by MuJoCo's own field names, as JSON: what a
// program using MuJoCo's Python bindings reads from MjModel and MjData. The Python test builds
// objects with these attributes and hands them to scalecert.judge_mujoco_held, as such a program
// would (Debian has libmujoco but not MuJoCo's Python bindings).
//   mujoco_arrays MODEL.xml QPOS_FILE   (JSON on stdout; doubles %.17g, float32s %.9g: both read back exactly)
#include <mujoco/mujoco.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {
template <class T>
void list(const char* name, const T* v, int n, const char* fmt, bool comma = true) {
    std::printf("\"%s\": [", name);
    for (int i = 0; i < n; ++i) {
        std::printf(i ? ", " : "");
        std::printf(fmt, v[i]);
    }
    std::printf("]%s", comma ? ", " : "");
}
}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) return std::fprintf(stderr, "usage: mujoco_arrays MODEL.xml QPOS_FILE\n"), 2;
    char err[500] = "";
    mjModel* m = mj_loadXML(argv[1], nullptr, err, sizeof err);
    if (!m) return std::fprintf(stderr, "mujoco_arrays: %s\n", err), 2;
    mjData* d = mj_makeData(m);
    std::printf("{\"model\": {\"nq\": %d, ", m->nq);
    list("geom_type", m->geom_type, m->ngeom, "%d");
    list("geom_bodyid", m->geom_bodyid, m->ngeom, "%d");
    list("geom_contype", m->geom_contype, m->ngeom, "%d");
    list("geom_conaffinity", m->geom_conaffinity, m->ngeom, "%d");
    list("geom_dataid", m->geom_dataid, m->ngeom, "%d");
    list("geom_size", m->geom_size, 3 * m->ngeom, "%.17g");
    list("geom_margin", m->geom_margin, m->ngeom, "%.17g");
    list("geom_gap", m->geom_gap, m->ngeom, "%.17g");
    list("body_parentid", m->body_parentid, m->nbody, "%d");
    list("body_weldid", m->body_weldid, m->nbody, "%d");
    list("mesh_vertadr", m->mesh_vertadr, m->nmesh, "%d");
    list("mesh_vertnum", m->mesh_vertnum, m->nmesh, "%d");
    std::printf("\"mesh_vert\": [");
    for (int i = 0; i < 3 * m->nmeshvert; ++i)
        std::printf("%s%.9g", i ? ", " : "", static_cast<double>(m->mesh_vert[i]));
    std::printf("], ");
    list("pair_geom1", m->pair_geom1, m->npair, "%d");
    list("pair_geom2", m->pair_geom2, m->npair, "%d");
    list("pair_margin", m->pair_margin, m->npair, "%.17g");
    list("pair_gap", m->pair_gap, m->npair, "%.17g");
    list("exclude_signature", m->exclude_signature, m->nexclude, "%d");
    list("name_geomadr", m->name_geomadr, m->ngeom, "%d");
    list("name_bodyadr", m->name_bodyadr, m->nbody, "%d");
    std::printf("\"names\": \"");
    for (int i = 0; i < m->nnames; ++i) {
        const unsigned char c = static_cast<unsigned char>(m->names[i]);
        if (c < 0x20 || c == '"' || c == '\\' || c > 0x7e)
            std::printf("\\u%04x", c);
        else
            std::putchar(c);
    }
    std::printf("\", \"opt\": {\"disableflags\": %d, \"enableflags\": %d, \"collision\": %d, \"o_margin\": %.17g}}",
                m->opt.disableflags, m->opt.enableflags, m->opt.collision, m->opt.o_margin);
    std::printf(", \"data\": [");
    std::ifstream in(argv[2]);
    bool first = true;
    for (std::string line; std::getline(in, line);) {
        std::istringstream s(line);
        std::vector<double> q;
        for (double x; s >> x;) q.push_back(x);
        if (q.size() != static_cast<size_t>(m->nq)) continue;
        mj_resetData(m, d);
        for (int k = 0; k < m->nq; ++k) d->qpos[k] = q[static_cast<size_t>(k)];
        mj_forward(m, d);
        std::printf("%s{", first ? "" : ", ");
        first = false;
        list("qpos", d->qpos, m->nq, "%.17g");
        list("geom_xpos", d->geom_xpos, 3 * m->ngeom, "%.17g");
        list("geom_xmat", d->geom_xmat, 9 * m->ngeom, "%.17g");
        std::printf("\"ncon\": %d, \"contact\": {", d->ncon);
        std::vector<int> g1, g2, ex;
        std::vector<double> dist, pos, frame, inc;
        for (int i = 0; i < d->ncon; ++i) {
            const mjContact& c = d->contact[i];
            g1.push_back(c.geom1), g2.push_back(c.geom2), ex.push_back(c.exclude);
            dist.push_back(c.dist), inc.push_back(c.includemargin);
            pos.insert(pos.end(), c.pos, c.pos + 3);
            frame.insert(frame.end(), c.frame, c.frame + 9);
        }
        const int n = d->ncon;
        list("geom1", g1.data(), n, "%d");
        list("geom2", g2.data(), n, "%d");
        list("exclude", ex.data(), n, "%d");
        list("dist", dist.data(), n, "%.17g");
        list("includemargin", inc.data(), n, "%.17g");
        list("pos", pos.data(), 3 * n, "%.17g");
        list("frame", frame.data(), 9 * n, "%.17g", false);
        std::printf("}}");
    }
    std::printf("]}\n");
    mj_deleteData(d);
    mj_deleteModel(m);
}
