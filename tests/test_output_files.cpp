// Where outputs go: links written through, devices in place, regular files replaced
// atomically, the same file recognized however it is named, and temporaries that never
// collide with a user's file or outgrow the file system's name limit.
#include "core/output_files.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace shadows {
namespace {

namespace fs = std::filesystem;

class OutputFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("shadows_outputs_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "sub");
  }
  void TearDown() override { fs::remove_all(dir); }
  static std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::string resolve(const std::string& path) {
    OutputTarget t;
    EXPECT_EQ(resolveOutput(path, t), "") << path;
    return t.identity;
  }
  fs::path dir;
};

TEST_F(OutputFiles, ALinkIsWrittenThroughAndStaysALink) {
  std::ofstream(dir / "real.json") << "old";
  fs::create_symlink("real.json", dir / "link.json");
  ASSERT_TRUE(writeOutputFile((dir / "link.json").string(), "new"));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "link.json")));
  EXPECT_EQ(read(dir / "real.json"), "new");
}

TEST_F(OutputFiles, ADanglingLinkCreatesItsTarget) {
  fs::create_symlink("sub/made.png", dir / "dangling.png");
  ASSERT_TRUE(writeOutputFile((dir / "dangling.png").string(), "png"));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "dangling.png")));
  EXPECT_EQ(read(dir / "sub" / "made.png"), "png");
}

TEST_F(OutputFiles, ADeviceIsWrittenInPlace) {
  OutputTarget t;
  ASSERT_EQ(resolveOutput("/dev/null", t), "");
  EXPECT_EQ(t.kind, OutputTarget::Kind::InPlace);
  EXPECT_TRUE(t.character_device);
  ASSERT_TRUE(writeOutputFile("/dev/null", "bytes"));
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

// A picture for /dev/null is not encoded; for anything else, devices included, it is.
TEST_F(OutputFiles, OnlyDevNullByAnyNameDiscardsWhatIsWritten) {
  fs::create_symlink("/dev/null", dir / "null.png");
  std::ofstream(dir / "file.png") << "x";
  EXPECT_TRUE(discardsWhatIsWritten("/dev/null"));
  EXPECT_TRUE(discardsWhatIsWritten((dir / "null.png").string()));
  EXPECT_FALSE(discardsWhatIsWritten((dir / "file.png").string()));
  EXPECT_FALSE(discardsWhatIsWritten((dir / "new.png").string()));
  EXPECT_FALSE(discardsWhatIsWritten("/dev/zero"));
  EXPECT_FALSE(discardsWhatIsWritten(""));
}

TEST_F(OutputFiles, OneFileHasOneIdentityHoweverItIsNamed) {
  const std::string a = (dir / "a.png").string();
  const std::string fresh = resolve(a);
  EXPECT_EQ(resolve((dir / "." / "a.png").string()), fresh);
  EXPECT_EQ(resolve((dir / "sub" / ".." / "a.png").string()), fresh);
  fs::create_symlink("a.png", dir / "link.png");  // dangling until a.png exists
  EXPECT_EQ(resolve((dir / "link.png").string()), fresh);
  std::ofstream(a) << "x";
  const std::string existing = resolve(a);
  EXPECT_EQ(resolve((dir / "link.png").string()), existing);
  fs::create_hard_link(a, dir / "hard.png");
  EXPECT_EQ(resolve((dir / "hard.png").string()), existing);
  EXPECT_NE(resolve((dir / "b.png").string()), existing);
}

TEST_F(OutputFiles, TemporariesNeitherCollideNorOutgrowTheNameLimit) {
  // A user's file and a directory where a naive "<name>.partial" would go stay untouched.
  std::ofstream(dir / "o.png.partial") << "someone's";
  fs::create_directories(dir / "p.png.partial");
  ASSERT_TRUE(writeOutputFile((dir / "o.png").string(), "o"));
  ASSERT_TRUE(writeOutputFile((dir / "p.png").string(), "p"));
  EXPECT_EQ(read(dir / "o.png.partial"), "someone's");
  EXPECT_TRUE(fs::is_directory(dir / "p.png.partial"));
  // The longest name the file system takes works; one byte more is refused up front.
  const std::string longest = std::string(251, 'n') + ".png";
  ASSERT_TRUE(writeOutputFile((dir / longest).string(), "n"));
  EXPECT_EQ(read(dir / longest), "n");
  OutputTarget t;
  EXPECT_EQ(resolveOutput((dir / ("n" + longest)).string(), t), "file name too long");
  // Nothing else is left behind.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 6);
}

TEST_F(OutputFiles, AReplacedFileKeepsItsMode) {
  const fs::path p = dir / "r.json";
  std::ofstream(p) << "old";
  fs::permissions(p, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  ASSERT_TRUE(writeOutputFile(p.string(), "new"));
  EXPECT_EQ(fs::status(p).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

TEST_F(OutputFiles, PlacesThatTakeNoFilesAreRefusedUpFront) {
  OutputTarget t;
  // access() says yes to root there; the check asks the file system itself.
  EXPECT_NE(resolveOutput("/proc/x.png", t), "");
  EXPECT_NE(resolveOutput("/sys/x.png", t), "");
  EXPECT_NE(resolveOutput((dir / "missing" / "x.png").string(), t), "");
  EXPECT_EQ(resolveOutput(dir.string(), t), "it is a directory");
  EXPECT_EQ(resolveOutput((dir / "sub" / "..").string(), t), "it is a directory");
}

TEST_F(OutputFiles, AFailedBatchLeavesNoTemporaryAndChangesNothing) {
  std::ofstream(dir / "kept.png") << "before";
  // A failure in every phase: writing a device (after the temporaries were made), and a
  // file whose directory went away before the commit.
  for (const std::string& failing : {std::string("/dev/full"), (dir / "gone" / "x.png").string()}) {
    OutputBatch batch;
    batch.add((dir / "kept.png").string(), "after");
    batch.add((dir / "new.json").string(), "{}");
    batch.add(failing, "bytes");
    EXPECT_FALSE(batch.commit()) << failing;
    EXPECT_NE(batch.failure().find("cannot write " + failing), std::string::npos)
        << batch.failure();
    EXPECT_EQ(read(dir / "kept.png"), "before") << failing;
    EXPECT_FALSE(fs::exists(dir / "new.json")) << failing;
    // Only what was there: kept.png and sub/.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2) << failing;
  }
}

TEST_F(OutputFiles, ALinkLoopIsRefused) {
  fs::create_symlink("loop2.png", dir / "loop1.png");
  fs::create_symlink("loop1.png", dir / "loop2.png");
  OutputTarget t;
  EXPECT_NE(resolveOutput((dir / "loop1.png").string(), t), "");
}

}  // namespace
}  // namespace shadows
