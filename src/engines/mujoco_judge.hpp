// scalecert mujoco: MuJoCo's collision results at a model's states judged against the exact
// answer for the geometry MuJoCo held (CLAIMS.md, "Engines' conventions"): every geom pair its
// collision pipeline considers, as signed-distance claims at the geoms' poses.
#pragma once
#include "engines/mujoco_held.hpp"
#include "certify/claim.hpp"
#include "io/json.hpp"

#include <functional>
#include <string>
#include <vector>

namespace scalecert::internal::mj {

// A geom pair MuJoCo 2.2.2's pipeline considers: by contype and conaffinity, the weld and parent
// filters and <exclude>, or an explicit <pair>; margin and gap as it takes them (the larger of the
// geoms', a <pair>'s own, or the override's margin). An explicit <pair> replaces the filters' pair
// of the same geoms.
struct Considered {
    int g1 = 0, g2 = 0;  // g1 < g2
    double margin = 0, gap = 0;
    bool explicit_pair = false;
};
std::vector<Considered> considered_pairs(const ModelInfo& m);

// The states to judge: each qpos given (labels[i] names it in messages and the report), else
// keyframe `key` (>= 0), else qpos0. InputError for a qpos not of nq finite numbers, or a key the
// model lacks.
std::vector<std::vector<double>> choose_states(const ModelInfo& m, std::vector<std::vector<double>> qpos,
                                               std::vector<std::string>& labels, int key);

// Where a contact point p lies against a box geom g at pose [M | t], exactly (the fast path of
// judging contact positions; the claim rules decide what it leaves unsure): inside the box; within
// `len` of it (a point of the box that close was found); farther than len (outside the slab
// between two opposite faces by more than len); or unsure.
enum class BoxSide { Inside, Within, Farther, Unsure };
struct ExactPosedBox {
    Q adj[3][3], half[3], norm2[3];  // adj(M); size_k·|det M|; |adj_k|²
    Q det;                           // det M
    Pose M;
    Vec3q t;
    std::array<Q, 3> size;
    bool singular = false;
};
ExactPosedBox exact_posed_box(const Geom& g, const Pose& M);
BoxSide posed_box_side(const ExactPosedBox& b, const Vec3q& p, const Q& len);

struct MujocoOptions {
    Tolerance tolerance;
    std::string model;     // the model's path, for the report and reproducers
    std::string failures;  // a folder for reproducers of wrong judgements ("" for none)
    // Also judge each output against the model as written (--intended): the mesh files' numbers
    // as doubles, in MuJoCo's mesh frame exactly, at the same geom poses.
    bool intended = false;
};
// The states' judgements: the report as JSON, and the count of wrong judgements. `states`: each
// a qpos of nq numbers, `labels` their source ("qpos0", "key 2", "FILE line 7").
struct MujocoResult {
    Json report;
    long wrong = 0;
    std::string text;  // the wrong judgements and the summary, a line each
    // Wall-clock seconds in mj_forward and in judging (never in the report: it stays the same
    // bytes run after run).
    double forward_seconds = 0, judge_seconds = 0;
    // What MuJoCo warned of, each after its state's label (the command says them on stderr).
    std::vector<std::string> warnings;
    std::vector<std::string> warning_texts;  // the same without the labels (labels hold ": " too)
    long reproducers = 0;                    // pair states written to the failures folder (plane pairs have none)
};
MujocoResult judge_states(Loaded& model, const std::vector<std::vector<double>>& states,
                          const std::vector<std::string>& labels, const MujocoOptions& opt);

}  // namespace scalecert::internal::mj
