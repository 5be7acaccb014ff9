// The check on every option that names an output file: an empty name is refused (it wrote to
// standard output, as if --out were not given).
#pragma once
#include <CLI/CLI.hpp>

#include <string>

namespace scalecert::cli {

inline CLI::Validator file_name() {
    return CLI::Validator([](std::string& s) { return s.empty() ? std::string("an empty file name") : std::string(); },
                          "");
}

}  // namespace scalecert::cli
