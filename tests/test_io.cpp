// The reading and writing of files (src/io): strict JSON, UTF-8, shell words, regular files and
// whole outputs, integer points, meshes in every format and scene files, each against values
// worked out by hand in the comments (or, for shell words, against /bin/sh itself).
#include <boost/test/unit_test.hpp>

#include "support.hpp"

#include "files.hpp"
#include "io/files.hpp"
#include "io/int_points.hpp"
#include "io/mesh.hpp"
#include "io/scene.hpp"
#include "io/strict_json.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace scalecert::internal;
using test::input_error;

namespace {
fs::path tmpdir() {
    static const fs::path d = test::scratch_dir("io");
    return d;
}
void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }
// The JsonError of parsing text (its offset and problem), or {npos, ""} when it parses.
JsonError json_error(const std::string& text, bool non_numbers = false) {
    try {
        parse_strict_json(text, non_numbers);
    } catch (const JsonError& e) {
        return e;
    }
    return {std::string::npos, ""};
}
Q q(long p, long d = 1) {
    Q r(p, d);
    r.canonicalize();
    return r;
}
// A float's or a double's bytes, least significant first (little-endian) or most (big-endian).
template <class T>
std::string bytes_of(T v, bool big_endian) {
    std::string b(sizeof v, '\0');
    std::memcpy(&b[0], &v, sizeof v);  // x86-64 is little-endian
    if (big_endian) std::reverse(b.begin(), b.end());
    return b;
}
}  // namespace

BOOST_AUTO_TEST_CASE(strict_json_refuses_duplicate_keys_and_what_rfc_8259_refuses) {
    // {"a": 1, "a": 2}: the second key's quote is byte 9; the file would mean two things.
    const JsonError dup = json_error(R"({"a": 1, "a": 2})");
    BOOST_TEST(dup.pos == 9u);
    BOOST_TEST(dup.what == "duplicate key 'a'");
    // Keys differing in case are two keys, kept in the file's order.
    const JNode two = parse_strict_json(R"({"P1": 1, "p1": [2]})");
    BOOST_TEST_REQUIRE(two.keys.size() == 2u);
    BOOST_TEST(two.keys[1] == "p1");
    BOOST_TEST_REQUIRE(two.find("p1") != nullptr);
    BOOST_TEST(two.find("p1")->kind == JNode::Array);
    BOOST_TEST(two.find("P2") == nullptr);
    // [01]: the 1 after a leading 0 at byte 2; [1,]: a value expected at byte 3; a comment after
    // the value at byte 3; a string key expected at byte 1.
    BOOST_TEST(json_error("[01]").pos == 2u);
    BOOST_TEST(json_error("[01]").what == "a number has a leading zero");
    BOOST_TEST(json_error("[1,]").pos == 3u);
    BOOST_TEST(json_error("[1,]").what == "unexpected character");
    BOOST_TEST(json_error("{} // x").pos == 3u);
    BOOST_TEST(json_error("{} // x").what == "comments are not JSON (RFC 8259)");
    BOOST_TEST(json_error("{a: 1}").what == "expected a string key");
    BOOST_TEST(json_error("[1] [2]").what == "unexpected text after the JSON value");
    // NaN and infinities only where a program's non-finite output is read (claims files).
    BOOST_TEST(json_error("[NaN]").what == "unexpected character");
    const JNode nan = parse_strict_json("[NaN, Infinity, -Infinity, -1]", true);
    BOOST_TEST_REQUIRE(nan.items.size() == 4u);
    for (size_t k = 0; k < 4; ++k) BOOST_TEST(nan.items[k].kind == JNode::Number);
    BOOST_TEST(nan.items[0].text == "NaN");
    BOOST_TEST(nan.items[2].text == "-Infinity");
    BOOST_TEST(nan.items[3].text == "-1");
    // 64 levels of nesting are read; the 65th '[' (byte 64) is refused.
    BOOST_TEST(json_error(std::string(64, '[') + std::string(64, ']')).what == "");
    const JsonError deep = json_error(std::string(65, '[') + std::string(65, ']'));
    BOOST_TEST(deep.pos == 64u);
    BOOST_TEST(deep.what == "nested deeper than 64 levels");
    // Numbers keep their text as written (0.1 can then be read as 1/10).
    const JNode nums = parse_strict_json("[0.1, -0, 1E+2, 123456789012345678901234567890]");
    BOOST_TEST_REQUIRE(nums.items.size() == 4u);
    BOOST_TEST(nums.items[0].text == "0.1");
    BOOST_TEST(nums.items[1].text == "-0");
    BOOST_TEST(nums.items[2].text == "1E+2");
    BOOST_TEST(nums.items[3].text == "123456789012345678901234567890");
}

BOOST_AUTO_TEST_CASE(json_strings_are_utf8_with_paired_surrogates) {
    // \u00e9 is é, C3 A9 in UTF-8; \ud83d\ude00 is U+1F600, F0 9F 98 80.
    BOOST_TEST(parse_strict_json(R"(["\u00e9"])").items[0].text == "\xC3\xA9");
    BOOST_TEST(parse_strict_json(R"(["\ud83d\ude00"])").items[0].text == "\xF0\x9F\x98\x80");
    BOOST_TEST(parse_strict_json("[\"\xC3\xA9\"]").items[0].text == "\xC3\xA9");
    BOOST_TEST(json_error(R"(["\ude00"])").what == "unpaired surrogate in a \\u escape");
    BOOST_TEST(json_error(R"(["\ud83d x"])").what == "unpaired surrogate in a \\u escape");
    BOOST_TEST(json_error("[\"a\tb\"]").what == "control character in a string");
    BOOST_TEST(json_error("[\"\xFF\"]").what == "invalid UTF-8");
    BOOST_TEST(json_error(R"(["\q"])").what == "invalid escape in a string");
    // Sequence lengths: ASCII 1, é 2, € (E2 82 AC) 3, U+1F600 4, U+10FFFF (F4 8F BF BF) 4; none
    // (0) for the overlong C0 80 and E0 80 80, the surrogate U+D800 (ED A0 80), past U+10FFFF
    // (F4 90 80 80), a lead byte at the end, and a lead byte without its continuation.
    const std::vector<std::pair<std::string, size_t>> seqs = {
        {"A", 1},        {"\xC3\xA9", 2},     {"\xE2\x82\xAC", 3}, {"\xF0\x9F\x98\x80", 4}, {"\xF4\x8F\xBF\xBF", 4},
        {"\xC0\x80", 0}, {"\xE0\x80\x80", 0}, {"\xED\xA0\x80", 0}, {"\xF4\x90\x80\x80", 0}, {"\xC3", 0},
        {"\xC3\x41", 0}, {"\x80", 0}};
    for (size_t k = 0; k < seqs.size(); ++k) BOOST_TEST(utf8_sequence_length(seqs[k].first, 0) == seqs[k].second, k);
    BOOST_TEST(is_utf8("caf\xC3\xA9 \xE2\x82\xAC"));
    BOOST_TEST(!is_utf8("caf\xC3"));
    BOOST_TEST(is_utf8(""));
}

BOOST_AUTO_TEST_CASE(shell_words_read_back_as_themselves) {
    // Letters, digits and _./- stand as they are; anything else goes in single quotes, a quote
    // inside written '\''.
    BOOST_TEST(shell_word("build/scalecert") == "build/scalecert");
    BOOST_TEST(shell_word("a-b_c.1/2") == "a-b_c.1/2");
    BOOST_TEST(shell_word("") == "''");
    BOOST_TEST(shell_word("a b") == "'a b'");
    BOOST_TEST(shell_word("it's") == "'it'\\''s'");
    BOOST_TEST(shell_word("$HOME") == "'$HOME'");
    BOOST_TEST(shell_word("~") == "'~'");
    // /bin/sh reads each word back as the text it quotes.
    const fs::path out = tmpdir() / "word.txt";
    for (const std::string& w :
         {std::string("plain"), std::string(""), std::string("two words"), std::string("it's"), std::string("'''"),
          std::string("a\"b\\c"), std::string("$(echo no) `echo no` $HOME"), std::string("line\nbreak\ttab"),
          std::string("*?[a]{b,c}~!#&;|<>()"), std::string("caf\xC3\xA9"), std::string("-n")}) {
        const std::string cmd = "printf '%s' " + shell_word(w) + " > " + shell_word(out.string());
        BOOST_TEST_REQUIRE(std::system(cmd.c_str()) == 0, cmd);
        BOOST_TEST(test::slurp(out) == w, cmd);
    }
}

BOOST_AUTO_TEST_CASE(only_regular_files_are_read_and_within_their_limit) {
    const fs::path dir = tmpdir() / "a folder", fifo = tmpdir() / "pipe", missing = tmpdir() / "missing.json",
                   mib = tmpdir() / "one_mib.off", link = tmpdir() / "link.off";
    fs::create_directories(dir);
    BOOST_TEST(input_error([&] { read_regular_file(dir.string(), "scene file", 1 << 20); }) ==
               dir.string() + ": is a directory, not a scene file (only regular files are read)");
    // A FIFO with no writer: refused at once, not waited on.
    BOOST_TEST_REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    BOOST_TEST(input_error([&] { read_regular_file(fifo.string(), "mesh file", 1 << 20); }) ==
               fifo.string() + ": is a named pipe (FIFO), not a mesh file (only regular files are read)");
    BOOST_TEST(input_error([&] { read_regular_file(missing.string(), "claims file", 1 << 20); }) ==
               missing.string() + ": cannot open claims file (No such file or directory)");
    // 1 MiB exactly is within a limit of 1 MiB; one byte more is not.
    write(mib, std::string(1 << 20, 'x'));
    BOOST_TEST(read_regular_file(mib.string(), "mesh file", 1 << 20).size() == size_t(1) << 20);
    write(mib, std::string((1 << 20) + 1, 'x'));
    BOOST_TEST(input_error([&] { read_regular_file(mib.string(), "mesh file", 1 << 20); }) ==
               mib.string() + ": mesh file larger than 1 MiB (the limit)");
    // A symbolic link is followed unless refused by name.
    write(mib, "OFF\n");
    fs::create_symlink(mib, link);
    BOOST_TEST(read_regular_file(link.string(), "mesh file", 1 << 20) == "OFF\n");
    BOOST_TEST(input_error([&] { read_regular_file(link.string(), "mesh file", 1 << 20, true); }) ==
               link.string() + ": is a symbolic link, not a mesh file (only regular files are read)");
    // What is read is passed to the observer, with the path as given.
    std::vector<std::pair<std::string, std::string>> seen;
    {
        InputObserver watch([&](const std::string& p, const std::string& b) { seen.push_back({p, b}); });
        read_regular_file(mib.string(), "mesh file", 100);
    }
    read_regular_file(mib.string(), "mesh file", 100);  // no observer any more
    BOOST_TEST_REQUIRE(seen.size() == 1u);
    BOOST_TEST(seen[0].first == mib.string());
    BOOST_TEST(seen[0].second == "OFF\n");
}

BOOST_AUTO_TEST_CASE(outputs_are_written_whole_beside_their_target) {
    const fs::path out = tmpdir() / "out" / "cert.json", dir = tmpdir() / "out" / "a folder";
    fs::create_directories(dir);
    write_file_atomically(out.string(), "first");
    BOOST_TEST(test::slurp(out) == "first");
    write_file_atomically(out.string(), "second, longer");
    BOOST_TEST(test::slurp(out) == "second, longer");
    BOOST_TEST(input_error([&] { write_file_atomically(dir.string(), "x"); }) ==
               dir.string() + ": exists and is not a regular file (refused as an output)");
    write_files_atomically(
        {{(tmpdir() / "out" / "a.csv").string(), "a"}, {(tmpdir() / "out" / "b.csv").string(), "b"}});
    // No temporary file is left beside them: the folder holds what was written, and the folder.
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(tmpdir() / "out")) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    BOOST_TEST((names == std::vector<std::string>{"a folder", "a.csv", "b.csv", "cert.json"}));
    BOOST_TEST(test::slurp(tmpdir() / "out" / "b.csv") == "b");
}

BOOST_AUTO_TEST_CASE(integer_points_share_one_scale_within_2_to_the_53) {
    // (1/2, 1/3, 0) and (1/6, 1, -2) over their common denominator 6: (3, 2, 0) and (1, 6, -12).
    const std::optional<IntPoints> p = int_points({{q(1, 2), q(1, 3), q(0)}, {q(1, 6), q(1), q(-2)}});
    BOOST_TEST_REQUIRE(p.has_value());
    BOOST_TEST(p->scale == 6);
    BOOST_TEST((p->x == std::vector<std::int64_t>{3, 2, 0, 1, 6, -12}));
    BOOST_TEST(p->size() == 2u);
    BOOST_TEST((p->point(1) == Vec3q{q(1, 6), q(1), q(-2)}));
    BOOST_TEST((p->mean() == Vec3q{q(1, 3), q(2, 3), q(-1)}));  // ((1/2 + 1/6)/2, (1/3 + 1)/2, -2/2)
    // |coordinate x scale| <= 2^53: 2^53 itself fits, 2^53 + 1 does not; and with a half among
    // the points (scale 2), 2^52 fits (2^53) and 2^52 + 1/2 does not (2^53 + 1).
    const Q two53(Z(1) << 53), two52(Z(1) << 52);
    BOOST_TEST(int_points({{two53, q(0), -two53}}).has_value());
    BOOST_TEST(!int_points({{two53 + 1, q(0), q(0)}}).has_value());
    BOOST_TEST(!int_points({{q(0), q(0), -two53 - 1}}).has_value());
    const std::optional<IntPoints> h = int_points({{q(1, 2), q(0), q(0)}, {two52, q(0), q(0)}});
    BOOST_TEST_REQUIRE(h.has_value());
    BOOST_TEST(h->scale == 2);
    BOOST_TEST(h->x[3] == std::int64_t(1) << 53);
    BOOST_TEST(!int_points({{q(1, 2), q(0), q(0)}, {two52 + q(1, 2), q(0), q(0)}}).has_value());
    // The compact OFF reader: decimals that are doubles exactly (0.5, 1.5) under Double; 0.1 is
    // not one (left to the full reader), and under Exact it is 1/10.
    const std::string off = "OFF\n4 0 0\n0 0 0\n0.5 0 0\n0 1.5 0\n0 0 -2\n";
    const std::optional<IntPoints> o = parse_off_fast(off, Numbers::Double);
    BOOST_TEST_REQUIRE(o.has_value());
    BOOST_TEST(o->size() == 4u);
    BOOST_TEST(
        (q_points(*o) ==
         std::vector<Vec3q>{{q(0), q(0), q(0)}, {q(1, 2), q(0), q(0)}, {q(0), q(3, 2), q(0)}, {q(0), q(0), q(-2)}}));
    const std::string tenth = "OFF\n4 0 0\n0 0 0\n0.1 0 0\n0 1 0\n0 0 1\n";
    BOOST_TEST(!parse_off_fast(tenth, Numbers::Double).has_value());
    const std::optional<IntPoints> e = parse_off_fast(tenth, Numbers::Exact);
    BOOST_TEST_REQUIRE(e.has_value());
    BOOST_TEST((e->point(1) == Vec3q{q(1, 10), q(0), q(0)}));
}

BOOST_AUTO_TEST_CASE(a_tetrahedron_reads_alike_in_every_mesh_format) {
    // The tetrahedron (0, 0, 0), (1/2, 0, 0), (0, -3, 0), (0, 0, 1/4): every coordinate a float
    // exactly, so text and binary files give the same rationals.
    const std::vector<Vec3q> tetra = {
        {q(0), q(0), q(0)}, {q(1, 2), q(0), q(0)}, {q(0), q(-3), q(0)}, {q(0), q(0), q(1, 4)}};
    const double v[4][3] = {{0, 0, 0}, {0.5, 0, 0}, {0, -3, 0}, {0, 0, 0.25}};
    const int faces[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};  // first appearance: 0, 1, 2, 3
    // OBJ in homogeneous coordinates (w = 2 halves x, y, z), with a comment and a face.
    const std::string obj = "# a tetrahedron\nv 0 0 0\nv 1 0 0 2\nv 0 -3 0\nv 0 0 0.25\nf 1 2 3\n";
    const std::string off = "OFF\n4 4 0\n0 0 0\n0.5 0 0\n0 -3 0\n0 0 0.25\n3 0 1 2\n3 0 1 3\n3 0 2 3\n3 1 2 3\n";
    // ASCII PLY with a face element before the vertices (skipped) and a colour property beside them.
    std::string ply_ascii =
        "ply\nformat ascii 1.0\ncomment made by hand\nelement face 1\nproperty list uchar int vertex_indices\n"
        "element vertex 4\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nend_header\n"
        "3 0 1 2\n";
    for (const auto& p : v)
        ply_ascii += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + " 255\n";
    // Binary PLY: floats little-endian, doubles big-endian.
    std::string ply_le =
                    "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                    "property float z\nend_header\n",
                ply_be =
                    "ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
                    "property double z\nend_header\n";
    for (const auto& p : v)
        for (double c : p) {
            ply_le += bytes_of(static_cast<float>(c), false);
            ply_be += bytes_of(c, true);
        }
    // STL, ASCII and binary (80 bytes of header, the count, 50 bytes a triangle): each vertex in
    // every face that has it, read once each.
    std::string stl_ascii = "solid t\n", stl_bin(80, ' ');
    stl_bin += bytes_of(std::uint32_t(4), false);
    for (const auto& f : faces) {
        stl_ascii += "facet normal 0 0 0\nouter loop\n";
        stl_bin += bytes_of(0.0f, false) + bytes_of(0.0f, false) + bytes_of(0.0f, false);
        for (int k : f) {
            stl_ascii += "vertex " + std::to_string(v[k][0]) + " " + std::to_string(v[k][1]) + " " +
                         std::to_string(v[k][2]) + "\n";
            for (double c : v[k]) stl_bin += bytes_of(static_cast<float>(c), false);
        }
        stl_ascii += "endloop\nendfacet\n";
        stl_bin += std::string(2, '\0');
    }
    stl_ascii += "endsolid t\n";
    BOOST_TEST_REQUIRE(stl_bin.size() == 84u + 4u * 50u);
    const std::vector<std::pair<std::string, std::pair<MeshFormat, std::string>>> files = {
        {"OFF", {MeshFormat::Off, off}},
        {"OBJ", {MeshFormat::Obj, obj}},
        {"ASCII PLY", {MeshFormat::Ply, ply_ascii}},
        {"little-endian PLY", {MeshFormat::Ply, ply_le}},
        {"big-endian PLY", {MeshFormat::Ply, ply_be}},
        {"ASCII STL", {MeshFormat::Stl, stl_ascii}},
        {"binary STL", {MeshFormat::Stl, stl_bin}}};
    for (const auto& [what, file] : files) BOOST_TEST((parse_mesh(file.second, file.first, what) == tetra), what);
    // The format by extension, any case.
    BOOST_TEST((mesh_format_of("a/b.OFF") == MeshFormat::Off));
    BOOST_TEST((mesh_format_of("b.Obj") == MeshFormat::Obj));
    BOOST_TEST((mesh_format_of("c.ply") == MeshFormat::Ply));
    BOOST_TEST((mesh_format_of("d.StL") == MeshFormat::Stl));
    BOOST_TEST(input_error([] { mesh_format_of("e.txt"); }) ==
               "e.txt: unknown mesh format (expected .off, .obj, .ply or .stl)");
    BOOST_TEST(input_error([] { parse_mesh("v 1 2 3 0\n", MeshFormat::Obj, "w.obj"); }) ==
               "w.obj: line 1: w = 0 (a point at infinity)");
}

BOOST_AUTO_TEST_CASE(mesh_decimals_are_read_as_numbers_says) {
    // 0.1 as a double is 3602879701896397 / 2^55, as a float 13421773 / 2^27, as written 1/10.
    const Q dbl(Z("3602879701896397"), Z("36028797018963968")), flt(Z(13421773), Z(134217728));
    const std::string off = "OFF\n4 0 0\n0.1 0 0\n1 0 0\n0 1 0\n0 0 1\n";
    ReadOptions opt;
    long inexact = 0;
    opt.inexact = &inexact;
    BOOST_TEST(parse_mesh(off, MeshFormat::Off, "t.off", opt)[0][0] == dbl);
    BOOST_TEST(inexact == 1);  // one number not read as written
    opt.numbers = Numbers::Float32;
    BOOST_TEST(parse_mesh(off, MeshFormat::Off, "t.off", opt)[0][0] == flt);
    opt.numbers = Numbers::Exact;
    BOOST_TEST(parse_mesh(off, MeshFormat::Off, "t.off", opt)[0][0] == q(1, 10));
    // A binary float is its own value, whatever numbers says.
    std::string stl(80, ' ');
    stl += bytes_of(std::uint32_t(1), false) + std::string(12, '\0');
    for (float c : {0.1f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f}) stl += bytes_of(c, false);
    stl += std::string(2, '\0');
    BOOST_TEST(parse_mesh(stl, MeshFormat::Stl, "t.stl", opt)[0][0] == flt);
}

BOOST_AUTO_TEST_CASE(obj_groups_are_the_parts_of_an_object) {
    // Two tetrahedra as groups 'left' and 'right'; the right one's faces number its vertices back
    // from the face (-1 the last vertex before it). Vertex 9 is on no face: in no part.
    const fs::path p = tmpdir() / "two.obj";
    write(p,
          "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
          "g left\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n"
          "v 5 0 0\nv 6 0 0\nv 5 1 0\nv 5 0 1\nv 9 9 9\n"
          "g right\nf -5 -4 -3\nf -5 -4 -2\nf -5 -3 -2\nf -4 -3 -2\n");
    std::vector<std::string> names;
    const std::vector<std::vector<Vec3q>> parts = read_obj_groups(p.string(), {}, &names);
    BOOST_TEST_REQUIRE(parts.size() == 2u);
    BOOST_TEST((names == std::vector<std::string>{"left", "right"}));
    BOOST_TEST((parts[0] ==
                std::vector<Vec3q>{{q(0), q(0), q(0)}, {q(1), q(0), q(0)}, {q(0), q(1), q(0)}, {q(0), q(0), q(1)}}));
    BOOST_TEST((parts[1] ==
                std::vector<Vec3q>{{q(5), q(0), q(0)}, {q(6), q(0), q(0)}, {q(5), q(1), q(0)}, {q(5), q(0), q(1)}}));
}

BOOST_AUTO_TEST_CASE(a_scene_file_reads_exactly) {
    // P1 without a seed: the mean of its points, (1/2, 1/2, 1/2). P2 at the pose [R | t] that
    // turns a quarter about z and moves 1 along x: (x, y, z) -> (1 - y, x, z), its seed too.
    // I2's 0.5 is a double exactly.
    const std::string text = R"({"P1": {"vertices": [[0, 0, 0], [2, 0, 0], [0, 2, 0], [0, 0, 2]]},
 "P2": {"vertices": [[3, 0, 0], [4, 0, 0], [3, 1, 0], [3, 0, "1/3"]], "seed": ["7/2", "1/4", "1/12"],
        "pose": [[0, -1, 0, 1], [1, 0, 0, 0], [0, 0, 1, 0]]},
 "I1": ["1/2", 2], "I2": [0.5, "3"]})";
    const ExactScene sc = parse_scene_text(text, "s.json", ".");
    BOOST_TEST((sc.P[0].seed == Vec3q{q(1, 2), q(1, 2), q(1, 2)}));
    BOOST_TEST(!sc.P[0].seed_given);
    BOOST_TEST((sc.P[1].points ==
                std::vector<Vec3q>{{q(1), q(3), q(0)}, {q(1), q(4), q(0)}, {q(0), q(3), q(0)}, {q(1), q(3), q(1, 3)}}));
    BOOST_TEST((sc.P[1].seed == Vec3q{q(3, 4), q(7, 2), q(1, 12)}));
    BOOST_TEST(sc.lo[0] == q(1, 2));
    BOOST_TEST(sc.hi[0] == q(2));
    BOOST_TEST(sc.lo[1] == q(1, 2));
    BOOST_TEST(sc.hi[1] == q(3));
    BOOST_TEST(sc.inexact_numbers == 0);
    BOOST_TEST(scene_notes(sc).empty());
}

BOOST_AUTO_TEST_CASE(scene_numbers_are_read_as_numbers_says) {
    // I1's 0.1 as a double (3602879701896397 / 2^55), said once in the notes; as written 1/10; a
    // JSON string "0.1" is exact always.
    const std::string box = R"([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])";
    const std::string text =
        R"({"P1": {"vertices": )" + box + R"(}, "P2": {"vertices": )" + box + R"(}, "I1": [0.1, 1], "I2": ["0.1", 1]})";
    const ExactScene d = parse_scene_text(text, "s.json", ".");
    BOOST_TEST(d.lo[0] == Q(Z("3602879701896397"), Z("36028797018963968")));
    BOOST_TEST(d.lo[1] == q(1, 10));
    BOOST_TEST(d.inexact_numbers == 1);
    const std::vector<std::string> notes = scene_notes(d);
    BOOST_TEST_REQUIRE(notes.size() == 1u);
    BOOST_TEST(notes[0].rfind("1 number written as decimals is not a double exactly", 0) == 0, notes[0]);
    ReadOptions exact;
    exact.numbers = Numbers::Exact;
    const ExactScene e = parse_scene_text(text, "s.json", ".", exact);
    BOOST_TEST(e.lo[0] == q(1, 10));
    BOOST_TEST(e.inexact_numbers == 0);
}

BOOST_AUTO_TEST_CASE(an_object_reads_its_points_as_its_numbers_says) {
    // P1's points as float32 (0.1 is 13421773/2^27), its pose as the scene reads it (the double
    // 0.1 = 3602879701896397/2^55, added to x); P2's points exact (1/10). Each reading's inexact
    // numbers are counted apart: P1's one 0.1, the pose's one.
    const std::string text = R"({"P1": {"vertices": [[0.1, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
        "numbers": "float32", "pose": [[1, 0, 0, 0.1], [0, 1, 0, 0], [0, 0, 1, 0]]},
 "P2": {"vertices": [[0.1, 5, 5], [1, 5, 5], [0, 6, 5], [0, 5, 6]], "numbers": "exact"}})";
    const ExactScene sc = parse_scene_text(text, "s.json", ".");
    const Q flt(Z(13421773), Z(134217728)), dbl(Z("3602879701896397"), Z("36028797018963968"));
    BOOST_TEST(sc.P[0].points[0][0] == flt + dbl);
    BOOST_TEST(sc.P[0].points[1][0] == Q(1) + dbl);
    BOOST_TEST(sc.P[1].points[0][0] == q(1, 10));
    BOOST_TEST(sc.inexact_numbers == 1);
    BOOST_TEST(sc.inexact_by_reading[static_cast<size_t>(Numbers::Float32)] == 1);
    const std::vector<std::string> notes = scene_notes(sc);
    BOOST_TEST_REQUIRE(notes.size() == 2u);
    BOOST_TEST(notes[1].rfind("1 number of objects whose \"numbers\" is \"float32\" is not a float32 exactly", 0) == 0,
               notes[1]);
    // Without I1 and I2, both ranges are [1, 1]: the objects as they are.
    BOOST_TEST(sc.lo[0] == q(1));
    BOOST_TEST(sc.hi[0] == q(1));
    BOOST_TEST(sc.lo[1] == q(1));
    BOOST_TEST(sc.hi[1] == q(1));
    // A part's own reading wins over its object's: part 0 float32, part 1 the object's exact.
    const std::string box = R"([[0.1, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])";
    const std::string parts = R"({"P1": {"parts": [{"vertices": )" + box + R"(, "numbers": "float32"}, {"vertices": )" +
                              box + R"(}], "numbers": "exact"}, "P2": {"vertices": )" + box + R"(}, "I1": [1, 2]})";
    ReadOptions with_parts;
    with_parts.allow_parts = true;
    const ExactScene sp = parse_scene_text(parts, "p.json", ".", with_parts);
    BOOST_TEST(sp.P[0].parts[0][0][0] == flt);
    BOOST_TEST(sp.P[0].parts[1][0][0] == q(1, 10));
    BOOST_TEST(sp.P[1].points[0][0] == dbl);
    BOOST_TEST(sp.hi[0] == q(2));
    BOOST_TEST(sp.hi[1] == q(1));
    BOOST_TEST(input_error([&] {
                   parse_scene_text(R"({"P1": {"vertices": )" + box + R"(, "numbers": "single"}})", "n.json", ".");
               }) ==
               "n.json: P1.numbers: expected \"double\", \"float32\" or \"exact\" (how this object's points are "
               "read)");
}

BOOST_AUTO_TEST_CASE(bad_scenes_are_refused_naming_the_field) {
    const std::string box = R"([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])";
    auto scene = [&](const std::string& rest) {
        return R"({"P1": {"vertices": )" + box + R"(}, "P2": {"vertices": )" + box + "}" + rest + "}";
    };
    auto error = [](const std::string& text) { return input_error([&] { parse_scene_text(text, "s.json", "."); }); };
    // {"I1": [1, 2], "I1": ...: the second key's quote is byte 15.
    BOOST_TEST(error(R"({"I1": [1, 2], "I1": [1, 3]})") == "s.json: malformed JSON near byte 15: duplicate key 'I1'");
    BOOST_TEST(error(scene(R"(, "I1": [1, 2], "I2": [1, 2], "P3": 1)")) ==
               "s.json: unknown field 'P3' (expected P1, P2, I1, I2)");
    BOOST_TEST(error(scene(R"(, "I1": [2, 1], "I2": [1, 2])")) == "s.json: I1: lo > hi");
    BOOST_TEST(error(scene(R"(, "I1": [1, 2], "I2": [0, 2])")) == "s.json: I2: lo must be > 0 (got '0')");
    BOOST_TEST(error(R"({"P1": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}, "P2": {"vertices": )" + box +
                     R"(}, "I1": [1, 2], "I2": [1, 2]})") == "s.json: P1: fewer than 4 vertices (3)");
    // A pose whose R has a row twice another's: flat.
    BOOST_TEST(error(R"({"P1": {"vertices": )" + box + R"(}, "P2": {"vertices": )" + box +
                     R"(, "pose": [[1, 2, 3, 0], [2, 4, 6, 0], [0, 0, 1, 0]]}, "I1": [1, 2], "I2": [1, 2]})") ==
               "s.json: P2.pose: its 3x3 part R is singular (determinant 0): the object would be flat");
}

BOOST_AUTO_TEST_CASE(a_pose_is_singular_exactly_when_its_determinant_is_0) {
    auto pose = [](const std::array<std::array<Q, 3>, 3>& r) {
        Pose m;
        for (size_t i = 0; i < 3; ++i)
            for (size_t k = 0; k < 4; ++k) m[i][k] = k < 3 ? r[i][k] : Q(7);
        return m;
    };
    // Row 2 twice row 1: det 0. det [[1/3, 1/6], [2/3, 1/2]] = 1/6 - 1/9 = 1/18.
    BOOST_TEST(pose_singular(pose({{{q(1, 3), q(1, 6), q(0)}, {q(2, 3), q(1, 3), q(0)}, {q(0), q(0), q(1)}}})));
    BOOST_TEST(!pose_singular(pose({{{q(1, 3), q(1, 6), q(0)}, {q(2, 3), q(1, 2), q(0)}, {q(0), q(0), q(1)}}})));
    // det [[1, 1], [1, 1 + 2^-60]] = 2^-60: nonsingular, though its doubles are singular.
    const Q tiny(Z(1), Z(1) << 60);
    BOOST_TEST(!pose_singular(pose({{{q(1), q(1), q(0)}, {q(1), 1 + tiny, q(0)}, {q(0), q(0), q(1)}}})));
    BOOST_TEST(pose_singular(pose({{{q(1), q(1), q(0)}, {q(1), q(1), q(0)}, {q(0), q(0), q(1)}}})));
}
