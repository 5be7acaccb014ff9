#include "points.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

#include <cstdint>
#include <cstdlib>
#include <new>

namespace scalecert_check {
void advise_huge_pages(void* p, size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // madvise takes whole pages: those inside the block (the kernel gives 2 MiB pages to the
    // aligned stretches within them).
    const long size = ::sysconf(_SC_PAGESIZE);
    if (size <= 0) return;
    const uintptr_t page = static_cast<uintptr_t>(size), a = (reinterpret_cast<uintptr_t>(p) + page - 1) & ~(page - 1),
                    e = (reinterpret_cast<uintptr_t>(p) + bytes) & ~(page - 1);
    if (e > a) ::madvise(reinterpret_cast<void*>(a), e - a, MADV_HUGEPAGE);  // advice: its failure changes nothing
#else
    (void)p;
    (void)bytes;
#endif
}

namespace {
constexpr size_t kMapFrom = size_t(1) << 20;  // bytes from which an Int64s is a mapping of its own
}

void Int64s::grow(size_t need) {
    const size_t cap = std::max<size_t>({need, 2 * cap_, 1024}), bytes = cap * sizeof(int64_t);
#if defined(__linux__) && defined(MREMAP_MAYMOVE)
    if (bytes >= kMapFrom) {
        void* q;
        if (mapped_) {
            q = ::mremap(p_, cap_ * sizeof(int64_t), bytes, MREMAP_MAYMOVE);
        } else {
            q = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
            if (q != MAP_FAILED) {
                if (n_) std::memcpy(q, p_, n_ * sizeof(int64_t));
                std::free(p_);
            }
        }
        if (q == MAP_FAILED) throw std::bad_alloc();
        p_ = static_cast<int64_t*>(q);
        cap_ = cap;
        mapped_ = true;
        advise_huge_pages(p_, bytes);
        return;
    }
#endif
    void* q = std::realloc(p_, bytes);
    if (!q) throw std::bad_alloc();
    p_ = static_cast<int64_t*>(q);
    cap_ = cap;
}

void Int64s::release() {
#if defined(__linux__) && defined(MREMAP_MAYMOVE)
    if (mapped_) {
        ::munmap(p_, cap_ * sizeof(int64_t));
        return;
    }
#endif
    std::free(p_);
}
}  // namespace scalecert_check
