// Independent tasks 0..n−1 on `threads` threads (each thread takes every threads-th task, so the
// split depends on n and threads only). f(t, i) runs task i on thread t; results go to slots the
// caller indexes by i, so the output does not depend on the schedule. The first exception a thread
// throws is rethrown here once all have stopped (the other threads finish their current task and
// take no new one).
#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace scalecert::internal {

inline unsigned default_threads() { return std::max(1u, std::min(8u, std::thread::hardware_concurrency())); }

template <class F>
void parallel_tasks(std::size_t n, unsigned threads, F&& f) {
    threads = std::max(1u, std::min<unsigned>(threads, static_cast<unsigned>(std::max<std::size_t>(1, n))));
    std::vector<std::exception_ptr> errors(threads);
    std::atomic<bool> failed{false};
    auto run = [&](unsigned t) {
        try {
            for (std::size_t i = t; i < n && !failed.load(std::memory_order_relaxed); i += threads) f(t, i);
        } catch (...) {
            errors[t] = std::current_exception();
            failed = true;
        }
    };
    if (threads == 1) {
        run(0);
    } else {
        std::vector<std::thread> pool;
        for (unsigned t = 0; t < threads; ++t) pool.emplace_back(run, t);
        for (std::thread& th : pool) th.join();
    }
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
}

}  // namespace scalecert::internal
