#include "core/output_files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "core/text.hpp"

namespace shadows {

namespace {

namespace fs = std::filesystem;

constexpr size_t kMaxName = 255;   // NAME_MAX of the file systems we write to
constexpr size_t kMaxPath = 4095;  // PATH_MAX less the terminating zero
constexpr int kMaxLinks = 40;      // as the kernel's own limit (ELOOP)

std::string identityOf(const struct stat& st) {
  return "inode:" + std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino);
}

// Our standard output or error, when `st` is the very file or pipe it writes to.
int streamOf(const struct stat& st) {
  for (const int fd : {STDOUT_FILENO, STDERR_FILENO}) {
    struct stat own {};
    if (fstat(fd, &own) == 0 && own.st_dev == st.st_dev && own.st_ino == st.st_ino) return fd;
  }
  return -1;
}

// A new file of a short, unique name in `directory` (O_EXCL: never someone's file), or -1.
int createTemporary(const std::string& directory, std::string& name) {
  name = directory + "/.shadows-XXXXXX";
  return mkstemp(name.data());
}

// Whether a file can be created in `directory`: asked of the file system itself, since
// access() says yes to root for /proc and /sys.
bool canCreateIn(const std::string& directory) {
  std::string name;
  const int fd = createTemporary(directory, name);
  if (fd < 0) return false;
  close(fd);
  unlink(name.c_str());
  return true;
}

bool writeAll(int fd, const std::string& bytes) {
  for (size_t done = 0; done < bytes.size();) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

// The file a name that does not exist (yet) stands for: its directory's real path and, when
// the name is a dangling link, the file the link points to, followed to its end.
std::string resolveNew(std::string path, std::string& why) {
  for (int hops = 0; hops < kMaxLinks; ++hops) {
    std::error_code ec;
    const fs::path whole = fs::absolute(path, ec);
    const std::string name = whole.filename().string();
    if (name.empty() || name == "." || name == "..") {
      why = "it is a directory";
      return {};
    }
    if (name.size() > kMaxName) {
      why = "file name too long";
      return {};
    }
    const fs::path directory = fs::canonical(whole.parent_path(), ec);
    if (ec || !fs::is_directory(directory, ec)) {
      why = "no such directory";
      return {};
    }
    const fs::path candidate = directory / name;
    struct stat st {};
    if (lstat(candidate.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return candidate.string();
    const fs::path target = fs::read_symlink(candidate, ec);
    if (ec) {
      why = ec.message();
      return {};
    }
    path = target.is_absolute() ? target.string() : (directory / target).string();
  }
  why = "too many levels of symbolic links";
  return {};
}

}  // namespace

bool discardsWhatIsWritten(const std::string& path) {
  struct stat st {
  }, null{};
  return !path.empty() && stat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode) &&
         stat("/dev/null", &null) == 0 && st.st_rdev == null.st_rdev;
}

std::string resolveOutput(const std::string& path, OutputTarget& target) {
  target = {};
  if (path.empty()) return "no file name";
  if (path.size() > kMaxPath || fs::path(path).filename().string().size() > kMaxName) {
    return "file name too long";
  }
  struct stat st {};
  if (stat(path.c_str(), &st) == 0) {  // exists, links followed
    if (S_ISDIR(st.st_mode)) return "it is a directory";
    if (S_ISSOCK(st.st_mode)) return "it is a socket";
    target.identity = identityOf(st);
    target.character_device = S_ISCHR(st.st_mode);
    if (const int fd = streamOf(st); fd >= 0) {
      target.kind = OutputTarget::Kind::Stream;
      target.stream_fd = fd;
      target.path = path;
      return {};
    }
    if (access(path.c_str(), W_OK) != 0) return "not writable";
    if (!S_ISREG(st.st_mode)) {
      target.kind = OutputTarget::Kind::InPlace;
      target.path = path;
      return {};
    }
    std::error_code ec;
    const fs::path real = fs::canonical(path, ec);
    if (ec) return ec.message();
    target.path = real.string();
    // Replacing swaps the inode: fine for a file of ours with one name. A file someone else
    // owns (its owner, ACLs, a sticky /tmp that refuses the rename), one with other hard
    // links (they would keep the old bytes), or one in a directory we may not add to is
    // rewritten where it is instead.
    const bool ours = st.st_uid == geteuid() && st.st_nlink == 1;
    target.kind = ours && canCreateIn(real.parent_path().string()) ? OutputTarget::Kind::Replace
                                                                   : OutputTarget::Kind::InPlace;
    return {};
  }
  if (errno != ENOENT) return std::strerror(errno);
  std::string why;
  const std::string real = resolveNew(path, why);
  if (real.empty()) return why;
  if (!canCreateIn(fs::path(real).parent_path().string())) {
    return "cannot create files in its directory";
  }
  target.kind = OutputTarget::Kind::Replace;
  target.path = real;
  target.identity = "path:" + real;
  return {};
}

void OutputBatch::add(const std::string& path, std::string bytes) {
  files_.emplace_back(path, std::move(bytes));
}

bool OutputBatch::commit() {
  const size_t n = files_.size();
  std::vector<OutputTarget> targets(n);
  std::vector<std::string> temporaries(n);  // "" where the output is written where it is
  auto fail = [&](size_t i, const std::string& why) {
    for (const std::string& t : temporaries) {
      if (!t.empty()) unlink(t.c_str());
    }
    failure_ = "cannot write " + printable(files_[i].first) + " (" + why + ")";
    return false;
  };
  const mode_t mask = umask(0);
  umask(mask);
  // Regular files first, into temporaries: nothing the user sees changes until all succeed.
  for (size_t i = 0; i < n; ++i) {
    const auto& [path, bytes] = files_[i];
    if (bytes.empty()) return fail(i, "nothing to write");
    if (std::string why = resolveOutput(path, targets[i]); !why.empty()) return fail(i, why);
    for (size_t j = 0; j < i; ++j) {
      if (targets[i].sameFileAs(targets[j])) {
        return fail(i, "the same file as " + printable(files_[j].first));
      }
    }
    if (targets[i].kind != OutputTarget::Kind::Replace) continue;
    struct stat existing {};
    const mode_t mode = stat(targets[i].path.c_str(), &existing) == 0
                            ? existing.st_mode & 07777
                            : static_cast<mode_t>(0666 & ~mask);
    const int fd =
        createTemporary(fs::path(targets[i].path).parent_path().string(), temporaries[i]);
    if (fd < 0) {
      temporaries[i].clear();
      return fail(i, std::strerror(errno));
    }
    bool ok = writeAll(fd, bytes) && fchmod(fd, mode) == 0;
    const int saved = errno;
    ok = close(fd) == 0 && ok;
    if (!ok) return fail(i, std::strerror(saved != 0 ? saved : errno));
  }
  // Then what is written where it stands: devices, pipes, our own standard output.
  for (size_t i = 0; i < n; ++i) {
    const OutputTarget& t = targets[i];
    const std::string& bytes = files_[i].second;
    errno = 0;
    if (t.kind == OutputTarget::Kind::Stream) {
      std::FILE* stream = t.stream_fd == STDOUT_FILENO ? stdout : stderr;
      if (std::fwrite(bytes.data(), 1, bytes.size(), stream) != bytes.size() ||
          std::fflush(stream) != 0) {
        return fail(i, errno != 0 ? std::strerror(errno) : "write failed");
      }
    } else if (t.kind == OutputTarget::Kind::InPlace) {
      // Non-blocking open: a FIFO nobody reads is "no reader", not a hang. A regular file is
      // not truncated before the bytes are in (a full disk leaves the old content, not none).
      const int fd = open(t.path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
      if (fd < 0) return fail(i, errno == ENXIO ? "no reader on the pipe" : std::strerror(errno));
      bool ok = fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK) == 0 && writeAll(fd, bytes);
      struct stat written {};
      if (ok && fstat(fd, &written) == 0 && S_ISREG(written.st_mode)) {
        ok = ftruncate(fd, static_cast<off_t>(bytes.size())) == 0;
      }
      const int saved = errno;
      ok = close(fd) == 0 && ok;
      if (!ok) return fail(i, std::strerror(saved != 0 ? saved : errno));
    }
  }
  for (size_t i = 0; i < n; ++i) {
    if (temporaries[i].empty()) continue;
    if (std::rename(temporaries[i].c_str(), targets[i].path.c_str()) != 0) {
      return fail(i, std::strerror(errno));
    }
    temporaries[i].clear();
  }
  return true;
}

bool writeOutputFile(const std::string& path, const std::string& bytes) {
  OutputBatch batch;
  batch.add(path, bytes);
  return batch.commit();
}

}  // namespace shadows
