#include "image.hpp"

#include <stb_image.h>
#include <stb_image_write.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace shadows {

bool writePng(const std::string& path, const Image& image) {
  const std::string temporary = path + ".partial";
  const int stride = image.width * 4;
  // stb writes top-down; start at the last GL row and walk backwards.
  const auto* last_row = image.rgba.data() + static_cast<size_t>(stride) * (image.height - 1);
  if (!stbi_write_png(temporary.c_str(), image.width, image.height, 4, last_row, -stride)) {
    std::remove(temporary.c_str());
    return false;
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) std::remove(temporary.c_str());
  return !ec;
}

Image readPng(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (pixels == nullptr) {
    throw std::runtime_error(path + ": cannot read image (" + stbi_failure_reason() + ")");
  }
  Image image{w, h, std::vector<std::uint8_t>(static_cast<size_t>(w) * h * 4)};
  for (int y = 0; y < h; ++y) {
    std::copy_n(pixels + static_cast<size_t>(h - 1 - y) * w * 4, w * 4,
                image.rgba.begin() + static_cast<std::ptrdiff_t>(y) * w * 4);
  }
  stbi_image_free(pixels);
  return image;
}

bool canWrite(const std::string& path) {
  if (path.empty()) return false;
  const auto parent = std::filesystem::absolute(path).parent_path();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return false;
  return std::filesystem::is_directory(parent, ec) && access(parent.c_str(), W_OK) == 0;
}

}  // namespace shadows
