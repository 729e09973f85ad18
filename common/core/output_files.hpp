// Where a run's outputs go, and writing them all or none, without ever replacing what was not
// ours: a link is written through, a device or pipe is written in place, a file that is our
// standard output is written to the stream, and only regular files are replaced (atomically).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace shadows {

struct OutputTarget {
  enum class Kind {
    Replace,  // a regular file of ours (new, or ours with one name): temporary, then rename
    InPlace,  // a device or pipe (/dev/null, a FIFO), or a regular file that is not ours alone
              // (another owner, other hard links, a directory we cannot add to): written in
              // place, not atomically
    Stream,   // the file or pipe that is already our standard output or error
  };
  Kind kind = Kind::Replace;
  std::string path;               // Replace: absolute, with links and ".." resolved; else as given
  std::string identity;           // two outputs with the same identity are one file
  bool character_device = false;  // may be shared by several outputs (/dev/null)
  int stream_fd = -1;             // Stream: 1 or 2

  // Whether two outputs would land in one file (only a character device such as /dev/null
  // may take several).
  bool sameFileAs(const OutputTarget& other) const {
    return !identity.empty() && identity == other.identity && !character_device;
  }
};

// Resolves `path` for writing: "" and `target` set, or one line saying why it cannot be an
// output (a directory, a missing or read-only directory, a name over 255 bytes, a place that
// takes no files such as /proc, a link loop). Creates nothing that stays: a new file's
// directory is checked by creating and removing a temporary in it.
std::string resolveOutput(const std::string& path, OutputTarget& target);

// Whether what is written to `path` is thrown away (it is /dev/null, by any name): a run
// need not encode an output nobody keeps.
bool discardsWhatIsWritten(const std::string& path);

// Writes one output (a screenshot): the same rules as a batch of one.
bool writeOutputFile(const std::string& path, const std::string& bytes);

// Several outputs of one run, written all or nothing: regular files go first to a temporary
// of a short unique name in their directory (never a user's file, never a name over 255
// bytes), devices, pipes and our own stdout are written next, and only when every one
// succeeded are the temporaries renamed. On failure the temporaries are removed and failure()
// says which file and why, on one line.
class OutputBatch {
 public:
  void add(const std::string& path, std::string bytes);
  bool commit();
  const std::string& failure() const { return failure_; }

 private:
  std::vector<std::pair<std::string, std::string>> files_;
  std::string failure_;
};

}  // namespace shadows
