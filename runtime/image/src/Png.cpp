// SPDX-License-Identifier: Apache-2.0
// PNG encoding and decoding of Images (libpng), for render output and reference images.
#include "varc/image/Png.h"

#include <png.h>

#include <csetjmp>
#include <cstring>
#include <vector>

#include "varc/core/AtomicFile.h"
#include "varc/core/FileRead.h"

namespace varc::image {

namespace {

// Where libpng's callbacks put output and the first error message.
struct EncodeState {
    std::string* out = nullptr;
    char error[256] = {};
};

void onPngError(png_structp png, png_const_charp message) {
    auto* state = static_cast<EncodeState*>(png_get_error_ptr(png));
    std::strncpy(state->error, message ? message : "unknown libpng error",
                 sizeof(state->error) - 1);
    png_longjmp(png, 1);
}

void onPngWarning(png_structp, png_const_charp) {}

void onPngWrite(png_structp png, png_bytep data, png_size_t length) {
    auto* state = static_cast<EncodeState*>(png_get_io_ptr(png));
    state->out->append(reinterpret_cast<const char*>(data), length);
}

void onPngFlush(png_structp) {}

// Runs libpng over prepared |rows|. libpng reports errors by longjmp to the setjmp below, so
// this function holds no objects with destructors (a longjmp would skip them).
bool encodeRows(png_bytepp rows, png_uint_32 width, png_uint_32 height, int zlibLevel,
                EncodeState* state) {
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, state, onPngError, onPngWarning);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, state, onPngWrite, onPngFlush);
    png_set_compression_level(png, zlibLevel);
    // One fixed filter: libpng's adaptive choice tries all five per row, ~1.7x slower at
    // level 1 for a similar size.
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace

Result<std::string> encodePng(const Image& image, int zlibLevel) {
    if (image.width() == 0 || image.height() == 0) {
        return makeError(ErrorCode::InvalidInput, "cannot encode an empty image as PNG");
    }
    if (zlibLevel < 0 || zlibLevel > 9) {
        return makeError(ErrorCode::InvalidInput,
                         "zlib level " + std::to_string(zlibLevel) + " is outside 0..9");
    }
    Image converted;
    const Image& rgba8 = image.isFloat() ? (converted = image.toRgba8(Tonemap::Clamp)) : image;
    std::vector<png_bytep> rows(rgba8.height());
    // libpng's row type is non-const but png_write_image only reads the rows.
    auto* base = const_cast<png_bytep>(rgba8.bytes().data());
    for (uint32_t y = 0; y < rgba8.height(); ++y) {
        rows[y] = base + std::size_t{y} * rgba8.width() * 4;
    }
    std::string out;
    out.reserve(std::size_t{rgba8.width()} * rgba8.height());
    EncodeState state;
    state.out = &out;
    if (!encodeRows(rows.data(), rgba8.width(), rgba8.height(), zlibLevel, &state)) {
        return makeError(ErrorCode::Internal, std::string("libpng failed: ") + state.error);
    }
    return out;
}

Status writePng(const std::string& path, const Image& image, int zlibLevel) {
    Result<std::string> encoded = encodePng(image, zlibLevel);
    if (!encoded) return encoded.error();
    return writeFileAtomically(path, *encoded);
}

Result<Image> decodePng(std::string_view bytes) {
    png_image header{};
    header.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&header, bytes.data(), bytes.size())) {
        return makeError(ErrorCode::InvalidInput, std::string("not a PNG: ") + header.message);
    }
    if (uint64_t{header.width} * header.height > kMaxPngPixels) {
        png_image_free(&header);
        return makeError(ErrorCode::InvalidInput, "PNG of " + std::to_string(header.width) + "x" +
                                                      std::to_string(header.height) +
                                                      " pixels is too large");
    }
    header.format = PNG_FORMAT_RGBA;
    Image image(header.width, header.height, PixelFormat::Rgba8);
    if (!png_image_finish_read(&header, nullptr, image.bytes().data(), 0, nullptr)) {
        png_image_free(&header);
        return makeError(ErrorCode::InvalidInput, std::string("corrupt PNG: ") + header.message);
    }
    return image;
}

Result<Image> readPng(const std::string& path) {
    Result<std::string> bytes = readFile(path);
    if (!bytes) return bytes.error();
    Result<Image> image = decodePng(*bytes);
    if (!image) return makeError(image.error().code, path + ": " + image.error().detail);
    return image;
}

}  // namespace varc::image
