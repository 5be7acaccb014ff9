// scalecert-mpi: golden data and audits over MPI. Every rank reads the same arguments and plans
// the same shards; rank 0 hands shards out on request (dynamic: a slow rank holds no one back),
// records each finished shard in the run folder's manifest, and merges at the end, so the output
// is byte-identical to scalecert golden / audit with the same arguments, whatever the number of
// ranks. With one rank, rank 0 runs every shard itself.
//
// Run folder: manifest.jsonl (line 1: the command's identity; then one line per finished shard,
// {"shard": i, "sha256": h}, appended and synced) and shards/NNNNNNNN.json (each written
// atomically). --resume redoes only shards that are missing, whose file's hash differs from the
// manifest's, or (golden) whose output files no longer match their hashes.
#include "../cli/campaign_options.hpp"

#include <mpi.h>
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
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

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Appends one line to the manifest and syncs it: a crash leaves at most a torn last line, which
// the reader ignores.
void append_line(const std::string& path, const std::string& line) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT, 0644);
    if (fd < 0) throw InputError(path + ": cannot write the manifest");
    const std::string l = line + "\n";
    const bool ok = ::write(fd, l.data(), l.size()) == static_cast<ssize_t>(l.size()) && ::fsync(fd) == 0;
    ::close(fd);
    if (!ok) throw InputError(path + ": cannot write the manifest");
}

// The shards the manifest records as finished, with their hashes; checks the identity line.
std::map<int, std::string> read_manifest(const std::string& run, const std::string& identity) {
    std::map<int, std::string> done;
    std::ifstream in(run + "/manifest.jsonl");
    std::string line;
    if (!std::getline(in, line)) throw InputError(run + ": no manifest to resume from");
    if (line != identity) throw InputError(run + ": the run folder holds another command's run (its manifest's first line differs)");
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
        std::fprintf(stderr, "%sscalecert-mpi: %zu/%zu shards, %.1f scenes/s, about %.0f s left%s", tty ? "\r" : "", done, total, rate,
                     left, tty && !final ? "" : "\n");
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

    CLI::App app{"scalecert-mpi: golden data and audits sharded over MPI ranks, resumable; output identical to scalecert's"};
    app.require_subcommand(1);
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
        sub->add_option("--shard-size", shard_size, "family scenes per shard (default 16 golden, 4 audit)")->check(CLI::Range(1, 1000000));
        sub->add_option("--stop-after", stop_after, "(for tests) stop, as if killed, after this many shards")->check(CLI::Range(0L, 1L << 40));
        sub->footer("\nExample:\n  mpirun -np 64 scalecert-mpi " + std::string(sub == golden ? "golden --family random --count 100000 --dir golden/"
                                                                                           : "audit --family sliver --sweep 2 --sweep-to 40 --count 1000 --out a.json --csv a.csv --no-timing") +
                    " --run run/\n  (rerun with --resume after a crash)");
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        const int st = rank == 0 ? app.exit(e) : 0;
        MPI_Finalize();
        return st;
    } catch (const CLI::ParseError& e) {
        return fail(rank, std::string(e.what()) + " (see scalecert-mpi --help)", 2);
    }
    CampaignArgs& a = *golden ? golden_args : audit_args;
    a.shard_size = shard_size;
    std::vector<Shard> shards;
    std::string identity;
    // Every rank checks the arguments the same way; rank 0 alone speaks, and every rank exits.
    try {
        validate(a);
        shards = plan(a);
        identity = campaign_identity(a);
    } catch (const InputError& e) {
        return fail(rank, e.what(), 2);
    }
    int setup_ok = 1;
    std::string setup_error;
    std::vector<int> todo;
    std::vector<std::string> hashes(shards.size());
    size_t done_before = 0, redone = 0;
    if (rank == 0) {
        try {
            if (a.golden) make_output_dir(a.dir);
            std::map<int, std::string> done;
            if (resume) {
                done = read_manifest(run, identity);
            } else {
                if (fs::exists(run + "/manifest.jsonl")) throw InputError(run + ": a run is already there (add --resume to go on with it)");
                std::error_code ec;
                fs::create_directories(run + "/shards", ec);
                if (ec) throw InputError(run + ": cannot create the run folder (" + ec.message() + ")");
                append_line(run + "/manifest.jsonl", identity);
            }
            for (const Shard& s : shards) {
                auto it = done.find(s.index);
                if (it != done.end()) {
                    const std::string text = slurp(shard_path(run, s.index));
                    if (sha256_hex(text) == it->second && shard_outputs_intact(a, text)) {
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
        auto may_start = [&] { return next < todo.size() && (stop_after < 0 || started < stop_after) && error.empty(); };
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
                std::fprintf(stderr, "scalecert-mpi: stopped after %zu shards as asked; %zu of %zu to go (--resume)\n", ran,
                             shards.size() - finished, shards.size());
                status = 3;
            } else {
                // Merge: every shard read back and checked against the manifest's hash.
                const auto merge_start = std::chrono::steady_clock::now();
                std::vector<std::string> texts;
                for (const Shard& s : shards) {
                    texts.push_back(slurp(shard_path(run, s.index)));
                    if (sha256_hex(texts.back()) != hashes[static_cast<size_t>(s.index)])
                        throw InputError(shard_path(run, s.index) + ": changed during the run (hash mismatch)");
                }
                const long n = finish_campaign(a, texts);
                const double merge = std::chrono::duration<double>(std::chrono::steady_clock::now() - merge_start).count();
                std::fprintf(stderr, "scalecert-mpi: %zu shards (%zu done before, %zu redone as damaged, %zu run now) on %d ranks: %ld %s; merge %.3f s\n",
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
