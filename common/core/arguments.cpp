#include "core/arguments.hpp"

#include <filesystem>
#include <fstream>

#include <algorithm>

#include "core/text.hpp"

namespace shadows {

bool Arguments::value(std::string& out) {
  out.clear();
  if (i_ + 1 >= argc_) return false;
  out = argv_[++i_];
  return true;
}

bool parsePositive(const std::string& text, int& out, int max) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return false;
  // Leading zeros are the same number, for every flag ("00064", "00001").
  const std::string digits = text.substr(std::min(text.find_first_not_of('0'), text.size() - 1));
  if (digits.size() > 9) return false;
  const int n = std::stoi(digits);
  if (n < 1 || n > max) return false;
  out = n;
  return true;
}

std::string readCount(Arguments& args, int& out, int max) {
  std::string value;
  if (!args.value(value) || !parsePositive(value, out, max)) {
    return args.flag() + ": expected a whole number in 1.." + std::to_string(max) + ", got '" +
           value + "'";
  }
  return {};
}

std::string readIndex(Arguments& args, int& out, int max) {
  std::string value;
  const bool digits = args.value(value) && !value.empty() && value.size() <= 9 &&
                      value.find_first_not_of("0123456789") == std::string::npos;
  if (!digits || std::stoi(value) > max) {
    return args.flag() + ": expected a whole number in 0.." + std::to_string(max) + ", got '" +
           value + "'";
  }
  out = std::stoi(value);
  return {};
}

std::string readSize(Arguments& args, int& width, int& height, int minSide) {
  constexpr int kMaxSide = 8192;
  std::string value;
  const auto x = args.value(value) ? value.find('x') : std::string::npos;
  int w = 0, h = 0;
  if (x == std::string::npos || !parsePositive(value.substr(0, x), w, kMaxSide) ||
      !parsePositive(value.substr(x + 1), h, kMaxSide) || w < minSide || h < minSide) {
    return args.flag() + ": expected WxH with W and H in " + std::to_string(minSide) + ".." +
           std::to_string(kMaxSide) + ", got '" + value + "'";
  }
  width = w, height = h;
  return {};
}

std::string readSet(Arguments& args, std::vector<std::string>& sets) {
  std::string value;
  if (!args.value(value)) return args.flag() + ": expected name=value";
  // `--set --size 160x120`: the value is missing, not `160x120` unknown.
  if (isOption(value)) return args.flag() + ": expected name=value, got the option '" + value + "'";
  sets.push_back(value);
  return {};
}

std::string readFileName(Arguments& args, std::string& out) {
  if (!args.value(out)) return args.flag() + ": expected a file name";
  if (isOption(out)) return args.flag() + ": expected a file name, got the option '" + out + "'";
  return {};
}

bool isOption(const std::string& value) {
  return value.size() > 2 && value.rfind("--", 0) == 0;
}

std::string readSettingsFile(const std::string& path, std::vector<std::string>& sets) {
  // A settings file is a few lines of text: a regular file, not a folder or a device.
  constexpr std::uintmax_t kLargest = 1 << 20;
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status)) {
    return "--settings " + printable(path) + ": cannot read it";
  }
  if (!std::filesystem::is_regular_file(status)) {
    return "--settings " + printable(path) + ": not a file";
  }
  if (std::filesystem::file_size(path, error) > kLargest || error) {
    return "--settings " + printable(path) + ": larger than a settings file (1 MiB)";
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return "--settings " + printable(path) + ": cannot read it";
  std::vector<std::string> read;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // a UTF-8 BOM
    if (!line.empty() && line.back() == '\r') line.pop_back();                // written on Windows
    const size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] == '#') continue;
    line = line.substr(start, line.find_last_not_of(" \t") + 1 - start);
    // A parameter's name, '=', its value: anything else is not a settings file.
    const size_t eq = line.find('=');
    const bool named = eq != std::string::npos && eq > 0 &&
                       line.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_.") >= eq;
    if (!named) {
      return "--settings " + printable(path) + ":" + std::to_string(number) +
             ": not a setting (name=value): '" + printable(line.substr(0, 60)) + "'";
    }
    read.push_back(line);
  }
  if (in.bad()) return "--settings " + printable(path) + ": cannot read it";
  sets.insert(sets.end(), read.begin(), read.end());
  return {};
}

std::string unknownOption(const std::string& arg) {
  return "unknown option '" + printable(arg) + "'; see --help";
}

}  // namespace shadows
