// OutputFile: regular files replaced atomically, symlinks followed, errors that say why.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "nckit/core/output_file.hpp"

namespace nckit {
namespace {

namespace fs = std::filesystem;

struct TempDir {
    TempDir() {
        std::string pattern = (fs::temp_directory_path() / "nckit-output-XXXXXX").string();
        path = ::mkdtemp(pattern.data());
    }
    ~TempDir() { fs::remove_all(path); }
    fs::path path;
};

std::string read(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(OutputFile, ReplacesARegularFileKeepingItsPermissionsAndLeavesNoPartial) {
    TempDir dir;
    const fs::path file = dir.path / "out.txt";
    std::ofstream(file) << "old";
    ::chmod(file.c_str(), 0640);
    ASSERT_FALSE(write_file_atomically(file, "new"));
    EXPECT_EQ(read(file), "new");
    struct stat status {};
    ASSERT_EQ(::stat(file.c_str(), &status), 0);
    EXPECT_EQ(status.st_mode & 0777, 0640u);
    EXPECT_FALSE(fs::exists(dir.path / "out.txt.partial"));
}

TEST(OutputFile, AnUncommittedOutputLeavesTheOldFileAndRemovesItsPartial) {
    TempDir dir;
    const fs::path file = dir.path / "out.txt";
    std::ofstream(file) << "old";
    {
        auto opened = OutputFile::open(file.string());
        ASSERT_TRUE(std::holds_alternative<OutputFile>(opened));
        std::get<OutputFile>(opened).write("half");
        EXPECT_TRUE(fs::exists(dir.path / "out.txt.partial"));
    }
    EXPECT_EQ(read(file), "old");
    EXPECT_FALSE(fs::exists(dir.path / "out.txt.partial"));
}

TEST(OutputFile, AStalePartialIsNeverReadNorFollowed) {
    TempDir dir;
    const fs::path file = dir.path / "out.txt";
    const fs::path victim = dir.path / "victim.txt";
    std::ofstream(victim) << "keep";
    fs::create_symlink(victim, dir.path / "out.txt.partial");  // left by someone else
    ASSERT_FALSE(write_file_atomically(file, "new"));
    EXPECT_EQ(read(file), "new");
    EXPECT_EQ(read(victim), "keep");
}

TEST(OutputFile, ASymlinkIsFollowedAndItsTargetReplaced) {
    TempDir dir;
    const fs::path target = dir.path / "real.txt";
    const fs::path link = dir.path / "link.txt";
    std::ofstream(target) << "old";
    fs::create_symlink("real.txt", link);
    ASSERT_FALSE(write_file_atomically(link, "new"));
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(read(target), "new");
}

TEST(OutputFile, ErrorsSayWhy) {
    TempDir dir;
    auto missing = write_file_atomically(dir.path / "no" / "out.txt", "x");
    ASSERT_TRUE(missing);
    EXPECT_EQ(missing->reason, "No such file or directory");
    EXPECT_NE(missing->message().find("folder '" + (dir.path / "no").string() + "' does not exist"), std::string::npos);
    auto folder = write_file_atomically(dir.path, "x");
    ASSERT_TRUE(folder);
    EXPECT_EQ(folder->reason, "Is a directory");
    EXPECT_FALSE(fs::exists(dir.path.string() + ".partial"));
}

}  // namespace
}  // namespace nckit
