// scalecert-mpi: golden data and audits over MPI. Every rank reads the same arguments and plans
// the same shards; rank 0 hands shards out on request (dynamic: a slow rank holds no one back),
// records each finished shard in the run folder's manifest, and merges at the end, so the output
// is byte-identical to scalecert golden / audit with the same arguments, whatever the number of
// ranks. With one rank, rank 0 runs every shard itself.
//
// Run folder: manifest.jsonl (line 1: the command's identity, with the SHA-256 of every scene file
// and mesh file the audit reads; then one line per finished shard, {"shard": i, "sha256": h},
// appended and synced) and shards/NNNNNNNN.json (each written atomically; an audit shard of a
// scene file records the SHA-256 of the files it read). --resume redoes only shards that are
// missing, whose file's hash differs from the manifest's, or (golden) whose output files no longer
// match their hashes; it refuses (exit 2) when an input's contents changed since the run began,
// so no shard computed from old contents is merged. Nothing in the run folder may be a symbolic
// link: every file there is opened with O_NOFOLLOW (the manifest created with O_EXCL).
#include "../cli/campaign_options.hpp"
#include "io/files.hpp"

#include <scalecert/scalecert.hpp>

#include <mpi.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

using namespace scalecert::internal;
namespace fs = std::filesystem;

namespace {

constexpr int kTagRequest = 1, kTagWork = 2;

std::string shard_path(const std::string& run, int i) {
    char b[32];
    std::snprintf(b, sizeof b, "%08d.json", i);
    return run + "/shards/" + b;
}

// Every file in the run folder is opened with O_NOFOLLOW and must be a regular file: a symbolic
// link (even a dangling one) planted there cannot make the run read or write outside the folder.
bool run_file_exists(const std::string& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) return false;
    if (!S_ISREG(st.st_mode))
        throw InputError(path + ": " + (S_ISLNK(st.st_mode) ? "is a symbolic link" : "is not a regular file") +
                         " (refused in a run folder)");
    return true;
}

// A shard file's bytes; "" when it is missing (the shard is then redone).
std::string slurp(const std::string& path) {
    if (!run_file_exists(path)) return "";
    return read_regular_file(path, "shard file", kMaxRunFileBytes, true);
}

// Appends one line to the manifest and syncs it: a crash leaves at most a torn last line, which
// the reader ignores. `create`: the manifest is new (O_EXCL: nothing may be there, not even a
// dangling symbolic link); else it must be the regular file already there (O_NOFOLLOW).
void append_line(const std::string& path, const std::string& line, bool create = false) {
    const int fd =
        ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC | O_NOFOLLOW | (create ? O_CREAT | O_EXCL : 0), 0644);
    if (fd < 0 && (errno == ELOOP || errno == EEXIST)) run_file_exists(path);  // words a symbolic link
    if (fd < 0) throw InputError(path + ": cannot write the manifest (" + std::strerror(errno) + ")");
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        throw InputError(path + ": is not a regular file (refused in a run folder)");
    }
    const std::string l = line + "\n";
    const bool ok = ::write(fd, l.data(), l.size()) == static_cast<ssize_t>(l.size()) && ::fsync(fd) == 0;
    ::close(fd);
    if (!ok) throw InputError(path + ": cannot write the manifest");
}

// The run folder's shards/ must be a directory of its own, not a symbolic link to one elsewhere.
void check_shards_dir(const std::string& run) {
    const std::string d = run + "/shards";
    struct stat st {};
    if (::lstat(d.c_str(), &st) != 0) {
        std::error_code ec;
        fs::create_directories(d, ec);
        if (ec) throw InputError(run + ": cannot create the run folder (" + ec.message() + ")");
        if (::lstat(d.c_str(), &st) != 0) throw InputError(d + ": cannot create the shards folder");
    }
    if (!S_ISDIR(st.st_mode))
        throw InputError(d + ": " + (S_ISLNK(st.st_mode) ? "is a symbolic link" : "is not a directory") +
                         " (refused in a run folder)");
}

// Why the manifest's first line differs from this command's identity: another command, or the
// same command on files whose contents changed since the run began.
std::string identity_mismatch(const std::string& run, const std::string& recorded, const std::string& identity) {
    const std::string other = run + ": the run folder holds another command's run (its manifest's first line differs)";
    Json was, now;
    try {
        was = Json::parse(recorded);
        now = Json::parse(identity);
    } catch (const std::exception&) {
        return other;
    }
    if (!was.is_object() || !was.contains("inputs")) return other;
    const Json old_inputs = was["inputs"], new_inputs = now["inputs"];
    was.erase("inputs");
    now.erase("inputs");
    if (was != now) return other;
    for (const Json& f : new_inputs) {
        const std::string path = f.at(0).get<std::string>();
        bool same = false;
        for (const Json& g : old_inputs)
            if (g.is_array() && g.size() == 2 && g.at(0) == f.at(0) && g.at(1) == f.at(1)) same = true;
        if (!same)
            return path + ": changed since the run in " + run +
                   " began (its SHA-256 differs); refused: no shard computed from the old contents is merged (start a "
                   "new --run folder)";
    }
    if (old_inputs == new_inputs)  // the same identity, written otherwise: an edited line
        return run +
               ": the manifest's first line holds this command's identity written otherwise (edited by hand?); "
               "refused: start a new --run folder";
    return run +
           ": the files the run read changed since it began (their SHA-256 differ); refused: no shard computed from "
           "the old contents is merged (start a new --run folder)";
}

// The shards the manifest records as finished, with their hashes; checks the identity line.
std::map<int, std::string> read_manifest(const std::string& run, const std::string& identity) {
    std::map<int, std::string> done;
    const std::string path = run + "/manifest.jsonl";
    if (!run_file_exists(path)) throw InputError(run + ": no manifest to resume from");
    std::istringstream in(read_regular_file(path, "manifest", kMaxRunFileBytes, true));
    std::string line;
    if (!std::getline(in, line)) throw InputError(run + ": no manifest to resume from");
    if (line != identity) throw InputError(identity_mismatch(run, line, identity));
    while (std::getline(in, line)) {
        try {
            const Json j = Json::parse(line);
            done[j.at("shard").get<int>()] = j.at("sha256").get<std::string>();
        } catch (const std::exception&) {
            // a torn last line: that shard is redone
        }
    }
    return done;
}

struct Progress {
    bool tty = ::isatty(2);
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now(), last{};
    long scenes = 0;
    void show(size_t done, size_t total, size_t todo_done, size_t todo, bool final) {
        const auto now = std::chrono::steady_clock::now();
        if (!final && now - last < std::chrono::seconds(1)) return;
        last = now;
        const double t = std::chrono::duration<double>(now - start).count();
        const double rate = t > 0 ? scenes / t : 0;
        const double left = todo_done ? t * static_cast<double>(todo - todo_done) / static_cast<double>(todo_done) : 0;
        std::fprintf(stderr, "%sscalecert-mpi: %zu/%zu shards, %.1f scenes/s, about %.0f s left%s", tty ? "\r" : "",
                     done, total, rate, left, tty && !final ? "" : "\n");
        std::fflush(stderr);
    }
};

// Runs a shard, writes its file atomically into the run folder, and returns the file's hash.
std::string run_and_store(const CampaignArgs& a, const Shard& s, const std::string& run) {
    const std::string text = run_shard(a, s);
    scalecert::internal::write_file_atomically(shard_path(run, s.index), text);
    return sha256_hex(text);
}

int fail(int rank, const std::string& msg, int status) {
    if (rank == 0) std::fprintf(stderr, "scalecert-mpi: error: %s\n", msg.c_str());
    MPI_Finalize();
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);

    CLI::App app{
        "scalecert-mpi: golden data and audits sharded over MPI ranks, resumable; output identical to scalecert's"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("scalecert-mpi ") + scalecert::version());
    CampaignArgs golden_args, audit_args;
    std::string run;
    bool resume = false;
    int shard_size = 0;
    long stop_after = -1;
    CLI::App* golden = app.add_subcommand("golden", "scalecert golden, sharded");
    CLI::App* audit = app.add_subcommand("audit", "scalecert audit, sharded");
    scalecert::cli::add_golden_options(golden, golden_args);
    scalecert::cli::add_audit_options(audit, audit_args);
    for (CLI::App* sub : {golden, audit}) {
        sub->add_option("--run", run, "run folder: the manifest and one file per finished shard")->required();
        sub->add_flag("--resume", resume, "go on with the run in --run: redo only missing or damaged shards");
        sub->add_option("--shard-size", shard_size, "family scenes per shard (default 16 golden, 4 audit)")
            ->check(scalecert::cli::whole_number(1, 1000000));
        sub->add_option("--stop-after", stop_after, "(for tests) stop, as if killed, after this many shards")
            ->check(scalecert::cli::whole_number(0, 1LL << 40));
        sub->footer("\nExample:\n  mpirun -np 64 scalecert-mpi " +
                    std::string(sub == golden ? "golden --family random --count 100000 --dir golden/"
                                              : "audit --family sliver --sweep 2 --sweep-to 40 --count 1000 --out "
                                                "a.json --csv a.csv --no-timing") +
                    " --run run/\n  (rerun with --resume after a crash)");
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {  // --help, --version
        const int st = rank == 0 ? app.exit(e) : 0;
        MPI_Finalize();
        return st;
    } catch (const CLI::ParseError& e) {
        return fail(rank, std::string(e.what()) + " (see scalecert-mpi --help)", 2);
    }
    CampaignArgs& a = *golden ? golden_args : audit_args;
    a.shard_size = shard_size;
    // The replay commands name the scalecert beside this program, when it was run by a path.
    if (const std::string self = argv[0]; self.find('/') != std::string::npos)
        a.program = self.substr(0, self.rfind('/') + 1) + "scalecert";
    std::vector<Shard> shards;
    // Every rank checks the arguments the same way; rank 0 alone speaks, and every rank exits.
    try {
        validate(a);
        shards = plan(a);
    } catch (const InputError& e) {
        return fail(rank, e.what(), 2);
    }
    Json inputs = Json::array();
    int setup_ok = 1;
    std::string setup_error;
    std::vector<int> todo;
    std::vector<std::string> hashes(shards.size());
    size_t done_before = 0, redone = 0;
    if (rank == 0) {
        try {
            // The inputs' contents (scene files and the meshes they name) are part of the identity.
            inputs = campaign_inputs(a);
            const std::string identity = campaign_identity(a, inputs);
            if (a.golden) make_output_dir(a.dir);
            if (!a.golden && !a.failures.empty()) make_output_dir(a.failures);
            std::map<int, std::string> done;
            if (resume) {
                done = read_manifest(run, identity);
                check_shards_dir(run);
            } else {
                if (run_file_exists(run + "/manifest.jsonl"))
                    throw InputError(run + ": a run is already there (add --resume to go on with it)");
                check_shards_dir(run);
                append_line(run + "/manifest.jsonl", identity, true);
            }
            for (const Shard& s : shards) {
                auto it = done.find(s.index);
                if (it != done.end()) {
                    const std::string text = slurp(shard_path(run, s.index));
                    // (A shard that read other contents than the run's inputs, changed and changed
                    // back while the run was stopped, is redone like a damaged one.)
                    if (sha256_hex(text) == it->second && shard_well_formed(a, s, text) &&
                        shard_outputs_intact(a, text) && stale_input(inputs, text).empty()) {
                        hashes[static_cast<size_t>(s.index)] = it->second;
                        ++done_before;
                        continue;
                    }
                    ++redone;
                }
                todo.push_back(s.index);
            }
        } catch (const InputError& e) {
            setup_ok = 0;
            setup_error = e.what();
        }
    }
    MPI_Bcast(&setup_ok, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (!setup_ok) return fail(rank, setup_error, 2);

    int status = 0;
    std::string error;
    if (rank == 0) {
        Progress progress;
        size_t finished = done_before, next = 0, ran = 0;
        long started = 0;
        auto record = [&](int idx, const std::string& h) {
            hashes[static_cast<size_t>(idx)] = h;
            append_line(run + "/manifest.jsonl", Json{{"shard", idx}, {"sha256", h}}.dump());
            progress.scenes += shards[static_cast<size_t>(idx)].scenes();
            ++finished;
            ++ran;
            progress.show(finished, shards.size(), ran, todo.size(), false);
        };
        auto may_start = [&] {
            return next < todo.size() && (stop_after < 0 || started < stop_after) && error.empty();
        };
        try {
            if (size == 1) {
                while (may_start()) {
                    const int idx = todo[next++];
                    ++started;
                    record(idx, run_and_store(a, shards[static_cast<size_t>(idx)], run));
                }
            } else {
                int active = size - 1;
                while (active > 0) {
                    // A request carries the previous shard's result: index (or -1) and hash (or an error).
                    // Polled with a 1 ms sleep: a blocking probe spins, taking a core from the workers.
                    MPI_Status st;
                    for (int flag = 0;;) {
                        MPI_Iprobe(MPI_ANY_SOURCE, kTagRequest, MPI_COMM_WORLD, &flag, &st);
                        if (flag) break;
                        ::usleep(1000);
                    }
                    int len = 0;
                    MPI_Get_count(&st, MPI_CHAR, &len);
                    std::string msg(static_cast<size_t>(len), '\0');
                    MPI_Recv(msg.data(), len, MPI_CHAR, st.MPI_SOURCE, kTagRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                    const Json r = Json::parse(msg);
                    if (r.at("shard").get<int>() >= 0) {
                        if (r.contains("error")) {
                            if (error.empty()) error = r.at("error").get<std::string>();
                        } else {
                            record(r.at("shard").get<int>(), r.at("sha256").get<std::string>());
                        }
                    }
                    int work = -1;
                    if (may_start()) {
                        work = todo[next++];
                        ++started;
                    } else {
                        --active;
                    }
                    MPI_Send(&work, 1, MPI_INT, st.MPI_SOURCE, kTagWork, MPI_COMM_WORLD);
                }
            }
            progress.show(finished, shards.size(), ran, todo.size(), true);
            if (!error.empty()) throw InputError(error);
            if (finished < shards.size()) {
                std::fprintf(stderr, "scalecert-mpi: stopped after %zu shards as asked; %zu of %zu to go (--resume)\n",
                             ran, shards.size() - finished, shards.size());
                status = 3;
            } else {
                // Merge: every shard read back and checked against the manifest's hash.
                const auto merge_start = std::chrono::steady_clock::now();
                std::vector<std::string> texts;
                for (const Shard& s : shards) {
                    texts.push_back(slurp(shard_path(run, s.index)));
                    if (sha256_hex(texts.back()) != hashes[static_cast<size_t>(s.index)])
                        throw InputError(shard_path(run, s.index) + ": changed during the run (hash mismatch)");
                    if (!shard_well_formed(a, s, texts.back()))
                        throw InputError(shard_path(run, s.index) + ": not shard " + std::to_string(s.index) +
                                         " of this run (malformed, or another shard's); refused: not merged");
                    // A scene file (or a mesh it names) changed after the run hashed it: refused, not merged.
                    const std::string stale = stale_input(inputs, texts.back());
                    if (!stale.empty())
                        throw InputError(stale +
                                         ": changed during the run (its SHA-256 differs from the run's); refused: not "
                                         "merged (start a new --run folder)");
                }
                const long n = finish_campaign(a, texts);
                const double merge =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - merge_start).count();
                std::fprintf(stderr,
                             "scalecert-mpi: %zu shards (%zu done before, %zu redone as damaged, %zu run now) on %d "
                             "ranks: %ld %s; merge %.3f s\n",
                             shards.size(), done_before, redone, ran, size, n, a.golden ? "scenes" : "rows", merge);
            }
        } catch (const InputError& e) {
            std::fprintf(stderr, "scalecert-mpi: error: %s\n", e.what());
            status = 2;
        }
        if (status == 2 && size > 1) MPI_Abort(MPI_COMM_WORLD, 2);  // workers may be mid-shard
    } else {
        Json result{{"shard", -1}};
        for (;;) {
            const std::string msg = result.dump();
            MPI_Send(msg.data(), static_cast<int>(msg.size()), MPI_CHAR, 0, kTagRequest, MPI_COMM_WORLD);
            int work = -1;
            MPI_Recv(&work, 1, MPI_INT, 0, kTagWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            if (work < 0) break;
            try {
                result = Json{{"shard", work}, {"sha256", run_and_store(a, shards[static_cast<size_t>(work)], run)}};
            } catch (const std::exception& e) {
                result = Json{{"shard", work}, {"error", e.what()}};
            }
        }
    }
    MPI_Finalize();
    return status;
}
