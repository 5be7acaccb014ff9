// scalecert report: an audit's JSON as one HTML page. The page is drawn by tools/report.py (with
// Debian's python3 and libjs-three); this subcommand runs it with this program as the reader of
// the scenes, so that the bodies drawn are those this scalecert reads.
#include "common.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>

namespace scalecert::cli {

namespace {
// This program's own path (the page's 3-D views read the scenes with it).
std::string self() {
    char buf[PATH_MAX];
    const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
    return n > 0 ? std::string(buf, static_cast<size_t>(n)) : std::string("scalecert");
}
// report.py: installed beside this program (PREFIX/bin -> PREFIX/share/scalecert/tools), else in
// the source tree this program was built from.
std::string report_script() {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path installed = fs::path(self()).parent_path() / ".." / "share" / "scalecert" / "tools" / "report.py";
    if (fs::is_regular_file(installed, ec)) return installed.string();
#ifdef SCALECERT_SOURCE_DIR
    const fs::path source = fs::path(SCALECERT_SOURCE_DIR) / "tools" / "report.py";
    if (fs::is_regular_file(source, ec)) return source.string();
#endif
    return {};
}
}  // namespace

Command add_report(CLI::App& app) {
    struct Args {
        std::string audit, out, failures;
    };
    auto a = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand(
        "report", "an audit's JSON as one self-contained HTML page: tables, charts, failures and 3-D views");
    sub->add_option("AUDIT", a->audit, "scalecert audit's JSON (its --out)")->required();
    sub->add_option("--out", a->out, "the HTML page (one file, its scripts inlined; written atomically)")
        ->required()
        ->type_name("FILE");
    sub->add_option("--failures", a->failures,
                    "the audit's --failures directory (family scenes' and mesh pairs' scene files)")
        ->type_name("DIR");
    example(sub,
            "Example:\n  scalecert audit certificates/scenes/stacked_cubes.json --out a.json\n"
            "  scalecert report a.json --out report.html");
    return {sub, [a] {
                const std::string script = report_script();
                if (script.empty()) throw InputError("report: tools/report.py is not installed beside this scalecert");
                std::vector<std::string> args = {"/usr/bin/python3", script, a->audit, "--out", a->out,
                                                 "--scalecert",      self()};
                if (!a->failures.empty()) args.insert(args.end(), {"--failures", a->failures});
                std::vector<char*> argv;
                for (std::string& s : args) argv.push_back(s.data());
                argv.push_back(nullptr);
                std::fflush(nullptr);
                const pid_t pid = fork();
                if (pid < 0)
                    throw InputError(std::string("report: cannot start python3 (") + std::strerror(errno) + ")");
                if (pid == 0) {
                    execv(argv[0], argv.data());
                    std::fprintf(stderr, "scalecert: error: report: cannot run /usr/bin/python3 (%s)\n",
                                 std::strerror(errno));
                    _exit(2);
                }
                int status = 0;
                while (waitpid(pid, &status, 0) < 0)
                    if (errno != EINTR) throw InputError("report: lost python3");
                if (WIFEXITED(status)) return WEXITSTATUS(status);
                throw InputError("report: python3 was killed by signal " + std::to_string(WTERMSIG(status)));
            }};
}

}  // namespace scalecert::cli
