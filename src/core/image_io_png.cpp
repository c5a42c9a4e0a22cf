// PNG reading and writing with libpng's classic API.
//
// libpng reports errors by longjmp. Every call that can fail runs inside a small function that owns
// the setjmp and holds only C data, so a jump never skips a C++ destructor; buffers and cleanup
// live in the calling frame, which has no setjmp.
#include <png.h>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <exception>
#include <memory>
#include <span>
#include <string>
#include <system_error>
#include <vector>

#include "core/png_text.h"
#include "image_writers.h"
#include "luxel/core/file_io.h"
#include "luxel/core/image_io.h"
#include "luxel/core/memory.h"
#include "luxel/core/tonemap.h"

namespace luxel {

namespace {

// State for libpng's callbacks.
struct PngContext {
    std::FILE* file = nullptr;
    int ioErrno = 0;  // errno of a failed read or write, reported with the error
    char error[256] = {};
    char warning[256] = {};
};

struct PngHeader {
    png_uint_32 width = 0;
    png_uint_32 height = 0;
    int bitDepth = 0;
    int channels = 0;
    std::size_t rowBytes = 0;        // per decoded row, after expansion
    std::size_t storedRowBytes = 0;  // per row as the file stores it, before expansion
    bool interlaced = false;         // Adam7: rows arrive in passes, so all are decoded at once
};

// Frees libpng's structures on every way out of the calling function.
struct PngReadStructs {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~PngReadStructs() {
        if (png != nullptr)
            png_destroy_read_struct(&png, info != nullptr ? &info : nullptr, nullptr);
    }
};

struct PngWriteStructs {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~PngWriteStructs() {
        if (png != nullptr) png_destroy_write_struct(&png, info != nullptr ? &info : nullptr);
    }
};

void onPngError(png_structp png, png_const_charp message) {
    auto* context = static_cast<PngContext*>(png_get_error_ptr(png));
    std::snprintf(context->error, sizeof context->error, "%s", message);
    png_longjmp(png, 1);
}

// Warnings are kept rather than printed: a later error such as "Invalid IHDR data" is explained
// only by the warning before it.
void onPngWarning(png_structp png, png_const_charp message) {
    auto* context = static_cast<PngContext*>(png_get_error_ptr(png));
    std::snprintf(context->warning, sizeof context->warning, "%s", message);
}

void readFromFile(png_structp png, png_bytep data, std::size_t length) {
    auto* context = static_cast<PngContext*>(png_get_io_ptr(png));
    if (std::fread(data, 1, length, context->file) != length) {
        if (std::feof(context->file)) png_error(png, "unexpected end of file (truncated?)");
        context->ioErrno = errno;
        png_error(png, "read error");
    }
}

void writeToFile(png_structp png, png_bytep data, std::size_t length) {
    auto* context = static_cast<PngContext*>(png_get_io_ptr(png));
    if (std::fwrite(data, 1, length, context->file) != length) {
        context->ioErrno = errno;
        png_error(png, "write error");
    }
}

void flushFile(png_structp png) {
    auto* context = static_cast<PngContext*>(png_get_io_ptr(png));
    if (std::fflush(context->file) != 0) {
        context->ioErrno = errno;
        png_error(png, "write error");
    }
}

// Reads the header and sets up expansion to 8 or 16 bits per channel with 1 to 4 channels.
bool readPngHeader(png_structp png, png_infop info, PngHeader* header) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_sig_bytes(png, 8);
    png_set_user_limits(png, kMaxImageSide, kMaxImageSide);
    png_read_info(png, info);
    header->storedRowBytes = png_get_rowbytes(png, info);
    header->interlaced = png_get_interlace_type(png, info) != PNG_INTERLACE_NONE;
    // Palette -> RGB, grey below 8 bits -> 8 bits, tRNS -> an alpha channel.
    png_set_expand(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    header->width = png_get_image_width(png, info);
    header->height = png_get_image_height(png, info);
    header->bitDepth = png_get_bit_depth(png, info);
    header->channels = png_get_channels(png, info);
    header->rowBytes = png_get_rowbytes(png, info);
    return true;
}

bool readPngRows(png_structp png, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    return true;
}

bool readPngRow(png_structp png, png_bytep row) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_row(png, row, nullptr);
    return true;
}

// Reading to IEND also catches files truncated after the pixel data; text chunks after the
// pixels join those before them in `info`.
bool readPngEnd(png_structp png, png_infop info) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_end(png, info);
    return true;
}

bool writePngHead(png_structp png, png_infop info, const PngHeader* header, int colorType,
                  bool srgb, const png_text* text, int textCount) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_IHDR(png, info, header->width, header->height, 8, colorType, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (srgb) png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    if (textCount > 0) png_set_text(png, info, text, textCount);
    png_write_info(png, info);
    return true;
}

// Rows go in one call per strip; libpng writes them one by one, as png_write_image would.
bool writePngStrip(png_structp png, png_bytepp rows, png_uint_32 count) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_write_rows(png, rows, count);
    return true;
}

bool writePngEnd(png_structp png) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_write_end(png, nullptr);
    return true;
}

Error openError(const std::string& path, int error) {
    return Error("cannot open '" + path + "': " + std::generic_category().message(error));
}

Error readError(const std::string& path, const std::string& problem) {
    return Error("cannot read PNG '" + path + "': " + problem);
}

Error writeError(const std::string& path, const std::string& problem) {
    return Error("cannot write PNG '" + path + "': " + problem);
}

std::string describeFailure(const PngContext& context) {
    std::string message = context.error[0] != '\0' ? context.error : "unknown libpng error";
    if (context.ioErrno != 0) message += ": " + std::generic_category().message(context.ioErrno);
    if (context.warning[0] != '\0') message += std::string(" (") + context.warning + ")";
    return message;
}

// Deflate expands by at most about 1032:1, so the filtered pixel data a header declares (a filter
// byte and the stored bytes per row) cannot come out of a much smaller file. A header claiming more
// is corrupt or truncated, and is refused before the decode buffer is allocated.
constexpr std::uint64_t kMaxDeflateRatio = 1100;
constexpr std::uint64_t kPngSlackBytes = 4096;

Status checkPngPlausible(const std::string& path, std::uint64_t fileBytes,
                         const PngHeader& header) {
    const std::uint64_t stored = (std::uint64_t{header.storedRowBytes} + 1) * header.height;
    if (stored > fileBytes * kMaxDeflateRatio + kPngSlackBytes) {
        return readError(path, "the header declares " + std::to_string(header.width) + "x" +
                                   std::to_string(header.height) + " pixels (" +
                                   formatBytes(stored) + " of pixel data), which a file of " +
                                   std::to_string(fileBytes) +
                                   " bytes cannot hold (truncated or corrupt)");
    }
    // The decode buffer (one row, or every row of an interlaced image) and the float image exist
    // together.
    const std::uint64_t decoded =
        std::uint64_t{header.rowBytes} * (header.interlaced ? header.height : 1);
    const std::uint64_t floats = std::uint64_t{header.width} * header.height *
                                 static_cast<std::uint64_t>(header.channels) * sizeof(float);
    if (Status s = checkMemory(decoded + floats, "decoding PNG '" + path + "' (" +
                                                     std::to_string(header.width) + "x" +
                                                     std::to_string(header.height) + ")");
        !s) {
        return s.error();
    }
    return Ok{};
}

int alphaChannel(int channels) {
    return channels == 2 ? 1 : (channels == 4 ? 3 : -1);
}

// Reads a PNG of `streamBytes` from an open stream; `path` names it in messages. The file reader
// and the in-memory reader (a stream over the bytes) share it, so both see the same checks.
Result<Image> readPngImpl(const FilePtr& file, std::uint64_t streamBytes, const std::string& path,
                          PngEncoding encoding, ImageMetadata* metadata) {
    std::array<png_byte, 8> signature{};
    if (std::fread(signature.data(), 1, signature.size(), file.get()) != signature.size()) {
        if (std::ferror(file.get())) return openError(path, errno);
        return readError(path, "not a PNG file (too short)");
    }
    if (png_sig_cmp(signature.data(), 0, signature.size()) != 0) {
        return readError(path, "not a PNG file (bad signature)");
    }

    PngContext context;
    context.file = file.get();
    PngReadStructs structs;
    structs.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &context, onPngError, onPngWarning);
    if (structs.png == nullptr) return readError(path, "cannot initialise libpng");
    structs.info = png_create_info_struct(structs.png);
    if (structs.info == nullptr) return readError(path, "cannot initialise libpng");
    png_set_read_fn(structs.png, &context, readFromFile);

    PngHeader header;
    if (!readPngHeader(structs.png, structs.info, &header)) {
        return readError(path, describeFailure(context));
    }
    const std::uint64_t pixels = std::uint64_t{header.width} * header.height;
    if (header.width == 0 || header.height == 0 || header.width > kMaxImageSide ||
        header.height > kMaxImageSide || pixels > kMaxImagePixels) {
        return readError(path, "image too large (" + std::to_string(header.width) + "x" +
                                   std::to_string(header.height) + "; the limit is " +
                                   std::to_string(kMaxImageSide) + " per side and " +
                                   std::to_string(kMaxImagePixels) + " pixels)");
    }
    if (header.channels < 1 || header.channels > 4 ||
        (header.bitDepth != 8 && header.bitDepth != 16)) {
        return readError(path, "unsupported layout (" + std::to_string(header.channels) +
                                   " channels of " + std::to_string(header.bitDepth) + " bits)");
    }
    if (Status s = checkPngPlausible(path, streamBytes, header); !s) return s.error();

    const int width = static_cast<int>(header.width);
    const int height = static_cast<int>(header.height);
    const int channels = header.channels;
    const int alpha = alphaChannel(channels);
    const bool srgb = encoding == PngEncoding::Srgb;
    std::array<float, 256> linearLut{}, srgbLut{};
    for (int v = 0; v < 256; ++v) {
        linearLut[v] = static_cast<float>(v) / 255.0f;
        srgbLut[v] = srgbToLinear(linearLut[v]);
    }
    Image image(width, height, channels);
    // One decoded row -> floats in image row y.
    auto convert = [&](const png_byte* row, int y) {
        float* out = image.data() + static_cast<std::size_t>(y) * width * channels;
        for (int i = 0; i < width * channels; ++i) {
            const bool colour = srgb && i % channels != alpha;
            if (header.bitDepth == 8) {
                *out++ = colour ? srgbLut[row[i]] : linearLut[row[i]];
            } else {
                // 16-bit PNG samples are big-endian.
                const int value = (row[2 * i] << 8) | row[2 * i + 1];
                const float v = static_cast<float>(value) / 65535.0f;
                *out++ = colour ? srgbToLinear(v) : v;
            }
        }
    };
    if (header.interlaced) {
        std::vector<png_byte> bytes(header.rowBytes * header.height);
        std::vector<png_bytep> rows(header.height);
        for (png_uint_32 y = 0; y < header.height; ++y)
            rows[y] = bytes.data() + y * header.rowBytes;
        if (!readPngRows(structs.png, rows.data())) {
            return readError(path, describeFailure(context));
        }
        for (int y = 0; y < height; ++y) convert(rows[y], y);
    } else {
        // Row by row: no buffer of the whole decoded image next to the floats.
        std::vector<png_byte> row(header.rowBytes);
        for (int y = 0; y < height; ++y) {
            if (!readPngRow(structs.png, row.data())) {
                return readError(path, describeFailure(context));
            }
            convert(row.data(), y);
        }
    }
    if (!readPngEnd(structs.png, structs.info)) return readError(path, describeFailure(context));
    if (metadata != nullptr) *metadata = detail::pngTextMetadata(structs.png, structs.info);
    return image;
}

Status writePngImpl(AtomicFile& file, const ImageRows& image, PngEncoding encoding,
                    const ImageMetadata& metadata) {
    if (image.empty()) return file.failure("the image is empty");
    if (Status s = checkMetadata(metadata); !s) return file.failure(s.error().message());
    const std::vector<png_text> text = detail::pngTextChunks(metadata);
    const int channels = image.channels;
    const int alpha = alphaChannel(channels);
    const bool srgb = encoding == PngEncoding::Srgb;
    const std::size_t rowBytes = image.rowFloats();

    int colorType = PNG_COLOR_TYPE_GRAY;
    if (channels == 2) colorType = PNG_COLOR_TYPE_GRAY_ALPHA;
    if (channels == 3) colorType = PNG_COLOR_TYPE_RGB;
    if (channels == 4) colorType = PNG_COLOR_TYPE_RGB_ALPHA;

    // One strip of encoded rows at a time: no 8-bit copy of the whole image.
    std::vector<png_byte> bytes(rowBytes * std::min(kImageStripRows, image.height));
    std::vector<png_bytep> rows(static_cast<std::size_t>(std::min(kImageStripRows, image.height)));
    for (std::size_t y = 0; y < rows.size(); ++y) rows[y] = bytes.data() + y * rowBytes;

    PngContext context;
    context.file = file.file();
    bool written = false;
    {
        PngWriteStructs structs;
        structs.png =
            png_create_write_struct(PNG_LIBPNG_VER_STRING, &context, onPngError, onPngWarning);
        if (structs.png != nullptr) structs.info = png_create_info_struct(structs.png);
        if (structs.info == nullptr) {
            std::snprintf(context.error, sizeof context.error, "cannot initialise libpng");
        } else {
            png_set_write_fn(structs.png, &context, writeToFile, flushFile);
            PngHeader header;
            header.width = static_cast<png_uint_32>(image.width);
            header.height = static_cast<png_uint_32>(image.height);
            written = writePngHead(structs.png, structs.info, &header, colorType, srgb, text.data(),
                                   static_cast<int>(text.size()));
            forEachStrip(image, kImageStripRows, [&](int y0, int y1, const float* in) {
                if (!written) return;
                const std::size_t count = static_cast<std::size_t>(y1 - y0) * rowBytes;
                for (std::size_t i = 0; i < count; ++i) {
                    const float v = in[i];
                    const bool colour = srgb && static_cast<int>(i % channels) != alpha;
                    // linearToSrgb clamps to [0, 1] and maps NaN to 0; the plain path does the
                    // same here.
                    const float encoded =
                        colour ? linearToSrgb(v) : (v > 0.0f ? std::min(v, 1.0f) : 0.0f);
                    bytes[i] = static_cast<png_byte>(encoded * 255.0f + 0.5f);
                }
                written =
                    writePngStrip(structs.png, rows.data(), static_cast<png_uint_32>(y1 - y0));
            });
            written = written && writePngEnd(structs.png);
        }
    }
    // The temporary is removed by AtomicFile unless the caller publishes it.
    if (!written) return file.failure(describeFailure(context));
    return Ok{};
}

}  // namespace

Result<Image> readPng(const std::string& path, PngEncoding encoding, ImageMetadata* metadata) {
    try {
        auto opened = openRegularFile(path);
        if (!opened) return Error("cannot open '" + path + "': " + opened.error().message());
        struct stat status {};
        const std::uint64_t size = ::fstat(::fileno(opened->get()), &status) == 0
                                       ? std::uint64_t(status.st_size)
                                       : ~std::uint64_t{0};  // no bound
        return readPngImpl(*opened, size, path, encoding, metadata);
    } catch (const std::exception& e) {
        return readError(path, e.what());
    } catch (...) {
        return readError(path, "unknown error");
    }
}

Result<Image> decodePng(std::span<const std::uint8_t> bytes, const std::string& name,
                        PngEncoding encoding, ImageMetadata* metadata) {
    // fmemopen refuses an empty buffer; such input is simply too short.
    if (bytes.size() < 8) return readError(name, "not a PNG file (too short)");
    try {
        // A read-only stream over the caller's bytes (fmemopen does not write in mode "rb").
        FilePtr file(::fmemopen(const_cast<std::uint8_t*>(bytes.data()), bytes.size(), "rb"),
                     &std::fclose);
        if (!file) return readError(name, std::generic_category().message(errno));
        return readPngImpl(file, bytes.size(), name, encoding, metadata);
    } catch (const std::exception& e) {
        return readError(name, e.what());
    } catch (...) {
        return readError(name, "unknown error");
    }
}

namespace detail {

Status writePngInto(AtomicFile& file, const ImageRows& image, PngEncoding encoding,
                    const ImageMetadata& metadata) {
    try {
        return writePngImpl(file, image, encoding, metadata);
    } catch (const std::exception& e) {
        return file.failure(e.what());
    } catch (...) {
        return file.failure("unknown error");
    }
}

}  // namespace detail

Status writePng(const std::string& path, const Image& image, PngEncoding encoding,
                const ImageMetadata& metadata) {
    try {
        Result<AtomicFile> file = AtomicFile::create(path, "PNG");
        if (!file) return file.error();
        if (Status s = detail::writePngInto(*file, rowsOf(image), encoding, metadata); !s) return s;
        return file->commit();
    } catch (const std::exception& e) {
        return writeError(path, e.what());
    } catch (...) {
        return writeError(path, "unknown error");
    }
}

}  // namespace luxel
