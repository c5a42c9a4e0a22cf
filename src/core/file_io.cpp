#include "luxel/core/file_io.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <system_error>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace luxel {

Result<FilePtr> openRegularFile(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return Error(std::generic_category().message(errno));
    const auto fail = [fd](const std::string& reason) {
        ::close(fd);
        return Error(reason);
    };
    struct stat info {};
    if (::fstat(fd, &info) != 0) return fail(std::generic_category().message(errno));
    if (S_ISDIR(info.st_mode)) return fail(std::generic_category().message(EISDIR));
    if (!S_ISREG(info.st_mode)) return fail("not a regular file");
    const int flags = ::fcntl(fd, F_GETFL);
    if (flags < 0 || ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != 0) {
        return fail(std::generic_category().message(errno));
    }
    std::FILE* file = ::fdopen(fd, "rb");
    if (file == nullptr) return fail(std::generic_category().message(errno));
    return FilePtr(file, &std::fclose);
}

Result<std::string> readFileBytes(const std::string& path, const std::string& what,
                                  std::uintmax_t maxBytes) {
    auto opened = openRegularFile(path);
    if (!opened)
        return Error("cannot open " + what + " '" + path + "': " + opened.error().message());
    FilePtr file = std::move(*opened);
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    const std::string tooLarge = what + " file '" + path + "' is too large (at most " +
                                 std::to_string(maxBytes >> 20) + " MiB)";
    if (!ec && size > maxBytes) return Error(tooLarge);
    // Read in chunks up to the limit: file_size may be stale.
    std::string text;
    char buffer[1 << 16];
    for (;;) {
        const std::size_t n = std::fread(buffer, 1, sizeof(buffer), file.get());
        text.append(buffer, n);
        if (text.size() > maxBytes) return Error(tooLarge);
        if (n < sizeof(buffer)) break;
    }
    if (std::ferror(file.get())) {
        return Error("cannot read " + what + " '" + path +
                     "': " + std::generic_category().message(errno));
    }
    return text;
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : target_(std::move(other.target_)),
      temporary_(std::move(other.temporary_)),
      what_(std::move(other.what_)),
      file_(std::exchange(other.file_, nullptr)),
      published_(std::exchange(other.published_, true)) {}

AtomicFile& AtomicFile::operator=(AtomicFile&& other) noexcept {
    if (this != &other) {
        discard();
        target_ = std::move(other.target_);
        temporary_ = std::move(other.temporary_);
        what_ = std::move(other.what_);
        file_ = std::exchange(other.file_, nullptr);
        published_ = std::exchange(other.published_, true);
    }
    return *this;
}

AtomicFile::~AtomicFile() {
    discard();
}

void AtomicFile::discard() {
    if (file_ != nullptr) std::fclose(std::exchange(file_, nullptr));
    if (!published_ && !temporary_.empty()) ::unlink(temporary_.c_str());
    published_ = true;
}

Error AtomicFile::failure(const std::string& reason) const {
    return Error("cannot write " + what_ + " '" + target_ + "': " + reason);
}

Result<AtomicFile> AtomicFile::create(const std::string& target, const std::string& what) {
    static std::atomic<unsigned> counter{0};
    AtomicFile out;
    out.target_ = target;
    out.what_ = what;
    // Pid and counter make the name unique per process and thread; "x" refuses an existing file.
    // A crash leaves at most a stray ".tmp-" file, never a truncated target.
    out.temporary_ =
        target + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1));
    out.file_ = std::fopen(out.temporary_.c_str(), "wbx");
    if (out.file_ == nullptr) {
        const int error = errno;
        out.temporary_.clear();  // not ours to remove
        return out.failure(std::generic_category().message(error));
    }
    return out;
}

Status AtomicFile::finish() {
    if (file_ == nullptr) return failure("the file is not open");
    // Buffered write errors (ENOSPC, EIO) surface at fflush, fsync or fclose; each is checked.
    int error = 0;
    if (std::ferror(file_)) error = errno != 0 ? errno : EIO;
    if (error == 0 && std::fflush(file_) != 0) error = errno;
    if (error == 0 && ::fsync(::fileno(file_)) != 0 && errno != EINVAL) error = errno;
    const int closed = std::fclose(std::exchange(file_, nullptr));
    if (error == 0 && closed != 0) error = errno;
    if (error != 0) {
        discard();
        return failure(std::generic_category().message(error));
    }
    return Ok{};
}

Status AtomicFile::publish() {
    if (file_ != nullptr || published_) return failure("the file is not finished");
    if (::rename(temporary_.c_str(), target_.c_str()) != 0) {
        const int error = errno;
        discard();
        return failure(std::generic_category().message(error));
    }
    published_ = true;
    return Ok{};
}

Status AtomicFile::commit() {
    if (Status s = finish(); !s) return s;
    return publish();
}

Status commitAll(AtomicFile* files, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
        if (Status s = files[i].finish(); !s) return s;
    }
    for (std::size_t i = 0; i < count; ++i) {
        if (Status s = files[i].publish(); !s) return s;
    }
    return Ok{};
}

Status writeFileAtomically(const std::string& path, std::string_view bytes,
                           const std::string& what) {
    Result<AtomicFile> file = AtomicFile::create(path, what);
    if (!file) return file.error();
    if (!bytes.empty() &&
        std::fwrite(bytes.data(), 1, bytes.size(), file->file()) != bytes.size()) {
        return file->failure(std::generic_category().message(errno));
    }
    return file->commit();
}

}  // namespace luxel
