#include "luxel/core/file_io.h"

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <system_error>

#include <unistd.h>

namespace luxel {

Result<std::string> readFileBytes(const std::string& path, const std::string& what,
                                  std::uintmax_t maxBytes) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                         &std::fclose);
    if (!file) {
        return Error("cannot open " + what + " '" + path +
                     "': " + std::generic_category().message(errno));
    }
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    const std::string tooLarge = what + " file '" + path + "' is too large (at most " +
                                 std::to_string(maxBytes >> 20) + " MiB)";
    if (!ec && size > maxBytes) return Error(tooLarge);
    // Read in chunks up to the limit: file_size is unknown for pipes and may be stale.
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

Status writeFileAtomically(const std::string& path, std::string_view bytes,
                           const std::string& what) {
    auto failure = [&](const std::string& reason) {
        return Error("cannot write " + what + " '" + path + "': " + reason);
    };
    // Unique per process; a crash leaves at most a stray ".tmp" file, never a truncated target.
    const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
    {
        std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(temporary.c_str(), "wb"),
                                                             &std::fclose);
        if (!file) return failure(std::generic_category().message(errno));
        if (!bytes.empty() &&
            std::fwrite(bytes.data(), 1, bytes.size(), file.get()) != bytes.size()) {
            const std::string reason = std::generic_category().message(errno);
            file.reset();
            std::remove(temporary.c_str());
            return failure(reason);
        }
        if (std::fflush(file.get()) != 0) {
            const std::string reason = std::generic_category().message(errno);
            file.reset();
            std::remove(temporary.c_str());
            return failure(reason);
        }
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::remove(temporary.c_str());
        return failure(ec.message());
    }
    return Ok{};
}

}  // namespace luxel
