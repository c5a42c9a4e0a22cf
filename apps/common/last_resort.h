// The last resort of luxel and luxel-view when memory runs out where no estimate caught it:
// std::bad_alloc (and std::length_error from a size nobody checked, and the std::system_error of a
// thread that could not start) become one error line and exit code 1 instead of std::terminate
// and SIGABRT. Estimates and checkMemory
// (luxel/core/memory.h) refuse most such work before it starts; this only catches the rest.
#pragma once

#include <cstdio>
#include <new>
#include <stdexcept>
#include <string>
#include <system_error>

namespace luxel::options {

// Runs `body` (returning the exit code); `program` and `task` name the line:
// "luxel: error: out of memory while running 'render'; try a smaller --size".
template <typename Body>
int runUntilOutOfMemory(const char* program, const std::string& task, Body&& body) {
    std::string what;
    try {
        return body();
    } catch (const std::bad_alloc&) {
        what = "out of memory";
    } catch (const std::length_error&) {
        what = "a size too large to allocate";
    } catch (const std::system_error& e) {
        // std::thread and TBB report a thread they cannot start (no memory for its stack) so.
        what = std::string("out of system resources (") + e.what() + ")";
    }
    std::fprintf(stderr, "%s: error: %s while %s; try a smaller --size or free some memory\n",
                 program, what.c_str(), task.c_str());
    return 1;
}

}  // namespace luxel::options
