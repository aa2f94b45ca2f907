// SPDX-License-Identifier: Apache-2.0
// PNG encoding and decoding of Images (libpng), for render output and reference images.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "varc/core/Result.h"
#include "varc/image/Image.h"

namespace varc::image {

// Encodes |image| as an 8-bit RGBA PNG with zlib |zlibLevel| (0 = store .. 9 = smallest) and
// one fixed row filter ("sub") instead of libpng's per-row adaptive choice. Float (HDR) images are
// first converted with Image::toRgba8(Tonemap::Clamp): linear values clamped to [0, 1] and scaled
// by 255, with no exposure, tonemapping curve or sRGB encoding; call toRgba8 yourself for another
// Tonemap. Level 1 is the default because libpng's defaults cost more than a lavapipe render: for a
// 512x512 gradient-plus-noise image, level 6 with adaptive filters takes ~77 ms, level 1 with
// "sub" ~7.5 ms (files ~10% larger than level 6 "sub"; flat renders compress either way). Errors:
// ErrorCode::InvalidInput for an empty image or a level outside 0..9, ErrorCode::Internal when
// libpng fails.
Result<std::string> encodePng(const Image& image, int zlibLevel = 1);

// encodePng, then writes the bytes to |path| atomically (varc::writeFileAtomically): readers
// see the old file or the whole new one. Errors: those of encodePng, ErrorCode::IoError.
Status writePng(const std::string& path, const Image& image, int zlibLevel = 1);

// The largest PNG decodePng accepts (16384 x 16384), so a forged header cannot make it
// allocate gigabytes.
constexpr uint64_t kMaxPngPixels = uint64_t{1} << 28;

// Decodes PNG bytes of any colour type and bit depth to an Rgba8 image (libpng's simplified
// API: palette and grey expand to RGB, missing alpha becomes 255, 16-bit channels are reduced
// to 8 bits). Errors: ErrorCode::InvalidInput with libpng's message, or for images over
// kMaxPngPixels pixels.
Result<Image> decodePng(std::string_view bytes);

// Reads |path| and decodes it with decodePng. Errors: ErrorCode::IoError when the file cannot
// be read, else those of decodePng (the message names |path|).
Result<Image> readPng(const std::string& path);

}  // namespace varc::image
