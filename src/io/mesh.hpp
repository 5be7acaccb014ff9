// Stage 1, mesh files: the vertices of a polyhedron from OFF, OBJ, PLY (ASCII, binary little- or
// big-endian) or STL (ASCII or binary). Only the vertices are used: the polyhedron is their
// convex hull. Text numbers are exact as written (0.1 is 1/10; with binary_doubles, the double
// strtod gives); binary floats and doubles are their exact values.
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
std::vector<Vec3q> parse_mesh(const std::string& bytes, MeshFormat f, const std::string& name, const ReadOptions& opt = {});

// Reads a mesh file (format by extension, at most kMaxSceneBytes).
std::vector<Vec3q> read_mesh(const std::string& path, const ReadOptions& opt = {});

}  // namespace scalecert::internal
