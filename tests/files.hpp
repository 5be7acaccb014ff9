// Test helpers for files: read one whole, and a scratch directory per test process.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace test {

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// A directory under the system's temporary directory, named for `tag` and this process, removed
// with what it holds when the process exits normally (a crashed run leaves it to look at).
inline std::filesystem::path scratch_dir(const std::string& tag) {
    std::filesystem::path p =
        std::filesystem::temp_directory_path() / ("scalecert-" + tag + "-" + std::to_string(::getpid()));
    std::filesystem::create_directories(p);
    struct RemovedAtExit {
        std::vector<std::filesystem::path> dirs;
        ~RemovedAtExit() {
            std::error_code ec;
            for (const std::filesystem::path& d : dirs) std::filesystem::remove_all(d, ec);
        }
    };
    static RemovedAtExit removed;
    removed.dirs.push_back(p);
    return p;
}

}  // namespace test
