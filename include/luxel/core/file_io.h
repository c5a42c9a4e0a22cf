// Whole-file reads with a size limit, and writes that never leave a half-written file: the bytes
// go to a temporary file next to the target, which is renamed over it only once complete.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

#include "luxel/core/error.h"

namespace luxel {

using FilePtr = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

// `path` opened for reading when it is a regular file. A FIFO or a device would block the reader
// (opening a FIFO waits for a writer) or never end, so the open is non-blocking and fstat on the
// open descriptor decides: nothing can be swapped in between. The error is the bare reason
// ("not a regular file", "Is a directory", "No such file or directory") for callers to prefix.
Result<FilePtr> openRegularFile(const std::string& path);

// The bytes of a regular file of at most `maxBytes` ("cannot open scene 'p': reason",
// "scene file 'p' is too large (at most 64 MiB)"). `what` names the kind of file.
Result<std::string> readFileBytes(const std::string& path, const std::string& what,
                                  std::uintmax_t maxBytes = std::uintmax_t{64} << 20);

// Writes `bytes` to `path` through a temporary file in the same folder and a rename, so `path`
// holds either its old content or all of the new ("cannot write octree 'p': reason").
Status writeFileAtomically(const std::string& path, std::string_view bytes,
                           const std::string& what);

// A file written under a fresh temporary name next to `target` (same folder, so the final rename
// is atomic). finish() flushes, syncs and closes it, checking each step; publish() renames it over
// the target. Writers of several files finish() all of them before publishing any, so a failure
// leaves every target as it was. The destructor removes a temporary that was not published.
// Errors read "cannot write <what> '<target>': reason".
class AtomicFile {
  public:
    static Result<AtomicFile> create(const std::string& target, const std::string& what);
    AtomicFile(AtomicFile&& other) noexcept;
    AtomicFile& operator=(AtomicFile&& other) noexcept;
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;
    ~AtomicFile();

    std::FILE* file() const { return file_; }
    const std::string& target() const { return target_; }
    const std::string& temporaryPath() const { return temporary_; }
    Error failure(const std::string& reason) const;

    Status finish();
    Status publish();
    Status commit();  // finish() then publish()

  private:
    AtomicFile() = default;
    void discard();

    std::string target_;
    std::string temporary_;
    std::string what_;
    std::FILE* file_ = nullptr;
    bool published_ = false;
};

// finish()es every file, then publishes them in order; stops at the first error.
Status commitAll(AtomicFile* files, std::size_t count);

}  // namespace luxel
