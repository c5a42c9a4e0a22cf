// readImage / writeImage: choose the PNG or EXR codec by the file extension.
#include <cctype>
#include <exception>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "image_writers.h"
#include "luxel/core/file_io.h"
#include "luxel/core/image_io.h"

namespace luxel {

namespace {

enum class ImageFormat { Png, Exr, Unknown };

ImageFormat formatOf(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".png") return ImageFormat::Png;
    if (extension == ".exr") return ImageFormat::Exr;
    return ImageFormat::Unknown;
}

Error unknownFormat(const char* verb, const std::string& path) {
    return Error(std::string("cannot ") + verb + " '" + path +
                 "': unknown image format (the extension must be .png or .exr)");
}

}  // namespace

Result<Image> readImage(const std::string& path, ImageMetadata* metadata) {
    try {
        switch (formatOf(path)) {
            case ImageFormat::Png:
                return readPng(path, PngEncoding::Srgb, metadata);
            case ImageFormat::Exr:
                return readExr(path, metadata);
            case ImageFormat::Unknown:
                break;
        }
        return unknownFormat("read", path);
    } catch (const std::exception& e) {
        return Error("cannot read '" + path + "': " + e.what());
    }
}

Status writeImage(const std::string& path, const Image& image, const ImageMetadata& metadata) {
    try {
        switch (formatOf(path)) {
            case ImageFormat::Png:
                return writePng(path, image, PngEncoding::Srgb, metadata);
            case ImageFormat::Exr:
                return writeExr(path, image, metadata);
            case ImageFormat::Unknown:
                break;
        }
        return unknownFormat("write", path);
    } catch (const std::exception& e) {
        return Error("cannot write '" + path + "': " + e.what());
    }
}

Status writeImages(const std::vector<ImageFile>& files) {
    static const ImageMetadata kNone;
    std::vector<AtomicFile> written;
    written.reserve(files.size());
    for (const ImageFile& entry : files) {
        const ImageFormat format = formatOf(entry.path);
        if (format == ImageFormat::Unknown) return unknownFormat("write", entry.path);
        Result<AtomicFile> file =
            AtomicFile::create(entry.path, format == ImageFormat::Png ? "PNG" : "EXR");
        if (!file) return file.error();
        const ImageMetadata& metadata = entry.metadata != nullptr ? *entry.metadata : kNone;
        LUXEL_CHECK(entry.rows != nullptr || entry.image != nullptr);
        const ImageRows rows = entry.rows != nullptr ? *entry.rows : rowsOf(*entry.image);
        const Status s = format == ImageFormat::Png
                             ? detail::writePngInto(*file, rows, PngEncoding::Srgb, metadata)
                             : detail::writeExrInto(*file, rows, metadata);
        if (!s) return s;
        written.push_back(std::move(*file));
    }
    return commitAll(written.data(), written.size());
}

}  // namespace luxel
