// readImage / writeImage: choose the PNG or EXR codec by the file extension.
#include <cctype>
#include <exception>
#include <filesystem>
#include <string>

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

Result<Image> readImage(const std::string& path) {
    try {
        switch (formatOf(path)) {
            case ImageFormat::Png:
                return readPng(path);
            case ImageFormat::Exr:
                return readExr(path);
            case ImageFormat::Unknown:
                break;
        }
        return unknownFormat("read", path);
    } catch (const std::exception& e) {
        return Error("cannot read '" + path + "': " + e.what());
    }
}

Status writeImage(const std::string& path, const Image& image) {
    try {
        switch (formatOf(path)) {
            case ImageFormat::Png:
                return writePng(path, image);
            case ImageFormat::Exr:
                return writeExr(path, image);
            case ImageFormat::Unknown:
                break;
        }
        return unknownFormat("write", path);
    } catch (const std::exception& e) {
        return Error("cannot write '" + path + "': " + e.what());
    }
}

}  // namespace luxel
