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
// Throws std::runtime_error naming the file when it is missing or not a PNG (other formats
// stb could read are refused: the parameters and the help say PNG).
Image readPng(const std::string& path);
// The PNG bytes of an image ("" if it cannot be encoded).
std::string encodePng(const Image& image);

// Several outputs of one run, written all or nothing: each goes first to a temporary next to
// its final name (a device such as /dev/null is written in place), and only when every one
// succeeded are the temporaries renamed. On failure the temporaries are removed and
// failure() says which file and why, on one line.
class OutputBatch {
 public:
  void add(const std::string& path, std::string bytes);
  bool commit();
  const std::string& failure() const { return failure_; }

 private:
  std::vector<std::pair<std::string, std::string>> files_;
  std::string failure_;
};

// The `check` of an image parameter: "" for "builtin" or a PNG that loads (at most 8192
// pixels a side), else one line saying what is accepted or what is wrong with the file.
std::string checkPngParam(const std::string& value);

// `text` with control characters (a newline in a file name, say) written as escapes, so a
// message stays on one line.
std::string printable(const std::string& text);
// True when `path` can be written: an existing non-directory we may write to, or a new file
// in a directory that exists and is writable.
bool canWrite(const std::string& path);

}  // namespace shadows
