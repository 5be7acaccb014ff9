// What MuJoCo held and reported, in plain types: the module that links MuJoCo (mujoco_module.cpp,
// loaded on first use by mujoco_loader.cpp) fills these, and the judge (mujoco_judge.hpp) reads
// them. No MuJoCo type crosses: the core never includes MuJoCo's headers.
#pragma once
#include <memory>
#include <string>
#include <vector>

namespace scalecert::internal::mj {

// MuJoCo's geom types (mjtGeom's numbers).
enum GeomType { kPlane = 0, kHField, kSphere, kCapsule, kEllipsoid, kCylinder, kBox, kMesh };
const char* geom_type_name(int type);

struct Geom {
    std::string name;  // "" when unnamed
    int type = 0, body = 0, contype = 0, conaffinity = 0;
    double size[3] = {0, 0, 0};
    double margin = 0, gap = 0;
    // A mesh geom's vertices as MuJoCo holds them (mesh_vert: float32, in the geom's frame, after
    // MuJoCo re-centred and rotated them), three a vertex; empty for other types.
    std::vector<float> vertices;
    int mesh = -1;  // a mesh geom's mesh (geom_dataid), else -1
};
// An explicit <pair>, with its own margin and gap.
struct Pair {
    int g1 = 0, g2 = 0;
    double margin = 0, gap = 0;
};
struct ModelInfo {
    int nq = 0;
    std::vector<Geom> geoms;
    std::vector<int> body_parent, body_weld;
    std::vector<std::string> body_names;
    std::vector<Pair> pairs;
    std::vector<int> excludes;  // exclude_signature: (body1 + 1) << 16 | (body2 + 1)
    int disableflags = 0, enableflags = 0;
    int collision = 0;    // opt.collision: 0 every pair, 1 the <pair>s only, 2 the filters' pairs only
    double o_margin = 0;  // the override margin (enableflags' override bit)
    std::vector<double> qpos0;
    std::vector<std::vector<double>> keys;  // each keyframe's qpos
};
// One mjContact.
struct Contact {
    int g1 = 0, g2 = 0;
    double dist = 0;
    double pos[3] = {0, 0, 0};
    double frame[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};  // the normal, from g1 to g2, in frame[0..2]
    double includemargin = 0;
    int exclude = 0;
};
// After mj_forward at a qpos: each geom's frame (geom_xpos, geom_xmat by rows) and the contacts.
struct State {
    std::vector<double> xpos, xmat;
    std::vector<Contact> contacts;
    std::vector<std::string> warnings;  // what MuJoCo warned of during the step
    std::string error;                  // MuJoCo's error, when mj_forward failed ("" when it ran)
};

// A model loaded by MuJoCo; forward() sets qpos (nq numbers) and runs mj_forward, as a user's
// program would.
class Loaded {
  public:
    virtual ~Loaded() = default;
    virtual const ModelInfo& info() const = 0;
    virtual State forward(const std::vector<double>& qpos) = 0;
};

// The module's entry point: the model at `path`, or null with the reason in *error.
using LoadFn = Loaded* (*)(const char* path, std::string* error);

// A mesh asset as the model wrote it, and the frame MuJoCo moved its vertices to: MuJoCo holds
// mesh_vert = float32(Rᵀ(scale·v − pos)) for each vertex v of the file, R the rotation of quat
// (pos and quat MuJoCo's doubles, read off a model of that mesh alone). For --intended.
struct MeshSource {
    std::string name;
    std::string file;  // the path MuJoCo read it from
    double scale[3] = {1, 1, 1};
    double pos[3] = {0, 0, 0};
    double quat[4] = {1, 0, 0, 0};
    long vertices = 0;    // how many distinct vertices MuJoCo holds for it
    std::string why_not;  // why the mesh has no source to judge against ("" when it has)
};
// The second entry point: the model's meshes by mesh id, or false with the reason in *error.
using MeshSourcesFn = bool (*)(const char* path, std::vector<MeshSource>* out, std::string* error);
// Through the module; InputError as load_model.
std::vector<MeshSource> mesh_sources(const std::string& path);
// Through the module, loaded on first use; InputError when the model cannot be read, and when the
// module cannot be loaded (the build had no MuJoCo).
std::unique_ptr<Loaded> load_model(const std::string& path);

}  // namespace scalecert::internal::mj
