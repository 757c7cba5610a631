#include "core/AtomicFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "core/Error.h"

namespace sphcast {
namespace {

namespace fs = std::filesystem;

// A fresh folder per test, removed afterwards.
class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ = fs::temp_directory_path() / ("sphCastAtomicFileTest_" + std::string(info->name()) +
                                           "_" + std::to_string(std::random_device{}()));
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  static std::string readWhole(const fs::path& file) {
    // (not istreambuf_iterator: g++ 12 gives a false -Wnull-dereference for it)
    std::ifstream in(file, std::ios::binary | std::ios::ate);
    std::string content(static_cast<std::size_t>(in.tellg()), '\0');
    in.seekg(0);
    in.read(content.data(), static_cast<std::streamsize>(content.size()));
    return content;
  }

  fs::path folder_;
};

TEST_F(AtomicFileTest, WritesContentAndLeavesNoTemporaryFile) {
  const fs::path file = folder_ / "controlDict";
  const std::string content("binary\0content\n", 15);
  writeFileAtomically(file, content);
  EXPECT_EQ(readWhole(file), content);
  EXPECT_FALSE(fs::exists(temporaryPathFor(file)));
}

TEST_F(AtomicFileTest, ReplacesExistingFileWhole) {
  const fs::path file = folder_ / "case.pvd";
  writeFileAtomically(file, std::string(100000, 'a'));
  writeFileAtomically(file, "short");
  EXPECT_EQ(readWhole(file), "short");
}

TEST_F(AtomicFileTest, WritesEmptyFile) {
  const fs::path file = folder_ / "empty";
  writeFileAtomically(file, "");
  EXPECT_TRUE(fs::exists(file));
  EXPECT_EQ(fs::file_size(file), 0u);
}

TEST_F(AtomicFileTest, MissingFolderIsAnErrorNamingTheFile) {
  const fs::path file = folder_ / "noSuchFolder" / "metal.vtp";
  try {
    writeFileAtomically(file, "x");
    FAIL() << "no Error thrown";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
  }
  EXPECT_FALSE(fs::exists(file));
}

TEST_F(AtomicFileTest, RenameOfMissingFileIsAnErrorNamingBothFiles) {
  const fs::path from = folder_ / "absent.tmp";
  const fs::path to = folder_ / "absent";
  try {
    renameAtomically(from, to);
    FAIL() << "no Error thrown";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(from.string()), std::string::npos) << message;
    EXPECT_NE(message.find(to.string()), std::string::npos) << message;
  }
}

TEST_F(AtomicFileTest, SyncOfMissingFileIsAnErrorNamingTheFile) {
  const fs::path file = folder_ / "absent";
  try {
    syncFileToDisk(file);
    FAIL() << "no Error thrown";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos);
  }
}

}  // namespace
}  // namespace sphcast
