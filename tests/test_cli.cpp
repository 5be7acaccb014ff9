// The command line: every bad input gets one line "scalecert: error: ...", exit status 2, nothing
// on standard output and no output file.
#define BOOST_TEST_MODULE cli
#include <boost/test/unit_test.hpp>

#include "files.hpp"

#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {
struct Run {
    int status;
    std::string out, err;
};

using test::slurp;

fs::path workdir() {
    static fs::path d = test::scratch_dir("cli");
    return d;
}

Run run(const std::string& args) {
    fs::path o = workdir() / "stdout", e = workdir() / "stderr";
    std::string cmd = std::string(SCALECERT_BIN) + " " + args + " >" + o.string() + " 2>" + e.string();
    int st = std::system(cmd.c_str());
    return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, slurp(o), slurp(e)};
}

fs::path write(const std::string& name, const std::string& text) {
    fs::path p = workdir() / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
}

const std::string kCube1 = R"([[0,0,0],[2,0,0],[0,2,0],[2,2,0],[0,0,2],[2,0,2],[0,2,2],[2,2,2]])";
const std::string kCube2 = R"([[0,0,3],[2,0,3],[0,2,3],[2,2,3],[0,0,5],[2,0,5],[0,2,5],[2,2,5]])";

std::string scene(const std::string& p1, const std::string& p2, const std::string& i1 = "[0.5, 2.5]",
                  const std::string& i2 = "[0.5, 2.5]") {
    return "{\"P1\": " + p1 + ", \"P2\": " + p2 + ", \"I1\": " + i1 + ", \"I2\": " + i2 + "}";
}
std::string poly(const std::string& v, const std::string& extra = "") { return "{\"vertices\": " + v + extra + "}"; }

void expect_error(const std::string& label, const std::string& args, const std::string& needle) {
    fs::path out = workdir() / "out.json";
    fs::remove(out);
    Run r = run(args + " --out " + out.string());
    BOOST_TEST_CONTEXT(label) {
        BOOST_TEST(r.status == 2);
        BOOST_TEST(r.out.empty());
        BOOST_TEST(r.err.rfind("scalecert: error: ", 0) == 0u);
        BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        BOOST_TEST(r.err.find(needle) != std::string::npos, "'" << needle << "' in: " << r.err);
        BOOST_TEST(!fs::exists(out));
        for (const auto& e : fs::directory_iterator(workdir()))
            BOOST_TEST(e.path().filename().string().find(".tmp.") == std::string::npos);
    }
}
}  // namespace

BOOST_AUTO_TEST_CASE(bad_inputs) {
    const std::string good = scene(poly(kCube1), poly(kCube2));
    auto S = [&](const std::string& name, const std::string& text) { return "curve " + write(name, text).string(); };
    expect_error("malformed JSON", S("a.json", "{\"P1\": "), "malformed JSON");
    expect_error("not an object", S("b.json", "[1,2]"), "JSON object");
    expect_error("missing I2", S("c.json", "{\"P1\": " + poly(kCube1) + ", \"P2\": " + poly(kCube2) + ", \"I1\": [1,2]}"), "\"I2\"");
    expect_error("missing vertices", S("d.json", scene("{}", poly(kCube2))), "P1");
    expect_error("NaN literal", S("e.json", scene(poly("[[NaN,0,0],[1,0,0],[0,1,0],[0,0,1]]"), poly(kCube2))), "malformed JSON");
    expect_error("NaN string", S("f.json", scene(poly("[[\"NaN\",0,0],[1,0,0],[0,1,0],[0,0,1]]"), poly(kCube2))), "P1.vertices[0][0]");
    expect_error("Inf string", S("g.json", scene(poly(kCube1), poly(kCube2), "[\"inf\", 2]")), "I1[0]");
    expect_error("inf as binary double", S("h.json", scene(poly(kCube1), poly(kCube2), "[1e999, 2]")) + " --binary-doubles", "not finite");
    expect_error("3 vertices", S("i.json", scene(poly("[[0,0,0],[1,0,0],[0,1,0]]"), poly(kCube2))), "fewer than 4 vertices");
    expect_error("flat", S("j.json", scene(poly("[[0,0,0],[1,0,0],[0,1,0],[1,1,0],[3,3,0]]"), poly(kCube2))), "affinely independent");
    expect_error("seed on boundary", S("k.json", scene(poly(kCube1, ", \"seed\": [1,1,2]"), poly(kCube2))), "P1.seed");
    expect_error("seed outside", S("l.json", scene(poly(kCube1), poly(kCube2, ", \"seed\": [9,9,9]"))), "P2.seed");
    expect_error("lo = 0", S("m.json", scene(poly(kCube1), poly(kCube2), "[0, 2]")), "I1");
    expect_error("lo < 0", S("n.json", scene(poly(kCube1), poly(kCube2), "[1, 2]", "[-1, 2]")), "I2");
    expect_error("lo > hi", S("o.json", scene(poly(kCube1), poly(kCube2), "[3, 2]")), "lo > hi");
    expect_error("bad number text", S("p.json", scene(poly(kCube1), poly(kCube2), "[\"1.2.3\", 2]")), "not an exact number");
    expect_error("huge exponent", S("q.json", scene(poly(kCube1), poly(kCube2), "[\"1e99999999\", 2]")), "exponent");
    expect_error("zero denominator", S("r.json", scene(poly(kCube1), poly(kCube2), "[\"1/0\", 2]")), "zero denominator");
    expect_error("point with 2 coordinates", S("s.json", scene(poly("[[0,0],[1,0,0],[0,1,0],[0,0,1]]"), poly(kCube2))), "3 coordinates");
    expect_error("missing OFF", S("t.json", scene("{\"off\": \"nowhere.off\"}", poly(kCube2))), "cannot open");
    write("bad1.off", "OFF\n8 6 0\n0 0 0\n1 0 0\n");
    expect_error("short OFF", S("u.json", scene("{\"off\": \"bad1.off\"}", poly(kCube2))), "malformed OFF");
    write("bad2.off", "PLY\n");
    expect_error("not OFF", S("v.json", scene("{\"off\": \"bad2.off\"}", poly(kCube2))), "malformed OFF");
    write("bad3.off", "OFF\n4 1 0\n0 0 0\n1 0 x\n0 1 0\n0 0 1\n");
    expect_error("OFF bad number", S("w.json", scene("{\"off\": \"bad3.off\"}", poly(kCube2))), "not an exact number");
    expect_error("no such scene", "curve " + (workdir() / "absent.json").string(), "cannot open");
    fs::path g = write("good.json", good);
    expect_error("rho1 = 0", "query " + g.string() + " 0 1", "RHO1");
    expect_error("rho2 text", "query " + g.string() + " 1 abc", "RHO2");
    expect_error("unknown option", "curve " + g.string() + " --frobnicate", "frobnicate");
    expect_error("no subcommand", "", "subcommand");
    // An unwritable output file: the error names it and nothing is left behind.
    Run r = run("curve " + g.string() + " --out " + (workdir() / "no-such-dir" / "x.json").string());
    BOOST_TEST(r.status == 2);
    BOOST_TEST(r.err.find("cannot open for writing") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(off_input_reads_exactly_like_json) {
    write("c1.off", "OFF\n# a cube, with a comment\n8 6 12\n0 0 0\n2 0 0\n0 2 0\n2 2 0\n0 0 2\n2 0 2\n0 2 2\n2 2 2\n");
    fs::path a = write("off.json", scene("{\"off\": \"c1.off\"}", poly(kCube2)));
    fs::path b = write("json.json", scene(poly(kCube1), poly(kCube2)));
    Run ra = run("curve " + a.string()), rb = run("curve " + b.string());
    BOOST_TEST(ra.status == 0);
    BOOST_TEST(ra.out == rb.out);
}

BOOST_AUTO_TEST_CASE(query_words_and_exact_numbers) {
    fs::path g = write("good2.json", scene(poly(kCube1), poly(kCube2)));
    // ρ1 + ρ2 = 3 is the touching line (test_hand_curves derives it).
    BOOST_TEST(run("query " + g.string() + " 1 2").out == "touching\n");
    BOOST_TEST(run("query " + g.string() + " 1 1.99").out == "separated\n");
    BOOST_TEST(run("query " + g.string() + " 3/2 1.5000001").out == "overlapping\n");
    // 0.1 + 2.9 = 3 exactly, but not in doubles: exact reading says touching...
    BOOST_TEST(run("query " + g.string() + " 0.1 2.9").out == "touching\n");
    // ...and --binary-doubles reads the doubles 0.1 and 2.9, whose exact sum is 3 − 2^-51·(...):
    // 0.1 = 3602879701896397/2^55 > 1/10 and 2.9 = 6530219459687219/2^51 < 29/10.
    // Exact: 3602879701896397/2^55 + 6530219459687219/2^51 − 3 = (3602879701896397 + 16·6530219459687219 − 3·2^55)/2^55
    //      = (3602879701896397 + 104483511354995504 − 108086391056891904)/2^55 = −3/2^55 < 0: separated.
    BOOST_TEST(run("query " + g.string() + " 0.1 2.9 --binary-doubles").out == "separated\n");
}

BOOST_AUTO_TEST_CASE(classify_many_pairs) {
    fs::path g = write("good4.json", scene(poly(kCube1), poly(kCube2)));
    // ρ1 + ρ2 = 3 touches (test_hand_curves); 0.5 + 2.5 is exact in doubles.
    fs::path p = write("pairs.txt", "1 2\n# comment\n\n0.5 2.5\n1 1.99\n2 2\n");
    Run r = run("classify " + g.string() + " " + p.string());
    BOOST_TEST(r.status == 0);
    BOOST_TEST(r.out == "touching\ntouching\nseparated\noverlapping\n");
    fs::path bad = write("bad-pairs.txt", "1 2\n1 x\n");
    Run e = run("classify " + g.string() + " " + bad.string());
    BOOST_TEST(e.status == 2);
    BOOST_TEST(e.err.find("line 2") != std::string::npos);
    BOOST_TEST(e.out.empty());
}

BOOST_AUTO_TEST_CASE(out_file_is_written_whole) {
    fs::path g = write("good3.json", scene(poly(kCube1), poly(kCube2)));
    fs::path out = workdir() / "p.json";
    Run r = run("partition " + g.string() + " --out " + out.string());
    BOOST_TEST(r.status == 0);
    BOOST_TEST(r.out.empty());
    BOOST_TEST(slurp(out) == run("partition " + g.string()).out);
}
