#include "core/image.hpp"

#include <fcntl.h>
#include <stb_image.h>
#include <stb_image_write.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <system_error>

// libstb exports this, but its header declares it only in the implementation section.
extern "C" unsigned char* stbi_write_png_to_mem(const unsigned char* pixels, int stride_bytes,
                                                int x, int y, int n, int* out_len);

namespace shadows {

namespace {

// What stb says went wrong, or a plain word when it says nothing.
std::string reason() {
  const char* why = stbi_failure_reason();
  return why != nullptr && *why != '\0' ? why : "corrupt or truncated";
}

}  // namespace

std::string encodePng(const Image& image) {
  if (image.width <= 0 || image.height <= 0) return {};
  const int stride = image.width * 4;
  // stb writes top-down; start at the last GL row and walk backwards.
  const auto* last_row = image.rgba.data() + static_cast<size_t>(stride) * (image.height - 1);
  int length = 0;
  unsigned char* png =
      stbi_write_png_to_mem(last_row, -stride, image.width, image.height, 4, &length);
  if (png == nullptr) return {};
  std::string bytes(reinterpret_cast<char*>(png), static_cast<size_t>(length));
  std::free(png);  // stb allocates with malloc
  return bytes;
}

bool writePng(const std::string& path, const Image& image) {
  const std::string bytes = encodePng(image);
  return !bytes.empty() && writeOutputFile(path, bytes);
}

std::string checkPngParam(const std::string& value) {
  if (value == "builtin") return {};
  if (value.empty()) return "expected 'builtin' or the path of a PNG file";
  try {
    readPng(value);
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

Image readPng(const std::string& path) {
  auto refuse = [&](const std::string& why) {
    return std::runtime_error(printable(path) + ": " + why);
  };
  // Non-blocking, then a look at what was opened: a FIFO or a device is refused before a
  // byte is read from it, so no input can hang the run.
  const int fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw refuse(std::string("cannot open (") + std::strerror(errno) + ")");
  struct stat st {};
  if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    close(fd);
    throw refuse("not a regular file");
  }
  std::FILE* in = fdopen(fd, "rb");
  if (in == nullptr) {
    close(fd);
    throw refuse(std::string("cannot open (") + std::strerror(errno) + ")");
  }
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> closer(in, &std::fclose);
  // stb reads BMP, JPEG, ... too; the contract is PNG, so look at the signature first.
  unsigned char signature[8] = {};
  static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (std::fread(signature, 1, 8, in) != 8 || !std::equal(signature, signature + 8, kPng)) {
    throw refuse("not a PNG file");
  }
  // The size from the header, before anything is decoded: a small file may declare a huge
  // picture.
  std::rewind(in);
  int w = 0, h = 0, channels = 0;
  if (stbi_info_from_file(in, &w, &h, &channels) == 0) {
    throw refuse("not a readable PNG (" + reason() + ")");
  }
  if (w > kMaxImageSide || h > kMaxImageSide) {
    throw refuse(std::to_string(w) + "x" + std::to_string(h) + " is larger than " +
                 std::to_string(kMaxImageSide) + " a side");
  }
  std::rewind(in);
  stbi_uc* pixels = stbi_load_from_file(in, &w, &h, &channels, 4);
  if (pixels == nullptr) throw refuse("cannot read image (" + reason() + ")");
  Image image{w, h, std::vector<std::uint8_t>(static_cast<size_t>(w) * h * 4)};
  for (int y = 0; y < h; ++y) {
    std::copy_n(pixels + static_cast<size_t>(h - 1 - y) * w * 4, w * 4,
                image.rgba.begin() + static_cast<std::ptrdiff_t>(y) * w * 4);
  }
  stbi_image_free(pixels);
  return image;
}

}  // namespace shadows
