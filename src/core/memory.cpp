// Available-memory queries (Linux /proc, cgroup v2/v1 and rlimits) for allocation estimates.
#include "luxel/core/memory.h"

#include <sys/mman.h>
#include <sys/resource.h>

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

// A "Key:   1234 kB" line of /proc/self/status in bytes, or 0 when missing.
std::uint64_t readStatusBytes(const std::string& wanted) {
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line)) {
        if (line.compare(0, wanted.size(), wanted) != 0) continue;
        std::istringstream fields(line.substr(wanted.size()));
        std::uint64_t kib = 0;
        if (fields >> kib) return kib * 1024;
    }
    return 0;
}

// The soft limit `resource` minus what the process already uses of it (`statusKey` in
// /proc/self/status), or 0 when there is no limit. malloc fails at the soft limit whatever the
// machine has free, so `ulimit -v` and `ulimit -d` count like a cgroup limit.
std::uint64_t readRlimitHeadroom(int resource, const std::string& statusKey) {
    rlimit limit{};
    if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return 0;
    const std::uint64_t used = readStatusBytes(statusKey);
    const std::uint64_t cap = static_cast<std::uint64_t>(limit.rlim_cur);
    return cap > used ? cap - used : 1;
}

// The smallest of the known limits; 0 (unknown) never wins.
std::uint64_t smallestKnown(std::uint64_t a, std::uint64_t b) {
    if (a == 0) return b;
    if (b == 0) return a;
    return std::min(a, b);
}

}  // namespace

std::uint64_t availableMemoryBytes() {
    std::uint64_t available = smallestKnown(readMemAvailable(), readCgroupHeadroom());
    available = smallestKnown(available, readRlimitHeadroom(RLIMIT_AS, "VmSize:"));
    // Since Linux 4.7 RLIMIT_DATA bounds the private writable mappings (VmData).
    return smallestKnown(available, readRlimitHeadroom(RLIMIT_DATA, "VmData:"));
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

void adviseHugePages(void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr std::size_t kMinBytes = std::size_t{4} << 20, kPage = 4096;
    if (data == nullptr || bytes < kMinBytes) return;
    const auto begin = (reinterpret_cast<std::uintptr_t>(data) + kPage - 1) & ~(kPage - 1);
    const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kPage - 1);
    // Advice only: a kernel without THP refuses it, and the memory works the same.
    if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
    (void)data;
    (void)bytes;
#endif
}

}  // namespace luxel
