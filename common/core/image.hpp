// PNG in and out (stb). Pixels are RGBA8, rows bottom-up as GL reads them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/output_files.hpp"
#include "core/text.hpp"

namespace shadows {

// The largest side an image parameter may have (its header is read before it is decoded).
constexpr int kMaxImageSide = 8192;

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // bottom-up rows
};

// Writes as every output is written (output_files.hpp): atomically for a regular file.
// Returns false on failure.
bool writePng(const std::string& path, const Image& image);
// Throws std::runtime_error naming the file when it is missing, not a regular file (a FIFO is
// never read: it could hang), not a PNG (other formats stb could read are refused: the
// parameters and the help say PNG), or declares more than kMaxImageSide a side.
Image readPng(const std::string& path);
// The PNG bytes of an image ("" if it cannot be encoded).
std::string encodePng(const Image& image);

// The `check` of an image parameter: "" for "builtin" or a PNG that loads (at most 8192
// pixels a side), else one line saying what is accepted or what is wrong with the file.
std::string checkPngParam(const std::string& value);

}  // namespace shadows
