#include "image.hpp"

#include <stb_image.h>
#include <stb_image_write.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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

std::string printable(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      out += '?';
    } else {
      out += c;
    }
  }
  return out;
}

void OutputBatch::add(const std::string& path, std::string bytes) {
  files_.emplace_back(path, std::move(bytes));
}

bool OutputBatch::commit() {
  std::vector<std::string> temporaries;  // parallel to files_, "" for devices
  auto fail = [&](const std::string& path, const std::string& why) {
    for (const std::string& t : temporaries) {
      if (!t.empty()) std::remove(t.c_str());
    }
    failure_ = "cannot write " + printable(path) + " (" + why + ")";
    return false;
  };
  for (const auto& [path, bytes] : files_) {
    if (bytes.empty()) return fail(path, "nothing to write");
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    const bool device =
        std::filesystem::exists(status) && !std::filesystem::is_regular_file(status);
    const std::string target = device ? path : path + ".partial";
    errno = 0;
    std::FILE* out = std::fopen(target.c_str(), "wb");
    bool ok = out != nullptr;
    if (ok) ok = std::fwrite(bytes.data(), 1, bytes.size(), out) == bytes.size();
    if (out != nullptr) ok = (std::fclose(out) == 0) && ok;
    const std::string why = errno != 0 ? std::strerror(errno) : "write failed";
    temporaries.push_back(device ? std::string() : target);
    if (!ok) return fail(path, why);
  }
  for (size_t i = 0; i < files_.size(); ++i) {
    if (temporaries[i].empty()) continue;
    std::error_code ec;
    std::filesystem::rename(temporaries[i], files_[i].first, ec);
    if (ec) return fail(files_[i].first, ec.message());
  }
  return true;
}

std::string checkPngParam(const std::string& value) {
  if (value == "builtin") return {};
  if (value.empty()) return "expected 'builtin' or the path of a PNG file";
  try {
    const Image loaded = readPng(value);
    if (loaded.width > 8192 || loaded.height > 8192) return printable(value) + ": larger than 8192";
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

Image readPng(const std::string& path) {
  // stb reads BMP, JPEG, ... too; the contract is PNG, so look at the signature first.
  {
    unsigned char signature[8] = {};
    std::FILE* in = std::fopen(path.c_str(), "rb");
    const size_t got = in != nullptr ? std::fread(signature, 1, 8, in) : 0;
    if (in != nullptr) std::fclose(in);
    static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (in == nullptr) {
      throw std::runtime_error(printable(path) + ": cannot open (" + std::strerror(errno) + ")");
    }
    if (got != 8 || !std::equal(signature, signature + 8, kPng)) {
      throw std::runtime_error(printable(path) + ": not a PNG file");
    }
  }
  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (pixels == nullptr) {
    throw std::runtime_error(printable(path) + ": cannot read image (" + stbi_failure_reason() +
                             ")");
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
