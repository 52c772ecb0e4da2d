#include "util/output_set.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace mirage {
namespace {

namespace fs = std::filesystem;

class OutputSetTest : public ::testing::Test {
  protected:
    fs::path dir_ =
        fs::path(::testing::TempDir()) / ("mirage_outputs_" + std::to_string(::getpid()));
    void SetUp() override { fs::create_directories(dir_); }
    void TearDown() override {
        fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add);
        fs::remove_all(dir_);
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    void write(const std::string& name, const std::string& text) const {
        std::ofstream(dir_ / name) << text;
    }
    std::string read(const std::string& name) const {
        std::ifstream in(dir_ / name);
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    }
    int files() const {
        int n = 0;
        for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++n;
        return n;
    }
};

TEST_F(OutputSetTest, NothingIsInPlaceBeforeTheCommitAndEverythingAfter) {
    write("b.txt", "old b");
    OutputSet out;
    ASSERT_TRUE(out.write_text(path("a.txt"), "new a").ok());
    ASSERT_TRUE(out.write_text(path("b.txt"), "new b").ok());
    EXPECT_FALSE(fs::exists(path("a.txt")));
    EXPECT_EQ(read("b.txt"), "old b");
    ASSERT_TRUE(out.commit().ok());
    EXPECT_EQ(read("a.txt"), "new a");
    EXPECT_EQ(read("b.txt"), "new b");
    EXPECT_EQ(files(), 2);  // no temporary or second name left behind
}

TEST_F(OutputSetTest, AnInputIsNeverAnOutput) {
    write("scene.pov", "sphere { 0, 1 }");
    fs::create_symlink(path("scene.pov"), path("link.pov"));
    OutputSet out({path("scene.pov")});
    EXPECT_EQ(out.write_text(path("scene.pov"), "x").message(),
              path("scene.pov") +
                  ": the output would overwrite an input of this command (the scene or a file it "
                  "includes)");
    // Through a link or another spelling of the path too.
    EXPECT_FALSE(out.check(path("link.pov")).ok());
    EXPECT_FALSE(out.check((dir_ / "." / "scene.pov").string()).ok());
    // Two outputs of one name, and a directory.
    ASSERT_TRUE(out.stage(path("x.png")).ok());
    EXPECT_EQ(out.check(path("x.png")).message(),
              path("x.png") + ": named for two outputs of this command");
    EXPECT_EQ(out.check(dir_.string()).message(),
              dir_.string() + ": is a directory; an output must be a file");
    EXPECT_EQ(read("scene.pov"), "sphere { 0, 1 }");
}

TEST_F(OutputSetTest, AFailedRenameUndoesTheOnesBefore) {
    write("a.txt", "old a");
    {
        OutputSet out;
        ASSERT_TRUE(out.write_text(path("a.txt"), "new a").ok());
        ASSERT_TRUE(out.write_text(path("new.txt"), "new").ok());
        ASSERT_TRUE(out.write_text(path("c.txt"), "new c").ok());
        // The last one's temporary vanishes: its rename fails after the first two were done.
        const auto staged = out.targets();
        ASSERT_EQ(staged.size(), 3u);
        for (const auto& e : fs::directory_iterator(dir_))
            if (e.path().filename().string().rfind(".c.tmp", 0) == 0) fs::remove(e.path());
        auto s = out.commit();
        ASSERT_FALSE(s.ok());
        EXPECT_NE(s.message().find(path("c.txt") + ": cannot write: "), std::string::npos)
            << s.message();
        EXPECT_NE(s.message().find("(no output of this command was changed)"), std::string::npos);
    }
    EXPECT_EQ(read("a.txt"), "old a");
    EXPECT_FALSE(fs::exists(path("new.txt")));
    EXPECT_FALSE(fs::exists(path("c.txt")));
    EXPECT_EQ(files(), 1);
}

TEST_F(OutputSetTest, AnUncommittedSetLeavesNothing) {
    {
        OutputSet out;
        ASSERT_TRUE(out.write_text(path("a.txt"), "a").ok());
    }
    EXPECT_EQ(files(), 0);
    // A directory that cannot be written: the message names the file and the reason.
    fs::permissions(dir_, fs::perms::owner_write, fs::perm_options::remove);
    if (::geteuid() != 0) {  // root writes anyway
        OutputSet out;
        auto s = out.write_text(path("a.txt"), "a");
        EXPECT_EQ(s.message(), path("a.txt") + ": cannot write: Permission denied");
    }
}

}  // namespace
}  // namespace mirage
