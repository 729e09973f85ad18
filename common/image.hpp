// PNG in and out (stb). Pixels are RGBA8, rows bottom-up as GL reads them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace shadows {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // bottom-up rows
};

// Writes atomically (temporary file, then rename) so a failure leaves no half file.
// Returns false on failure.
bool writePng(const std::string& path, const Image& image);
// Throws std::runtime_error naming the file when it is missing or not an image.
Image readPng(const std::string& path);
// True when `path` could be created: its directory exists and is writable.
bool canWrite(const std::string& path);

}  // namespace shadows
