#include "baselines/guest.hpp"

#include "io/files.hpp"
#include "io/strict_json.hpp"
#include "numeric/exact.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include <dirent.h>
#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace scalecert::internal {
namespace {

// Every process on the machine as pid -> (parent pid, state letter), from /proc/PID/stat.
std::map<pid_t, std::pair<pid_t, char>> processes() {
    std::map<pid_t, std::pair<pid_t, char>> all;
    DIR* d = opendir("/proc");
    if (!d) return all;
    while (const dirent* e = readdir(d)) {
        char* end = nullptr;
        const long pid = std::strtol(e->d_name, &end, 10);
        if (pid <= 0 || *end) continue;
        std::ifstream in(std::string("/proc/") + e->d_name + "/stat");
        std::string line;
        if (!std::getline(in, line)) continue;  // gone meanwhile
        // "pid (comm) state ppid ...": comm may hold spaces and parentheses; the last ')' ends it.
        const size_t close = line.rfind(')');
        if (close == std::string::npos || close + 4 >= line.size()) continue;
        std::istringstream rest(line.substr(close + 2));
        char state = '?';
        long ppid = 0;
        if (rest >> state >> ppid) all[static_cast<pid_t>(pid)] = {static_cast<pid_t>(ppid), state};
    }
    closedir(d);
    return all;
}

// The descendants of this process (children, their children, ...), with their parent and state.
std::map<pid_t, std::pair<pid_t, char>> descendants() {
    const auto all = processes();
    std::multimap<pid_t, pid_t> children;
    for (const auto& [pid, ps] : all) children.emplace(ps.first, pid);
    std::map<pid_t, std::pair<pid_t, char>> out;
    std::vector<pid_t> todo{getpid()};
    while (!todo.empty()) {
        const pid_t p = todo.back();
        todo.pop_back();
        auto [lo, hi] = children.equal_range(p);
        for (auto it = lo; it != hi; ++it)
            if (out.emplace(it->second, all.at(it->second)).second) todo.push_back(it->second);
    }
    return out;
}

// Kills every descendant not in `keep` and reaps those that are this process's children, until
// none is left (a process forking meanwhile is found on the next round; one that dies leaves its
// children to this process, the subreaper). Bounded at 10 s, for a process that cannot die.
void stop_descendants(const std::set<pid_t>& keep) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    for (long nap_us = 200;; nap_us = std::min(nap_us * 2, 20000L)) {
        bool left = false;
        for (const auto& [pid, ps] : descendants()) {
            if (keep.count(pid)) continue;
            left = true;
            if (ps.second != 'Z') kill(pid, SIGKILL);
            if (ps.first == getpid()) waitpid(pid, nullptr, WNOHANG);
        }
        if (!left || std::chrono::steady_clock::now() >= until) return;
        usleep(static_cast<useconds_t>(nap_us));
    }
}

// A signal that asks scalecert to stop (SIGINT, SIGTERM, SIGHUP) while the guest runs: noted, so
// that the guest and what it started are stopped before scalecert ends as the signal asks.
volatile std::sig_atomic_t g_stop_signal = 0;
void note_stop_signal(int sig) { g_stop_signal = sig; }
constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP};

// Reads what is there on fd into the count, keeping the last 4096 bytes in `tail` when given:
// 1 when it read something, 0 at end of file (or an error), -1 when nothing is there yet.
int drain(int fd, long long& count, std::string* tail) {
    char buf[65536];
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n < 0) return errno == EINTR || errno == EAGAIN ? -1 : 0;
    if (n == 0) return 0;
    count += n;
    if (tail) {
        tail->append(buf, static_cast<size_t>(n));
        if (tail->size() > 4096) tail->erase(0, tail->size() - 4096);
    }
    return true;
}

}  // namespace

GuestSignals::GuestSignals() {
    struct sigaction on_stop;
    std::memset(&on_stop, 0, sizeof on_stop);
    on_stop.sa_handler = note_stop_signal;  // (no SA_RESTART: poll and usleep return at once)
    sigemptyset(&on_stop.sa_mask);
    g_stop_signal = 0;
    for (int k = 0; k < 3; ++k) {  // (a signal the caller ignores, as nohup does SIGHUP, stays ignored)
        sigaction(kStopSignals[k], nullptr, &before_[k]);
        if (before_[k].sa_handler != SIG_IGN) sigaction(kStopSignals[k], &on_stop, nullptr);
    }
}

GuestSignals::~GuestSignals() {
    for (int k = 0; k < 3; ++k) sigaction(kStopSignals[k], &before_[k], nullptr);
}

int GuestSignals::pending() const { return g_stop_signal; }

void GuestSignals::end_by(int sig, const std::string& folder) {
    std::error_code ec;
    std::filesystem::remove_all(folder, ec);
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    std::_Exit(128 + sig);  // (raise returns only if the signal is blocked)
}

std::string printable(const std::string& text) {
    std::string out;
    for (size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        const size_t n = c < 0x80 ? 1 : utf8_sequence_length(text, i);
        if (n == 0 || (n == 1 && (c < 0x20 || c == 0x7f))) {
            out += '?';
            ++i;
        } else {
            out.append(text, i, n);
            i += n;
        }
    }
    return out;
}

std::string GuestRun::why_failed(double timeout) const {
    char m[200];
    switch (end) {
    case Exited:
        if (code > 128 && code < 128 + 65)  // what /bin/sh reports of a command a signal killed
            std::snprintf(m, sizeof m,
                          "it exited with status %d (the shell's word for a command killed by signal %d, %s)", code,
                          code - 128, strsignal(code - 128));
        else
            std::snprintf(m, sizeof m, "it exited with status %d", code);
        break;
    case Signalled: std::snprintf(m, sizeof m, "it was killed by signal %d (%s)", code, strsignal(code)); break;
    case TimedOut:
        std::snprintf(m, sizeof m, "it did not finish within %g s (--command-timeout) and was stopped", timeout);
        break;
    case NotStarted: std::snprintf(m, sizeof m, "it could not be started"); break;
    case Interrupted:
        std::snprintf(m, sizeof m, "scalecert was sent signal %d (%s) and stopped it", code, strsignal(code));
        break;
    }
    return last_error_line.empty() ? std::string(m) : m + std::string("; its error output ended: ") + last_error_line;
}

GuestRun run_guest(const std::string& command, double timeout) {
    GuestRun g;
    int out[2], err[2];
    if (pipe2(out, O_CLOEXEC) != 0) return g;
    if (pipe2(err, O_CLOEXEC) != 0) {
        close(out[0]);
        close(out[1]);
        return g;
    }
    const std::set<pid_t> before = [] {
        std::set<pid_t> s;
        for (const auto& kv : descendants()) s.insert(kv.first);
        return s;
    }();
    int was_subreaper = 0;
    prctl(PR_GET_CHILD_SUBREAPER, &was_subreaper);
    prctl(PR_SET_CHILD_SUBREAPER, 1);
    std::fflush(nullptr);
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid == 0) {
        // In scalecert's process group (Ctrl-C, or `timeout` signalling the group, reaches it too),
        // and killed if scalecert dies first.
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (getppid() != parent) _exit(127);
        const int in = open("/dev/null", O_RDONLY);
        if (in < 0 || dup2(in, 0) < 0 || dup2(out[1], 1) < 0 || dup2(err[1], 2) < 0) _exit(127);
        execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    close(out[1]);
    close(err[1]);
    if (pid > 0) {
        const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout);
        bool open_out = true, open_err = true;
        std::string tail;
        int status = 0;
        for (long nap_ms = 1;; nap_ms = std::min(nap_ms * 2, 50L)) {
            const pid_t r = waitpid(pid, &status, WNOHANG);
            if (r == pid) {
                g.end = WIFEXITED(status) ? GuestRun::Exited : GuestRun::Signalled;
                g.code = WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status);
                break;
            }
            const auto now = std::chrono::steady_clock::now();
            if (g_stop_signal) {
                g.end = GuestRun::Interrupted;
                g.code = g_stop_signal;
                kill(pid, SIGKILL);
                break;
            }
            if ((r < 0 && errno != EINTR) || now >= until) {
                g.end = GuestRun::TimedOut;
                kill(pid, SIGKILL);
                break;
            }
            pollfd fds[2] = {{out[0], POLLIN, 0}, {err[0], POLLIN, 0}};
            const long left_ms = std::chrono::duration_cast<std::chrono::milliseconds>(until - now).count() + 1;
            if (open_out || open_err) {
                if (!open_out) fds[0].fd = -1;
                if (!open_err) fds[1].fd = -1;
                if (poll(fds, 2, static_cast<int>(std::min(nap_ms, left_ms))) > 0) {
                    if (fds[0].revents) open_out = drain(out[0], g.stdout_bytes, nullptr) != 0;
                    if (fds[1].revents) open_err = drain(err[0], g.stderr_bytes, &tail) != 0;
                    nap_ms = 1;
                }
            } else {
                usleep(static_cast<useconds_t>(1000 * std::min(nap_ms, left_ms)));
            }
        }
        // Whatever is still running of it: the program's own processes outlive it no longer.
        stop_descendants(before);
        // Every writer is gone: what is left in the pipes, to their ends.
        for (int fd : {out[0], err[0]}) fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
        while (open_out && drain(out[0], g.stdout_bytes, nullptr) == 1) {}
        while (open_err && drain(err[0], g.stderr_bytes, &tail) == 1) {}
        // The last two non-empty lines of its error output (the shell's word on a signal comes
        // after the program's own last line), joined by " / ", printable.
        std::vector<std::string> lines;
        for (size_t end = tail.size(); lines.size() < 2 && end > 0;) {
            while (end > 0 && (tail[end - 1] == '\n' || tail[end - 1] == '\r')) --end;
            if (end == 0) break;
            const size_t nl = tail.find_last_of('\n', end - 1);
            const size_t begin = nl == std::string::npos ? 0 : nl + 1;
            lines.insert(lines.begin(), tail.substr(begin, end - begin));
            end = begin;
        }
        std::string line;
        for (const std::string& l : lines) line += (line.empty() ? "" : " / ") + l;
        if (line.size() > kKeptErrorBytes) line = "..." + line.substr(line.size() - kKeptErrorBytes);
        g.last_error_line = printable(line);
    }
    close(out[0]);
    close(err[0]);
    if (g_stop_signal && g.end != GuestRun::Interrupted) g.end = GuestRun::Interrupted, g.code = g_stop_signal;
    prctl(PR_SET_CHILD_SUBREAPER, was_subreaper);
    return g;
}

GuestFolder::GuestFolder() {
    std::vector<std::string> bases;
    if (const char* t = std::getenv("TMPDIR"); t && *t) {
        struct stat st {};
        if (stat(t, &st) == 0 && S_ISDIR(st.st_mode)) bases.push_back(t);
    }
    bases.push_back("/tmp");  // where $TMPDIR is unset, or no folder can be made in it
    int err = 0;
    for (std::string base : bases) {
        while (base.size() > 1 && base.back() == '/') base.pop_back();
        std::string templ = base + "/scalecert-command-XXXXXX";
        if (mkdtemp(templ.data())) {
            path_ = templ;
            return;
        }
        err = errno;
    }
    throw InputError(std::string("--command: cannot make a temporary folder in /tmp (") + std::strerror(err) + ")");
}

GuestFolder::~GuestFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
    if (!ec) return;
    // A folder the program made read-only (as some caches are): made writable, then again.
    namespace fs = std::filesystem;
    for (auto it = fs::recursive_directory_iterator(path_, fs::directory_options::skip_permission_denied, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
        if (it->is_directory(ec) && !it->is_symlink(ec)) fs::permissions(it->path(), fs::perms::owner_all, ec);
    fs::permissions(path_, fs::perms::owner_all, ec);
    ec.clear();
    fs::remove_all(path_, ec);
    if (ec) internal::say_note(path_ + ": the program's folder could not be removed (" + ec.message() + ")");
}

}  // namespace scalecert::internal
