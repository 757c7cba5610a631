#include "core/AtomicFile.h"

#include <gtest/gtest.h>

#include "support/TemporaryFolder.h"

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "core/Error.h"

namespace sphcast {
namespace {

namespace fs = std::filesystem;

using AtomicFileTest = testing::TemporaryFolderTest;

TEST_F(AtomicFileTest, WritesContentAndLeavesNoTemporaryFile) {
  const fs::path file = folder_ / "controlDict";
  const std::string content("binary\0content\n", 15);
  writeFileAtomically(file, content);
  EXPECT_EQ(testing::readWholeFile(file), content);
  EXPECT_FALSE(fs::exists(temporaryPathFor(file)));
}

TEST_F(AtomicFileTest, ReplacesExistingFileWhole) {
  const fs::path file = folder_ / "case.pvd";
  writeFileAtomically(file, std::string(100000, 'a'));
  writeFileAtomically(file, "short");
  EXPECT_EQ(testing::readWholeFile(file), "short");
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
