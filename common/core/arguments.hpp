// The pieces of a command line every program here parses the same way: the lessons' runner
// (command_line.cpp) and bench_sweep. Each reader returns "" or the one line that says what is
// wrong (the caller exits 2), and leaves `out` alone when it is wrong.
#pragma once

#include <string>
#include <vector>

namespace shadows {

// argv after the program name, one flag at a time, and the value after a flag.
class Arguments {
 public:
  Arguments(int argc, char** argv) : argc_(argc), argv_(argv) {}
  // Moves to the next flag; false when there is none.
  bool next() {
    if (i_ + 1 >= argc_) return false;
    flag_ = argv_[++i_];
    return true;
  }
  const std::string& flag() const { return flag_; }
  // Takes the argument after the flag as its value; false (and `out` empty) at the end.
  bool value(std::string& out);

 private:
  int argc_;
  char** argv_;
  int i_ = 0;
  std::string flag_;
};

// A whole number in 1..max, digits only.
bool parsePositive(const std::string& text, int& out, int max);

// The flag's value as a whole number in 1..max:
// "--frames: expected a whole number in 1..100000, got '0'".
std::string readCount(Arguments& args, int& out, int max);

// The flag's value as an index in 0..max: "--device: expected a whole number in 0..63, got 'x'".
std::string readIndex(Arguments& args, int& out, int max);

// --size WxH, each side in minSide..8192.
std::string readSize(Arguments& args, int& width, int& height, int minSide = 1);

// --set name=value, appended to `sets` (checked later by Params::assign, which knows the names).
std::string readSet(Arguments& args, std::vector<std::string>& sets);
// A flag's file name (--out, --settings, ...): "" or the line saying it is missing.
std::string readFileName(Arguments& args, std::string& out);
// A flag's value that is itself an option (`--size`): the value was left out. A file of such a
// name is given as `./--name`.
bool isOption(const std::string& value);
// --settings FILE: one name=value a line (what the panel's "Save settings" writes; blank lines
// and lines starting with # are skipped), appended to `sets` in order. "" or one line naming
// the file (and line) and what is wrong.
std::string readSettingsFile(const std::string& path, std::vector<std::string>& sets);

// An argument no branch took.
std::string unknownOption(const std::string& arg);

}  // namespace shadows
