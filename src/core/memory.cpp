// Available-memory queries (Linux /proc and cgroup v2/v1) for allocation estimates.
#include "luxel/core/memory.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace luxel {
namespace {

std::uint64_t readMemAvailable() {
    std::ifstream in("/proc/meminfo");
    std::string key;
    std::uint64_t kib = 0;
    std::string unit;
    while (in >> key >> kib >> unit) {
        if (key == "MemAvailable:") return kib * 1024;
    }
    return 0;
}

// A cgroup limit minus current usage, or 0 when there is no limit.
std::uint64_t readCgroupHeadroom() {
    auto readNumber = [](const char* path, std::uint64_t& value) {
        std::ifstream in(path);
        std::string text;
        if (!(in >> text) || text == "max") return false;
        try {
            value = std::stoull(text);
        } catch (...) {
            return false;
        }
        return true;
    };
    std::uint64_t limit = 0, usage = 0;
    if (readNumber("/sys/fs/cgroup/memory.max", limit)) {
        readNumber("/sys/fs/cgroup/memory.current", usage);
    } else if (readNumber("/sys/fs/cgroup/memory/memory.limit_in_bytes", limit)) {
        readNumber("/sys/fs/cgroup/memory/memory.usage_in_bytes", usage);
        if (limit > (1ull << 60)) return 0;  // v1 reports "no limit" as a huge number
    } else {
        return 0;
    }
    return limit > usage ? limit - usage : 1;
}

}  // namespace

std::uint64_t availableMemoryBytes() {
    const std::uint64_t available = readMemAvailable();
    const std::uint64_t headroom = readCgroupHeadroom();
    if (available == 0) return headroom;
    if (headroom == 0) return available;
    return std::min(available, headroom);
}

std::string formatBytes(std::uint64_t bytes) {
    const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB"};
    double value = static_cast<double>(bytes);
    int unit = 0;
    while (value >= 1024.0 && unit < 5) {
        value /= 1024.0;
        ++unit;
    }
    char text[32];
    std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", value, units[unit]);
    return text;
}

Status checkMemory(std::uint64_t needed, const std::string& what) {
    const std::uint64_t available = availableMemoryBytes();
    if (available != 0 && needed > available) {
        return Error(what + " needs " + formatBytes(needed) + ", only " + formatBytes(available) +
                     " is available");
    }
    return Ok{};
}

}  // namespace luxel
