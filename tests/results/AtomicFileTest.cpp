#include "results/AtomicFile.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace dropscope {
namespace {

namespace fs = std::filesystem;

class AtomicFile : public ::testing::Test {
protected:
    void SetUp() override {
        directory_ =
            fs::temp_directory_path() /
            ("dropscope-atomic-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(directory_);
        fs::create_directories(directory_);
    }
    void TearDown() override { fs::remove_all(directory_); }
    fs::path path(const std::string& name) const { return directory_ / name; }
    static std::string read(const fs::path& file) {
        std::ifstream in(file);
        std::stringstream text;
        text << in.rdbuf();
        return text.str();
    }
    std::size_t entries() const {
        return static_cast<std::size_t>(std::distance(fs::directory_iterator(directory_), fs::directory_iterator()));
    }

    fs::path directory_;
};

TEST_F(AtomicFile, WritesEveryFileOfASet) {
    writeFilesAtomically({{path("a"), [](std::ostream& out) { out << "alpha"; }},
                          {path("b"), [](std::ostream& out) { out << "beta"; }}});
    EXPECT_EQ(read(path("a")), "alpha");
    EXPECT_EQ(read(path("b")), "beta");
    EXPECT_EQ(entries(), 2U);
}

TEST_F(AtomicFile, AFailureInAnyFileLeavesEveryTargetAsItWasAndNoTemporaries) {
    std::ofstream(path("a")) << "old a";
    std::ofstream(path("b")) << "old b";
    EXPECT_THROW(writeFilesAtomically({{path("a"), [](std::ostream& out) { out << "new a"; }},
                                       {path("b"), [](std::ostream&) { throw std::runtime_error("b failed"); }}}),
                 std::runtime_error);
    EXPECT_EQ(read(path("a")), "old a");
    EXPECT_EQ(read(path("b")), "old b");
    EXPECT_EQ(entries(), 2U);
}

TEST_F(AtomicFile, ATargetThatIsAFolderIsRefusedBeforeAnythingIsReplaced) {
    std::ofstream(path("a")) << "old a";
    fs::create_directory(path("b"));
    try {
        writeFilesAtomically({{path("a"), [](std::ostream& out) { out << "new a"; }},
                              {path("b"), [](std::ostream& out) { out << "new b"; }}});
        FAIL() << "expected an error";
    } catch (const std::runtime_error& error) {
        EXPECT_EQ(std::string(error.what()), path("b").string() + ": exists and is not a regular file");
    }
    EXPECT_EQ(read(path("a")), "old a");
    EXPECT_EQ(entries(), 2U);
}

}  // namespace
}  // namespace dropscope
