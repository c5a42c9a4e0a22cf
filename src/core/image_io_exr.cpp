// EXR reading and writing with the OpenEXR 3 C++ API (32-bit float channels, linear values).
#include <ImathBox.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <ImfStringAttribute.h>
#include <ImfThreading.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "core/exr_header_check.h"
#include "image_writers.h"
#include "luxel/core/file_io.h"
#include "luxel/core/image_io.h"
#include "luxel/core/memory.h"
#include "luxel/core/parallel.h"

namespace luxel {

namespace {

Error readError(const std::string& path, const std::string& problem) {
    return Error("cannot read EXR '" + path + "': " + problem);
}

Error writeError(const std::string& path, const std::string& problem) {
    return Error("cannot write EXR '" + path + "': " + problem);
}

// OpenEXR's output stream over an AtomicFile's FILE. OutputFile's destructor writes the line
// offset table and swallows errors, so a failure is also remembered here and checked afterwards.
class AtomicFileStream final : public Imf::OStream {
  public:
    explicit AtomicFileStream(AtomicFile& file)
        : Imf::OStream(file.temporaryPath().c_str()), file_(file.file()) {}

    void write(const char c[], int n) override {
        if (error_ == 0 &&
            std::fwrite(c, 1, static_cast<std::size_t>(n), file_) != static_cast<std::size_t>(n)) {
            error_ = errno != 0 ? errno : EIO;
        }
        if (error_ != 0) throw std::runtime_error(std::generic_category().message(error_));
    }
    std::uint64_t tellp() override {
        const off_t at = ::ftello(file_);
        if (at < 0) fail();
        return static_cast<std::uint64_t>(at);
    }
    void seekp(std::uint64_t pos) override {
        if (::fseeko(file_, static_cast<off_t>(pos), SEEK_SET) != 0) fail();
    }
    int error() const { return error_; }

  private:
    void fail() {
        if (error_ == 0) error_ = errno != 0 ? errno : EIO;
        throw std::runtime_error(std::generic_category().message(error_));
    }

    std::FILE* file_;
    int error_ = 0;
};

// OpenEXR's own message for a missing file is long and varies by version, and it would block on
// a FIFO; opening it first as a regular file gives the same messages as the PNG reader.
Status canOpen(const std::string& path) {
    auto opened = openRegularFile(path);
    if (!opened) return Error("cannot open '" + path + "': " + opened.error().message());
    return Ok{};
}

// The channels to read, in image order: R,G,B(,A), or Y(,A).
std::vector<std::string> chooseChannels(const Imf::ChannelList& list) {
    const auto has = [&](const char* name) { return list.findChannel(name) != nullptr; };
    std::vector<std::string> names;
    if (has("R") && has("G") && has("B")) {
        names = {"R", "G", "B"};
    } else if (has("Y")) {
        names = {"Y"};
    } else {
        return names;
    }
    if (has("A")) names.push_back("A");
    return names;
}

std::string listChannels(const Imf::ChannelList& list) {
    std::string out;
    for (auto it = list.begin(); it != list.end(); ++it) {
        if (!out.empty()) out += ", ";
        out += it.name();
    }
    return out.empty() ? "none" : out;
}

// OpenEXR's input stream over bytes in memory (decodeExr). Reads past the end throw, as
// OpenEXR's own file stream does on a truncated file.
class MemoryStream final : public Imf::IStream {
  public:
    MemoryStream(std::span<const std::uint8_t> bytes, const std::string& name)
        : Imf::IStream(name.c_str()), bytes_(bytes) {}

    bool read(char c[], int n) override {
        if (n < 0 || static_cast<std::uint64_t>(n) > bytes_.size() - at_) {
            throw std::runtime_error("unexpected end of file (truncated?)");
        }
        std::memcpy(c, bytes_.data() + at_, static_cast<std::size_t>(n));
        at_ += static_cast<std::uint64_t>(n);
        return at_ < bytes_.size();
    }
    std::uint64_t tellg() override { return at_; }
    void seekg(std::uint64_t pos) override {
        if (pos > bytes_.size()) throw std::runtime_error("seek past the end of the file");
        at_ = pos;
    }

  private:
    std::span<const std::uint8_t> bytes_;
    std::uint64_t at_ = 0;
};

// Reads an EXR of `totalBytes` from `stream`; `path` names it in messages. The file reader and
// the in-memory reader share it, so both see the same checks.
// The header's string attributes, in the header's (alphabetical) order.
ImageMetadata stringAttributes(const Imf::Header& header) {
    ImageMetadata metadata;
    for (auto it = header.begin(); it != header.end(); ++it) {
        if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&it.attribute())) {
            metadata.push_back({it.name(), text->value()});
        }
    }
    return metadata;
}

Result<Image> readExrImpl(Imf::IStream& stream, std::uint64_t totalBytes, const std::string& path,
                          ImageMetadata* metadata) {
    if (Status s = detail::checkExrAttributeSizes(stream, totalBytes); !s) {
        return readError(path, s.error().message());
    }
    Imf::InputFile file(stream);
    const Imf::Header& header = file.header();
    if (metadata != nullptr) *metadata = stringAttributes(header);
    const Imath::Box2i window = header.dataWindow();
    const std::int64_t width = std::int64_t{window.max.x} - window.min.x + 1;
    const std::int64_t height = std::int64_t{window.max.y} - window.min.y + 1;
    if (width <= 0 || height <= 0) return readError(path, "the data window is empty");
    if (width > kMaxImageSide || height > kMaxImageSide ||
        static_cast<std::uint64_t>(width * height) > kMaxImagePixels) {
        return readError(path, "image too large (" + std::to_string(width) + "x" +
                                   std::to_string(height) + "; the limit is " +
                                   std::to_string(kMaxImageSide) + " per side and " +
                                   std::to_string(kMaxImagePixels) + " pixels)");
    }

    const Imf::ChannelList& list = header.channels();
    const std::vector<std::string> names = chooseChannels(list);
    if (names.empty()) {
        return readError(path, "no R,G,B or Y channels (the file has: " + listChannels(list) + ")");
    }
    for (const std::string& name : names) {
        const Imf::Channel& channel = list[name];
        if (channel.xSampling != 1 || channel.ySampling != 1) {
            return readError(path, "channel " + name + " is subsampled, which is not supported");
        }
    }

    const int channels = static_cast<int>(names.size());
    // The float image, plus OpenEXR's decode of one chunk at a time (small next to it). Unlike
    // PNG's deflate, EXR's codecs (PIZ, DWA) have no useful bound on their expansion, so the
    // declared size is checked against memory only.
    const std::uint64_t bytes =
        static_cast<std::uint64_t>(width * height) * static_cast<std::uint64_t>(channels) * 4;
    if (Status s = checkMemory(bytes, "decoding EXR '" + path + "' (" + std::to_string(width) +
                                          "x" + std::to_string(height) + ")");
        !s) {
        return s.error();
    }
    Image image(static_cast<int>(width), static_cast<int>(height), channels);
    const std::size_t xStride = sizeof(float) * channels;
    const std::size_t yStride = xStride * static_cast<std::size_t>(width);
    Imf::FrameBuffer frameBuffer;
    for (int c = 0; c < channels; ++c) {
        // Slice::Make offsets the pointer by the data window origin without overflow.
        frameBuffer.insert(
            names[c], Imf::Slice::Make(Imf::FLOAT, image.data() + c, window, xStride, yStride));
    }
    file.setFrameBuffer(frameBuffer);
    file.readPixels(window.min.y, window.max.y);
    return image;
}

int openExrThreads() {
    // ZIP compression of the line blocks runs on OpenEXR's thread pool, one thread per core.
    static const int threads = [] {
        Imf::setGlobalThreadCount(hardwareThreads());
        return Imf::globalThreadCount();
    }();
    return threads;
}

Status writeExrImpl(AtomicFile& out, const ImageRows& image, const ImageMetadata& metadata) {
    static const std::vector<std::string> kNames[] = {
        {"Y"}, {"Y", "A"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
    const std::vector<std::string>& names = kNames[image.channels - 1];

    Imf::Header header(image.width, image.height);
    for (const std::string& name : names) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    for (const MetadataEntry& entry : metadata) {
        // The header's own attributes (channels, compression, dataWindow, ...) keep their types.
        if (header.find(entry.key) != header.end()) {
            return out.failure("metadata key '" + entry.key +
                               "' is one of the EXR header's own attributes");
        }
        header.insert(entry.key, Imf::StringAttribute(entry.value));
    }
    AtomicFileStream stream(out);
    {
        Imf::OutputFile file(stream, header, openExrThreads());
        const std::size_t xStride = sizeof(float) * image.channels;
        const std::size_t yStride = xStride * static_cast<std::size_t>(image.width);
        // An image is read in place in one call; rows made on demand go strip by strip, each a
        // frame buffer of its own (OpenEXR takes a new one between writePixels calls).
        const int stripRows = image.image != nullptr ? image.height : detail::exrStripRows();
        forEachStrip(image, stripRows, [&](int y0, int y1, const float* strip) {
            Imf::FrameBuffer frameBuffer;
            for (int c = 0; c < image.channels; ++c) {
                // Slice::Make places the strip's first row at row y0 without overflow.
                frameBuffer.insert(names[c],
                                   Imf::Slice::Make(Imf::FLOAT, strip + c, Imath::V2i(0, y0),
                                                    image.width, y1 - y0, xStride, yStride));
            }
            file.setFrameBuffer(frameBuffer);
            file.writePixels(y1 - y0);
        });
    }
    if (stream.error() != 0) return out.failure(std::generic_category().message(stream.error()));
    return Ok{};
}

}  // namespace

Result<Image> readExr(const std::string& path, ImageMetadata* metadata) {
    if (Status s = canOpen(path); !s) return s.error();
    try {
        Imf::StdIFStream stream(path.c_str());
        std::error_code error;
        const std::uintmax_t size = std::filesystem::file_size(path, error);
        return readExrImpl(stream, error ? ~std::uint64_t{0} : size, path, metadata);
    } catch (const std::exception& e) {
        return readError(path, e.what());
    } catch (...) {
        return readError(path, "unknown error");
    }
}

Result<Image> decodeExr(std::span<const std::uint8_t> bytes, const std::string& name,
                        ImageMetadata* metadata) {
    try {
        MemoryStream stream(bytes, name);
        return readExrImpl(stream, bytes.size(), name, metadata);
    } catch (const std::exception& e) {
        return readError(name, e.what());
    } catch (...) {
        return readError(name, "unknown error");
    }
}

namespace detail {

int exrStripRows() {
    return 2 * 16 * std::max(1, openExrThreads());
}

Status writeExrInto(AtomicFile& file, const ImageRows& image, const ImageMetadata& metadata) {
    if (image.empty() || image.channels < 1 || image.channels > 4) {
        return file.failure("the image is empty");
    }
    if (Status s = checkMetadata(metadata); !s) return file.failure(s.error().message());
    try {
        return writeExrImpl(file, image, metadata);
    } catch (const std::exception& e) {
        return file.failure(e.what());
    } catch (...) {
        return file.failure("unknown error");
    }
}

}  // namespace detail

Status writeExr(const std::string& path, const Image& image, const ImageMetadata& metadata) {
    if (image.empty() || image.channels() < 1 || image.channels() > 4) {
        return writeError(path, "the image is empty");
    }
    Result<AtomicFile> file = AtomicFile::create(path, "EXR");
    if (!file) return file.error();
    if (Status s = detail::writeExrInto(*file, rowsOf(image), metadata); !s) return s;
    return file->commit();
}

}  // namespace luxel
