// scalecert-check FILE: reads one certificate (a regular file, at most 1 GiB) and prints one line.
// Exit 0: valid. Exit 1: the first claim that fails, on stderr. Exit 2: the file cannot be read
// (missing, not a regular file, too large, not strict JSON, too deeply nested, out of memory, past
// the work limit). The checking itself is check_text (check.hpp).
#include "check.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <new>
#include <string>

namespace {
// GMP aborts when an allocation fails: here that becomes std::bad_alloc, exit 2.
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
    if (argc == 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
        std::cout << "usage: scalecert-check CERTIFICATE.json\n\n"
                     "Checks a scalecert certificate (a partition, a query answer or certify-fp's judgements;\n"
                     "certificates/FORMAT.md), re-deriving every claim from the scene stored in it.\n"
                     "Prints one line.\n"
                     "Exit status: 0 valid, 1 invalid (the first claim that fails), 2 unreadable or refused\n"
                     "(not a regular file, too large, malformed JSON, past the work limit).\n"
                     "A file named --help or --version: give it as ./--help.\n";
        return 0;
    }
#ifdef SCALECERT_VERSION_STRING
    if (argc == 2 && std::strcmp(argv[1], "--version") == 0) {
        std::cout << "scalecert-check " SCALECERT_VERSION_STRING "\n";
        return 0;
    }
#endif
    if (argc != 2) {
        std::cerr << "usage: scalecert-check CERTIFICATE.json (scalecert-check --help)\n";
        return 2;
    }
    std::string name = scalecert_check::printable(argv[1]), text;
    try {
        // Opened without blocking (a FIFO with no writer, a terminal) and refused unless a
        // regular file: a FIFO, socket, device or directory is never read. (The engine has the
        // same rule in its own code; the checker shares none.)
        auto refuse = [&](const std::string& why) {
            std::cerr << "scalecert-check: error: " << name << ": " << why << "\n";
            return 2;
        };
        auto kind = [](mode_t m) -> std::string {
            if (S_ISDIR(m)) return "is a directory";
            if (S_ISFIFO(m)) return "is a named pipe (FIFO)";
            if (S_ISSOCK(m)) return "is a socket";
            if (S_ISCHR(m)) return "is a character device";
            if (S_ISBLK(m)) return "is a block device";
            return "is not a regular file";
        };
        const std::string not_regular = ", not a certificate file (only regular files are read)";
        struct stat st {};
        if (::stat(argv[1], &st) == 0 && !S_ISREG(st.st_mode)) return refuse(kind(st.st_mode) + not_regular);
        const int fd = ::open(argv[1], O_RDONLY | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0) return refuse(std::string("cannot open (") + std::strerror(errno) + ")");
        if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
            ::close(fd);
            return refuse(kind(st.st_mode) + not_regular);
        }
        if (static_cast<unsigned long long>(st.st_size) > scalecert_check::kMaxFileBytes) {
            ::close(fd);
            return refuse("larger than 1 GiB");
        }
        ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
        text.reserve(static_cast<size_t>(st.st_size) + 1);  // (a file that grows while read still appends)
        char buf[1 << 16];
        bool too_big = false, failed = false;
        for (;;) {
            const ssize_t got = ::read(fd, buf, sizeof buf);
            if (got < 0 && errno == EINTR) continue;
            if (got <= 0) {
                failed = got < 0;
                break;
            }
            text.append(buf, static_cast<size_t>(got));
            if (text.size() > scalecert_check::kMaxFileBytes) {
                too_big = true;
                break;
            }
        }
        ::close(fd);
        if (failed) return refuse("cannot read");
        if (too_big) return refuse("larger than 1 GiB");
        std::string message;
        int status = scalecert_check::check_text(text, message);
        (status == 0 ? std::cout : std::cerr)
            << (status == 0 ? "" : "scalecert-check: ")
            << (status == 2 ? "error: " + name + ": " + message.substr(7) : message) << "\n";
        return status;
    } catch (const std::bad_alloc&) {
        std::cerr << "scalecert-check: error: " << name << ": out of memory\n";
        return 2;
    }
}
