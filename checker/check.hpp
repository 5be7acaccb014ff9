// scalecert-check: an independent checker for scalecert certificates (partition files, query
// answers, certify-fp's judgements, and their compound forms for objects made of parts). It
// shares no code with the engine: GMP rationals, the standard library and a JSON reader. Every
// claim is re-derived from the scene stored in the file, and nothing in the file is trusted: its
// kind is an explicit field, every object must have exactly the documented keys, duplicate keys
// are rejected, indices must be exact integers in range, and contact labels are recomputed from
// all maximisers. See certificates/FORMAT.md ("What the checker rejects").
//
// The checker's modules, each read beside its part of FORMAT.md:
//   context.hpp       the number types, Invalid and Unreadable, the Context (claims, work limit)
//   json.*            strict JSON and the shapes of objects ("What the checker rejects")
//   numbers.*         exact numbers and their nearest doubles ("Numbers")
//   scan.*            support scans of a polytope's vertices ("What the checker costs")
//   scene.*           the scene, seed weights and witnesses ("Fields of a partition file")
//   polygon.*         convex polygons in the written form
//   curve.*           the pieces, switch points and curve ends of a curve
//   parts.*           objects made of parts and blocks of part pairs ("A compound partition")
//   judging.*         what both judgement formats share
//   partition.cpp, query.cpp, judgements.cpp, compound_partition.cpp, compound_judgements.cpp:
//                     one format each (formats.hpp)
#pragma once
#include "context.hpp"
#include "json.hpp"  // parse_strict: the JSON value of a file's text, read as the checker reads it

#include <string>

namespace scalecert_check {
// Checks a whole file's text in cx (its counts and limit start afresh; the limit's rates are
// cx's). Returns the exit status: 0 valid, 1 invalid (the first claim that fails), 2 unreadable;
// `message` is the line to print.
int check_text(const std::string& text, std::string& message, Context& cx);
// The same with the default work limit.
int check_text(const std::string& text, std::string& message);
}  // namespace scalecert_check
