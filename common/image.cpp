#include "image.hpp"

#include <stb_image.h>
#include <stb_image_write.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

// libstb exports this, but its header declares it only in the implementation section.
extern "C" unsigned char* stbi_write_png_to_mem(const unsigned char* pixels, int stride_bytes,
                                                int x, int y, int n, int* out_len);

namespace shadows {

bool writeOutputFile(const std::string& path, const std::string& bytes) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    std::ofstream out(path, std::ios::binary);
    out << bytes;
    return static_cast<bool>(out.flush());
  }
  const std::string temporary = path + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << bytes;
    if (!out.flush()) {
      out.close();
      std::remove(temporary.c_str());
      return false;
    }
  }
  std::filesystem::rename(temporary, path, ec);
  if (ec) std::remove(temporary.c_str());
  return !ec;
}

bool writePng(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0) return false;
  const int stride = image.width * 4;
  // stb writes top-down; start at the last GL row and walk backwards.
  const auto* last_row = image.rgba.data() + static_cast<size_t>(stride) * (image.height - 1);
  int length = 0;
  unsigned char* png =
      stbi_write_png_to_mem(last_row, -stride, image.width, image.height, 4, &length);
  if (png == nullptr) return false;
  const bool ok =
      writeOutputFile(path, std::string(reinterpret_cast<char*>(png), static_cast<size_t>(length)));
  std::free(png);  // stb allocates with malloc
  return ok;
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
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return false;
  if (std::filesystem::exists(path, ec)) return access(path.c_str(), W_OK) == 0;
  const auto parent = std::filesystem::absolute(path).parent_path();
  return std::filesystem::is_directory(parent, ec) && access(parent.c_str(), W_OK) == 0;
}

}  // namespace shadows
