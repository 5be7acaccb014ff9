// The scalecert command: each subcommand is a handler in its own file (common.hpp lists them).
#include "common.hpp"

#include "io/files.hpp"

#include <cstdio>
#include <cstdlib>
#include <iostream>

using namespace scalecert;

namespace {

// An error message as one line: control characters (a newline in a file name or a number)
// escaped, and at most 1000 characters.
std::string one_line(const std::string& msg) {
    std::string out;
    for (unsigned char c : msg) {
        if (out.size() >= 1000) return out + "... (cut)";
        if (c < 0x20 || c == 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", c);
            out += buf;
        } else {
            out += static_cast<char>(c);
        }
    }
    return out;
}

// GMP aborts the process when an allocation fails; this program (not the library, which must not
// replace its host's allocator) turns that into std::bad_alloc, reported below with exit 2.
void* gmp_alloc(size_t n) {
    if (void* p = std::malloc(n)) return p;
    throw std::bad_alloc();
}
void* gmp_realloc(void* p, size_t, size_t n) {
    if (void* q = std::realloc(p, n)) return q;
    throw std::bad_alloc();
}
void gmp_free(void* p, size_t) { std::free(p); }

}  // namespace

int main(int argc, char** argv) {
    mp_set_memory_functions(gmp_alloc, gmp_realloc, gmp_free);
    if (argc > 0 && std::string(argv[0]).find('/') != std::string::npos) cli::program_path() = argv[0];
    CLI::App app{"scalecert: exact, certified collision of uniformly scaled convex polyhedra"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("scalecert ") + scalecert::version());
    app.add_flag_callback(
        "--quiet,-q", [] { internal::set_quiet(true); },
        "no notes on stderr (how numbers were read, MuJoCo's warnings, a step that did not run) and no "
        "progress lines; errors are still said. Before or after the command's own options");
    app.fallthrough();
    app.footer(
        "\n--out FILE, wherever it appears, writes the command's output to FILE atomically instead of\n"
        "standard output. Exit status: 0 done, 1 certify-fp found a wrong claim, 2 bad input,\n"
        "3 internal error (a bug: please report it).\n"
        "scalecert COMMAND --help shows an example.");
    std::vector<cli::Command> commands = {cli::add_curve(app),    cli::add_query(app),      cli::add_partition(app),
                                          cli::add_classify(app), cli::add_certify_fp(app), cli::add_golden(app),
                                          cli::add_region(app),   cli::add_report(app),     cli::add_mujoco(app)};
#ifdef SCALECERT_WITH_BASELINES  // the floating-point baselines' commands
    commands.push_back(cli::add_audit(app));
    commands.push_back(cli::add_grid(app));
#endif
    std::string names;
    bool known = false;
    for (const cli::Command& c : commands) {
        names += (names.empty() ? "" : ", ") + c.app->get_name();
        known = known || (argc > 1 && c.app->get_name() == argv[1]);
    }
    if (argc > 1 && argv[1][0] != '-' && !known) {
        std::cerr << "scalecert: error: unknown command '" << one_line(argv[1]) << "' (" << names
                  << "; see scalecert --help)\n";
        return 2;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "scalecert: error: " << one_line(e.what()) << " (see scalecert --help)\n";
        return 2;
    }
    // Exit 2 (or 3) leaves no output file: what the command wrote before it failed is removed, and
    // what it replaced put back (files.hpp, the output journal).
    internal::begin_output_journal();
    try {
        for (const cli::Command& c : commands)
            if (*c.app) {
                const int status = c.run();
                internal::commit_outputs();
                return status;
            }
        return 2;  // unreachable: CLI11 requires one subcommand
    } catch (const InputError& e) {
        internal::undo_outputs();
        std::cerr << "scalecert: error: " << one_line(e.what()) << "\n";
        return 2;
    } catch (const std::bad_alloc&) {
        internal::undo_outputs();
        std::cerr << "scalecert: error: out of memory\n";
        return 2;
    } catch (const std::exception& e) {
        internal::undo_outputs();
        std::cerr << "scalecert: internal error: " << one_line(e.what()) << "\n";
        return 3;
    }
}
