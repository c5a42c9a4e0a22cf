// Memory estimates: refuse politely before an allocation that would not fit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "luxel/core/error.h"

namespace luxel {

// Bytes this process may still allocate: MemAvailable from /proc/meminfo, capped by a cgroup
// memory limit and by the soft RLIMIT_AS (`ulimit -v`) and RLIMIT_DATA (`ulimit -d`) less what the
// process already maps, when there are such limits. Returns 0 when unknown (then checks pass).
// Every check before a large allocation goes through this one function (via checkMemory).
std::uint64_t availableMemoryBytes();

// "1.5 GiB", "320 MiB", "12 KiB"
std::string formatBytes(std::uint64_t bytes);

// Ok when `needed` bytes fit in the available memory; otherwise an Error like
// "rendering 60000x60000 needs 120.7 GiB, only 20.1 GiB is available".
Status checkMemory(std::uint64_t needed, const std::string& what);

// Asks the kernel to back [data, data + bytes) with transparent huge pages where it allows them
// (Linux with THP in "madvise" or "always" mode; elsewhere nothing happens). Call it before the
// memory is first written: pages already touched stay small. Only for buffers of 4 MiB and more,
// where strided reads (a canvas walked down its columns) miss the TLB on every row.
void adviseHugePages(void* data, std::size_t bytes);

// v.resize(n), where growing makes a new allocation advised onto huge pages before its first
// write (then value-initialised: zeros for numbers). Old elements are not kept when it grows.
template <typename T>
void resizeOnHugePages(std::vector<T>& v, std::size_t n) {
    if (v.capacity() < n) {
        std::vector<T> fresh;
        fresh.reserve(n);
        adviseHugePages(fresh.data(), n * sizeof(T));
        v.swap(fresh);
    }
    v.resize(n);
}

}  // namespace luxel
