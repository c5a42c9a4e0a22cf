// Thread-count control for the oneTBB loops.
#include "luxel/core/parallel.h"

#include <algorithm>
#include <thread>

#include "luxel/core/thread_team.h"

namespace luxel {

ThreadLimit::ThreadLimit(int threads) {
    if (threads > 0) {
        control_ = std::make_unique<tbb::global_control>(
            tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
    }
}

int hardwareThreads() {
    const unsigned n = std::thread::hardware_concurrency();
    return n == 0 ? 1 : static_cast<int>(n);
}

int ThreadTeam::defaultSize() {
    const auto allowed = static_cast<int>(
        tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
    return std::max(1, std::min(allowed, hardwareThreads()));
}

}  // namespace luxel
