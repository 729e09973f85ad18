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
// The same for any output: a new or regular file is replaced atomically; anything else that
// exists (/dev/null, a pipe) is written in place, never replaced.
bool writeOutputFile(const std::string& path, const std::string& bytes);
// Throws std::runtime_error naming the file when it is missing or not an image.
Image readPng(const std::string& path);
// True when `path` can be written: an existing non-directory we may write to, or a new file
// in a directory that exists and is writable.
bool canWrite(const std::string& path);

}  // namespace shadows
