// Runs a check in a forked child whose soft RLIMIT_AS (or RLIMIT_DATA) leaves only `headroom`
// bytes above what the process maps already, so memory refusals can be tested on any machine.
#pragma once

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

namespace luxel::test {

// A "Key:  1234 kB" line of /proc/self/status in bytes (0 when missing).
inline std::uint64_t procStatusBytes(const std::string& key) {
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind(key, 0) == 0) {
            std::istringstream fields(line.substr(key.size()));
            std::uint64_t kib = 0;
            fields >> kib;
            return kib * 1024;
        }
    }
    return 0;
}

// The child's exit code is `check`'s result (0: passed); 100 + n when setting the limit failed,
// 128 + signal when it crashed.
inline int runUnderMemoryLimit(std::uint64_t headroom, const std::function<int()>& check,
                               int resource = RLIMIT_AS) {
    const pid_t pid = fork();
    if (pid == 0) {
        const std::uint64_t used = procStatusBytes(resource == RLIMIT_AS ? "VmSize:" : "VmData:");
        rlimit limit{};
        if (used == 0 || getrlimit(resource, &limit) != 0) _exit(101);
        limit.rlim_cur = used + headroom;
        if (limit.rlim_max != RLIM_INFINITY && limit.rlim_max < limit.rlim_cur) _exit(102);
        if (setrlimit(resource, &limit) != 0) _exit(103);
        _exit(check());
    }
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace luxel::test
