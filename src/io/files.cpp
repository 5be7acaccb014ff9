#include "io/files.hpp"

#include <filesystem>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <map>
#include <mutex>
#include <sys/stat.h>
#include <unistd.h>

namespace scalecert::internal {

namespace {
thread_local const InputObserver::Fn* t_observer = nullptr;

// What a file is, when it is not a regular file: for the one-line refusal.
std::string kind_of(mode_t m) {
    if (S_ISDIR(m)) return "is a directory";
    if (S_ISFIFO(m)) return "is a named pipe (FIFO)";
    if (S_ISSOCK(m)) return "is a socket";
    if (S_ISCHR(m)) return "is a character device";
    if (S_ISBLK(m)) return "is a block device";
    if (S_ISLNK(m)) return "is a symbolic link";
    return "is not a regular file";
}

// Standard input whole, in growing blocks, up to the limit.
std::string read_stdin(const std::string& what, size_t max_bytes) {
    std::string text;
    size_t used = 0, cap = 1 << 20;
    for (;; cap *= 2) {
        cap = std::min(cap, max_bytes + 1);
        text.resize(cap);
        used += std::fread(&text[used], 1, cap - used, stdin);
        if (used < cap || used > max_bytes) break;
    }
    if (std::ferror(stdin)) throw InputError("standard input: cannot read " + what);
    if (used > max_bytes)
        throw InputError("standard input: " + what + " larger than " + std::to_string(max_bytes >> 20) +
                         " MiB (the limit)");
    text.resize(used);
    return text;
}
}  // namespace

InputObserver::InputObserver(Fn f) : f_(std::move(f)), prev_(t_observer) { t_observer = &f_; }
InputObserver::~InputObserver() { t_observer = prev_; }

int open_regular_file(const std::string& path, const std::string& what, bool no_follow, size_t* size) {
    if (path.find('\0') != std::string::npos) throw InputError(in_quotes(path) + ": a file name with a NUL byte");
    // A name that is there and not a regular file is refused before it is opened at all (opening
    // a device can have effects); the descriptor's own fstat below settles any race.
    struct stat st {};
    if ((no_follow ? ::lstat(path.c_str(), &st) : ::stat(path.c_str(), &st)) == 0 && !S_ISREG(st.st_mode))
        throw InputError(path + ": " + kind_of(st.st_mode) + ", not a " + what + " (only regular files are read)");
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | (no_follow ? O_NOFOLLOW : 0));
    if (fd < 0) {
        const int err = errno;
        if (no_follow && err == ELOOP)
            throw InputError(path + ": is a symbolic link, not a " + what + " (only regular files are read)");
        throw InputError(path + ": cannot open " + what + " (" + std::strerror(err) + ")");
    }
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        const std::string kind = kind_of(st.st_mode);
        ::close(fd);
        throw InputError(path + ": " + kind + ", not a " + what + " (only regular files are read)");
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);  // a regular file: reads as usual
    if (size) *size = static_cast<size_t>(st.st_size);
    return fd;
}

std::string shell_word(const std::string& text) {
    if (!text.empty() && text.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_./-") ==
                             std::string::npos)
        return text;
    std::string q = "'";
    for (char ch : text) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    return q + "'";
}

std::string read_regular_file(const std::string& path, const std::string& what, size_t max_bytes, bool no_follow) {
    size_t size = 0;
    const int fd = open_regular_file(path, what, no_follow, &size);
    auto too_large = [&] {
        return InputError(path + ": " + what + " larger than " + std::to_string(max_bytes >> 20) + " MiB (the limit)");
    };
    if (size > max_bytes) {
        ::close(fd);
        throw too_large();
    }
    // One read of its size (plus one byte, to see a file that grew), then on to end of file.
    std::string text;
    size_t used = 0;
    text.resize(std::min(size, max_bytes) + 1);
    for (;;) {
        if (used == text.size()) {
            if (used > max_bytes) break;
            text.resize(std::min(std::max(text.size() * 2, size_t(1) << 16), max_bytes + 1));
        }
        const ssize_t got = ::read(fd, &text[used], text.size() - used);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) {
            const int err = errno;
            ::close(fd);
            throw InputError(path + ": cannot read " + what + " (" + std::strerror(err) + ")");
        }
        if (got == 0) break;
        used += static_cast<size_t>(got);
    }
    ::close(fd);
    if (used > max_bytes) throw too_large();
    text.resize(used);
    if (t_observer) (*t_observer)(path, text);
    return text;
}

std::string read_input(const std::string& path, const std::string& what, size_t max_bytes) {
    if (path != "-") return read_regular_file(path, what, max_bytes, false);
    std::string text = read_stdin(what, max_bytes);
    if (t_observer) (*t_observer)(path, text);
    return text;
}

void refuse_non_regular_output(const std::string& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        throw InputError(path + ": exists and is not a regular file (refused as an output)");
}

namespace {
// A temporary file beside `path`, created exclusively (mkstemp: O_CREAT | O_EXCL, an unpredictable
// name) so that nothing planted there is followed, holding `text` on disk (fsync). Refuses a
// target that exists and is not a regular file (a device, a directory, a symbolic link).
std::string write_temporary(const std::string& path, const std::string& text) {
    refuse_non_regular_output(path);
    const auto slash = path.rfind('/');
    const std::string dir = slash == std::string::npos ? "." : path.substr(0, slash == 0 ? 1 : slash);
    const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    if (base.empty()) throw InputError(path + ": not a file name");
    std::string tmp = dir + "/." + base + ".tmp.XXXXXX";
    int fd = ::mkstemp(&tmp[0]);
    if (fd < 0) throw InputError(path + ": cannot create a file in " + dir + " (" + std::strerror(errno) + ")");
    const mode_t mask = ::umask(0);
    ::umask(mask);
    bool ok = ::fchmod(fd, 0666 & ~mask) == 0;
    for (size_t done = 0; ok && done < text.size();) {
        const ssize_t w = ::write(fd, text.data() + done, text.size() - done);
        if (w < 0 && errno == EINTR) continue;
        ok = w > 0;
        if (ok) done += static_cast<size_t>(w);
    }
    ok = ok && ::fsync(fd) == 0;
    ok = ::close(fd) == 0 && ok;
    if (!ok) {
        ::unlink(tmp.c_str());
        throw InputError(path + ": write failed");
    }
    return tmp;
}
}  // namespace

namespace {
// The inputs noted by note_inputs, by device and inode (stat once, when noted), with the path as
// given for the message: each write looks its targets up instead of statting every input again
// (a golden run of N scenes writes 3N files).
std::mutex noted_mutex;
std::map<std::pair<dev_t, ino_t>, std::string> noted;
}  // namespace

namespace {
// The output journal (begin_output_journal): each file put in place, with the hard link that keeps
// what it replaced ("" when nothing was there), and each folder make_output_dir created.
std::mutex journal_mutex;
bool journal_on = false;
std::vector<std::pair<std::string, std::string>> journal_files;
std::vector<std::string> journal_dirs;
}  // namespace

void begin_output_journal() {
    const std::lock_guard<std::mutex> lock(journal_mutex);
    journal_on = true;
    journal_files.clear();
    journal_dirs.clear();
}

void undo_outputs() {
    const std::lock_guard<std::mutex> lock(journal_mutex);
    for (auto it = journal_files.rbegin(); it != journal_files.rend(); ++it) {
        if (it->second.empty())
            ::unlink(it->first.c_str());
        else
            std::rename(it->second.c_str(), it->first.c_str());
    }
    for (auto it = journal_dirs.rbegin(); it != journal_dirs.rend(); ++it) ::rmdir(it->c_str());  // only if empty
    journal_files.clear();
    journal_dirs.clear();
}

void commit_outputs() {
    const std::lock_guard<std::mutex> lock(journal_mutex);
    for (const auto& [path, kept] : journal_files)
        if (!kept.empty()) ::unlink(kept.c_str());
    journal_files.clear();
    journal_dirs.clear();
    journal_on = false;
}

void journal_dir(const std::string& dir) {
    const std::lock_guard<std::mutex> lock(journal_mutex);
    if (journal_on) journal_dirs.push_back(dir);
}

void note_inputs(const std::vector<std::string>& paths) {
    const std::lock_guard<std::mutex> lock(noted_mutex);
    for (const std::string& p : paths) {
        struct stat st {};
        if (!p.empty() && p != "-" && ::stat(p.c_str(), &st) == 0)
            noted.emplace(std::make_pair(st.st_dev, st.st_ino), p);
    }
}

void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files) {
    // An output over a noted input is refused, unless it writes the bytes the file holds (golden
    // --p1/--p2 writes its scene into the output folder, reads it, and writes it again).
    for (const auto& [path, text] : files) {
        struct stat st {};
        if (::stat(path.c_str(), &st) != 0) continue;  // not there yet: no input is it
        std::string input;
        {
            const std::lock_guard<std::mutex> lock(noted_mutex);
            const auto it = noted.find({st.st_dev, st.st_ino});
            if (it == noted.end()) continue;
            input = it->second;
        }
        bool same = false;
        if (S_ISREG(st.st_mode) && static_cast<size_t>(st.st_size) == text.size()) try {
                same = read_regular_file(path, "output file", text.size()) == text;
            } catch (const InputError&) {}
        if (!same) throw InputError(path + ": an output names an input file (" + input + "), which it would replace");
    }
    // Two outputs under one name (--out x --csv x, --out x --certificate x): the second would
    // replace the first. Compared as absolute, normalised paths (symbolic links to an existing
    // file followed), before anything is written.
    for (size_t i = 0; i < files.size(); ++i)
        for (size_t k = i + 1; k < files.size(); ++k) {
            // (weakly_canonical keeps a relative path relative when no part of it exists: x and ./x
            // would differ. Made absolute first, they compare equal.)
            std::error_code e1, e2, e3, e4;
            const auto a = std::filesystem::weakly_canonical(std::filesystem::absolute(files[i].first, e3), e1),
                       b = std::filesystem::weakly_canonical(std::filesystem::absolute(files[k].first, e4), e2);
            if (files[i].first == files[k].first ||
                (!e1 && !e2 && !e3 && !e4 && a.lexically_normal() == b.lexically_normal()))
                throw InputError(files[k].first + ": two outputs name the same file");
        }
    std::vector<std::string> tmps;
    try {
        for (const auto& [path, text] : files) tmps.push_back(write_temporary(path, text));
    } catch (...) {
        for (const std::string& t : tmps) ::unlink(t.c_str());
        throw;
    }
    for (size_t i = 0; i < files.size(); ++i) {
        const std::string& path = files[i].first;
        const std::lock_guard<std::mutex> lock(journal_mutex);
        std::string kept;
        if (journal_on) {  // what the rename replaces, kept under a second name until the run ends
            struct stat st {};
            if (::lstat(path.c_str(), &st) == 0) {
                kept = tmps[i] + ".old";
                // A second name for the old file; where the file system has no hard links, the old
                // file moved aside instead (the target is then missing for a moment).
                if (::link(path.c_str(), kept.c_str()) != 0 && std::rename(path.c_str(), kept.c_str()) != 0) {
                    for (size_t k = i; k < tmps.size(); ++k) ::unlink(tmps[k].c_str());
                    throw InputError(path + ": cannot keep the file it replaces (to put it back if the command fails)");
                }
            }
        }
        if (std::rename(tmps[i].c_str(), path.c_str()) != 0) {
            if (!kept.empty()) ::unlink(kept.c_str());
            for (size_t k = i; k < tmps.size(); ++k) ::unlink(tmps[k].c_str());
            throw InputError(path + ": cannot rename the temporary file into place");
        }
        if (journal_on) journal_files.emplace_back(path, kept);
    }
}

void write_file_atomically(const std::string& path, const std::string& text) { write_files_atomically({{path, text}}); }

void refuse_outputs_over_inputs(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs) {
    for (const std::string& o : outputs) {
        struct stat so {};
        if (o.empty() || o == "-" || ::stat(o.c_str(), &so) != 0) continue;  // not there yet: no input is it
        for (const std::string& i : inputs) {
            struct stat si {};
            if (!i.empty() && i != "-" && ::stat(i.c_str(), &si) == 0 && si.st_dev == so.st_dev &&
                si.st_ino == so.st_ino)
                throw InputError(o + ": an output names an input file (" + i + "), which it would replace");
        }
    }
}

namespace {
std::atomic<bool> quiet_notes{false};
}
void set_quiet(bool q) { quiet_notes = q; }
bool quiet() { return quiet_notes; }
void say_note(const std::string& text) {
    if (!quiet_notes) std::fprintf(stderr, "scalecert: note: %s\n", text.c_str());
}

}  // namespace scalecert::internal
