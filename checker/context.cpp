#include "context.hpp"

namespace scalecert_check {
void Context::over_budget() const {
    throw Unreadable{"beyond the checker's work limit (" + std::to_string(static_cast<long long>(work_per_byte)) +
                     " units a byte of the file; FORMAT.md \"What the checker costs\")"};
}
}  // namespace scalecert_check
