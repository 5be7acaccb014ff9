// The command line: every bad input gets one line "scalecert: error: ...", exit status 2, nothing
// on standard output and no output file.
#define BOOST_TEST_MODULE cli
#include <boost/test/unit_test.hpp>

#include "files.hpp"

#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <random>
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
    BOOST_TEST(r.err.find("cannot create a file in") != std::string::npos);
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

// ---- hostile input (issue 14): each class the adversarial review reproduced ------------------

BOOST_AUTO_TEST_CASE(json_is_read_as_rfc_8259_says) {
    const std::string P1 = poly(kCube1), P2 = poly(kCube2);
    auto S = [&](const std::string& name, const std::string& text) { return "curve " + write(name, text).string(); };
    // 10^6 levels of nesting overflowed the stack in the tree's recursive destructor.
    expect_error("nested 10^6 deep", S("deep.json", std::string(1000000, '[') + std::string(1000000, ']')), "nested deeper than 64");
    expect_error("leading zero", S("lz.json", scene(poly("[[0,0,0],[2,0,0],[0,2,0],[0,0,02]]"), P2)), "leading zero");
    expect_error("line comment", S("cm.json", "{\"P1\": " + P1 + ", // P2 next\n\"P2\": " + P2 + ", \"I1\": [1,2], \"I2\": [1,2]}"), "comments are not JSON");
    expect_error("numeric key", S("nk.json", "{\"P1\": " + P1 + ", 5: 1, \"P2\": " + P2 + ", \"I1\": [1,2], \"I2\": [1,2]}"), "expected a string key");
    expect_error("trailing comma", S("tc.json", scene(P1, P2, "[1, 2,]")), "malformed JSON");
    // The first value used to win here, the last in the checker: one file, two meanings.
    expect_error("duplicate key", S("dk.json", scene(P1, P2) .substr(0, scene(P1, P2).size() - 1) + ", \"I1\": [1, 3]}"), "duplicate key 'I1'");
    expect_error("duplicate key in P1", S("dk2.json", scene("{\"vertices\": " + kCube1 + ", \"vertices\": " + kCube2 + "}", P2)), "duplicate key 'vertices'");
    expect_error("unknown field", S("uf.json", scene(poly(kCube1, ", \"sead\": [1,1,1]"), P2)), "unknown field 'sead'");
    expect_error("invalid UTF-8", S("u8.json", scene(P1, P2, "[\"1\xff\", 2]")), "invalid UTF-8");
}

BOOST_AUTO_TEST_CASE(error_messages_are_one_line_with_the_file_and_cut) {
    const std::string P2 = poly(kCube2);
    auto S = [&](const std::string& name, const std::string& text) { return "curve " + write(name, text).string(); };
    // '1/2/3' was reported as '2/3'.
    expect_error("1/2/3", S("s3.json", scene(poly(kCube1), P2, "[\"1/2/3\", 2]")), "I1[0]: '1/2/3' is not an exact number");
    // A newline inside a number string (a JSON escape) stays inside the one line.
    expect_error("newline in a number", S("nl.json", scene(poly(kCube1), P2, "[\"1\\n2\", 2]")), "'1\\x0a2' is not an exact number");
    // A 1 MB number is cut, not echoed.
    const std::string huge(1000000, '7');
    fs::path hp = write("huge.json", scene(poly(kCube1), P2, "[\"" + huge + "x\", 2]"));
    expect_error("1 MB number", "curve " + hp.string(), "1000001 characters, cut");
    Run r = run("curve " + hp.string());
    BOOST_TEST(r.err.size() < 400u);
    // A newline in a file name.
    fs::path odd = write("bad\nname.json", scene(poly(kCube1), P2));
    fs::remove(odd);
    expect_error("newline in a file name", "curve '" + odd.string() + "'", "bad\\x0aname.json: cannot open");
    // Geometric errors found after reading name the file too.
    fs::path flat = write("flat.json", scene(poly("[[0,0,0],[1,0,0],[0,1,0],[1,1,0]]"), P2));
    expect_error("flat names its file", "curve " + flat.string(), flat.string() + ": P1: fewer than 4 affinely independent");
}

BOOST_AUTO_TEST_CASE(audit_arguments_that_crashed_or_never_ended_are_refused) {
    fs::path g = write("audit-scene.json", scene(poly(kCube1), poly(kCube2)));
    // --grid 1 dereferenced an empty junction list; a negative --sweep overflowed GMP; --grid
    // 100000 ran without end.
    expect_error("grid 1", "audit " + g.string() + " --methods grid --grid 1", "--grid");
    expect_error("grid 0", "audit " + g.string() + " --methods grid --grid 0", "--grid");
    expect_error("grid -3", "audit " + g.string() + " --methods grid --grid -3", "--grid");
    expect_error("grid 100000", "audit " + g.string() + " --methods grid --grid 100000", "--grid");
    expect_error("negative sweep", "audit --family random --sweep -2 --sweep-to 1", "--sweep");
    expect_error("sweep-to too far", "audit --family random --sweep 1 --sweep-to 5000", "--sweep-to");
    expect_error("unknown family", "audit --family bogus --sweep 1 --sweep-to 2", "unknown family 'bogus'");
    // The CSV was written before the JSON failed: now both or neither.
    fs::path prefix = workdir() / "both";
    fs::create_directories(workdir() / "both.json");  // the JSON target cannot be replaced
    Run a = run("audit " + g.string() + " --methods libccd-gjk --out " + prefix.string());
    BOOST_TEST(a.status == 2);
    BOOST_TEST(!fs::exists(workdir() / "both.csv"));
    fs::remove_all(workdir() / "both.json");
    Run b = run("audit " + g.string() + " --methods libccd-gjk --out " + prefix.string());
    BOOST_TEST(b.status == 0);
    BOOST_TEST(fs::exists(workdir() / "both.csv"));
    BOOST_TEST(fs::exists(workdir() / "both.json"));
}

BOOST_AUTO_TEST_CASE(outputs_go_only_to_regular_files_and_directories_we_can_make) {
    fs::path g = write("out-scene.json", scene(poly(kCube1), poly(kCube2)));
    // A device node or a symbolic link at the target is refused, and is left as it was.
    Run d = run("curve " + g.string() + " --out /dev/null");
    BOOST_TEST(d.status == 2);
    BOOST_TEST(d.err.find("not a regular file") != std::string::npos);
    fs::path victim = write("victim.txt", "untouched");
    fs::path link = workdir() / "link.json";
    fs::remove(link);
    fs::create_symlink(victim, link);
    Run l = run("curve " + g.string() + " --out " + link.string());
    BOOST_TEST(l.status == 2);
    BOOST_TEST(fs::is_symlink(link));
    BOOST_TEST(slurp(victim) == "untouched");
    // The temporary name is not predictable: a planted OUT.tmp.PID symlink is never followed
    // (the engine creates its temporary file exclusively, under a random name).
    fs::path out = workdir() / "fresh.json";
    for (int pid = 1; pid < 64; ++pid) {
        fs::path planted = workdir() / ("fresh.json.tmp." + std::to_string(pid));
        fs::remove(planted);
    }
    Run ok = run("curve " + g.string() + " --out " + out.string());
    BOOST_TEST(ok.status == 0);
    BOOST_TEST(slurp(out) == run("curve " + g.string()).out);
    BOOST_TEST(((fs::status(out).permissions() & fs::perms::others_read) != fs::perms::none));  // not mkstemp's 0600
    // golden: under a file (was exit 3), and an unknown family (left its directory behind).
    write("plain-file", "x");
    Run gf = run("golden --family random --count 1 --out " + (workdir() / "plain-file" / "g").string());
    BOOST_TEST(gf.status == 2);
    BOOST_TEST(gf.err.find("cannot create the output directory") != std::string::npos, gf.err);
    Run gu = run("golden --family bogus --out " + (workdir() / "never-made").string());
    BOOST_TEST(gu.status == 2);
    BOOST_TEST(!fs::exists(workdir() / "never-made"));
}

BOOST_AUTO_TEST_CASE(claims_and_pairs_must_be_files_with_content) {
    fs::path g = write("claims-scene.json", scene(poly(kCube1), poly(kCube2)));
    // certify-fp SCENE DIR exited 0 with "claims: 0".
    expect_error("claims directory", "certify-fp " + g.string() + " " + workdir().string(), "is a directory");
    fs::path empty = write("empty-claims.txt", "# nothing\n\n");
    expect_error("no claims", "certify-fp " + g.string() + " " + empty.string(), "no claims");
    expect_error("pairs directory", "classify " + g.string() + " " + workdir().string(), "is a directory");
    expect_error("scene directory", "curve " + workdir().string(), "is a directory");
    fs::path bad = write("bad-verdict.txt", "1 2 touch\n");
    expect_error("bad verdict", "certify-fp " + g.string() + " " + bad.string(), "unknown verdict 'touch'");
}

BOOST_AUTO_TEST_CASE(inputs_beyond_the_limits_are_refused_with_exit_2) {
    // README "Limits": each refused before the work that would exhaust memory or time.
    fs::path sparse = workdir() / "sparse.json";
    { std::ofstream(sparse) << "{"; }
    fs::resize_file(sparse, (std::uintmax_t(256) << 20) + 1);  // a sparse file one byte over 256 MiB
    expect_error("scene over 256 MiB", "curve " + sparse.string(), "larger than 256 MiB");
    fs::remove(sparse);
    write("many.off", "OFF\n1000001 0 0\n0 0 0\n");
    expect_error("OFF over 10^6 vertices", "curve " + write("many.json", scene("{\"off\": \"many.off\"}", poly(kCube2))).string(), "more than 1000000");
    std::string pts = "[";
    for (int i = 0; i < 1000001; ++i) pts += i ? ",[0,0,0]" : "[0,0,0]";
    pts += "]";
    expect_error("JSON over 10^6 points", "curve " + write("many2.json", scene(poly(pts), poly(kCube2))).string(), "more than 1000000 points");
    // The common denominator of a polyhedron's coordinates: 2,000 distinct primes above 2^15
    // give far more than 16,384 bits (each adds about 15).
    std::string v = "[[0,0,0],[1,0,0],[0,1,0],[0,0,1]";
    int found = 0;
    for (int p = 32771; found < 2000; p += 2) {
        bool prime = true;
        for (int d = 3; d * d <= p && prime; d += 2) prime = p % d != 0;
        if (!prime) continue;
        ++found;
        v += ",[\"1/" + std::to_string(p) + "\",\"1/" + std::to_string(p) + "\",\"1/" + std::to_string(p) + "\"]";
    }
    v += "]";
    expect_error("common denominator over 16384 bits", "curve " + write("dens.json", scene(poly(v), poly(kCube2))).string(),
                 "common denominator of the coordinates has more than 16384 bits");
}

BOOST_AUTO_TEST_CASE(out_of_memory_exits_2_with_one_line) {
    // 2,000 points with 100,000-digit coordinates need far more than 120 MB of GMP integers. GMP
    // aborts on a failed allocation; the command turns it into "out of memory" and exit 2.
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
    BOOST_TEST_MESSAGE("skipped under AddressSanitizer, which reserves more address space than the limit");
    return;
#endif
#endif
    std::mt19937 g(5);
    std::uniform_int_distribution<int> u(1, 999999);
    std::string v = "[";
    for (int i = 0; i < 2000; ++i)
        v += std::string(i ? "," : "") + "[\"" + std::to_string(u(g)) + "e99990\",\"" + std::to_string(u(g)) + "e99990\",\"" + std::to_string(u(g)) + "e99990\"]";
    v += "]";
    fs::path p = write("gmp-big.json", scene(poly(v), poly(kCube2)));
    fs::path err = workdir() / "oom-err.txt";
    int raw = std::system(("ulimit -v 120000; " + std::string(SCALECERT_BIN) + " curve " + p.string() + " >/dev/null 2>" + err.string()).c_str());
    BOOST_TEST((WIFEXITED(raw) && WEXITSTATUS(raw) == 2));
    const std::string e = slurp(err);
    BOOST_TEST(e == "scalecert: error: out of memory\n", e);
}
