// Memory estimates: refuse politely before an allocation that would not fit.
#pragma once

#include <cstdint>
#include <string>

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

}  // namespace luxel
