// Stage 1, mesh files: the vertices of a polyhedron from OFF, OBJ, PLY (ASCII, binary little- or
// big-endian) or STL (ASCII or binary). Only the vertices are used: the polyhedron is their
// convex hull. Text numbers are read as ReadOptions::numbers says (by default the double strtod
// gives: 0.1 is not 1/10); binary floats and doubles are their exact values.
#pragma once
#include "io/scene.hpp"

#include <string>
#include <vector>

namespace scalecert::internal {

enum class MeshFormat { Off, Obj, Ply, Stl };

// The format named by a file's extension (.off .obj .ply .stl, any case). Throws InputError
// naming the file for any other extension.
MeshFormat mesh_format_of(const std::string& path);

// The vertices of mesh text (the whole file's bytes). `name` labels errors. STL repeats each
// vertex in every triangle: its vertices come out once each, in order of first appearance.
std::vector<Vec3q> parse_mesh(const std::string& bytes, MeshFormat f, const std::string& name,
                              const ReadOptions& opt = {});

// Reads a mesh file (format by extension, at most kMaxSceneBytes).
// With `note`: a remark for the user when an OBJ file with two or more groups with faces is read
// as one convex object (the command says it once on stderr); `part`: the mesh is a part of
// "parts", which is one convex part whatever its groups, and the remark says so.
std::vector<Vec3q> read_mesh(const std::string& path, const ReadOptions& opt = {}, std::string* note = nullptr,
                             bool part = false);

// An OBJ file's groups as the parts of a compound (scalecert region --parts-from-groups): each
// 'o NAME' or 'g NAME' line starts a part, whose points are the vertices its faces ('f') name,
// each once, in the file's order (vertex numbers from 1, or back from -1, the last vertex before
// the face). The faces before any 'o' or 'g' line are a part too (a file without them is one
// part); groups without faces are skipped, and vertices no face names are in no part. Throws
// InputError naming the group (its name and line) when its points are flat or when a group with
// faces has the name of an earlier one, and past kMaxParts parts or kMaxPoints points in all. Any
// other format is refused (OFF, PLY and STL have no groups). A file without faces has no parts
// (an empty list). With `names`: each part's group name
// ("" for the faces before any 'o' or 'g' line, and for a group line without a name).
std::vector<std::vector<Vec3q>> read_obj_groups(const std::string& path, const ReadOptions& opt = {},
                                                std::vector<std::string>* names = nullptr);

// An object's mesh file: its vertices (a convex object), or with opt.parts_from_groups and an OBJ
// file its groups as parts (in.parts, and in.points all their points in order; in.part_names their
// group names, empty when no group has one). A mesh of another format has no groups, and an OBJ
// file without faces no parts: under opt.parts_from_groups each is one convex object still, so
// that one flag reads a scene of one compound OBJ and one convex STL or point list.
void read_mesh_object(const std::string& path, const ReadOptions& opt, PolyInput& in);

}  // namespace scalecert::internal
