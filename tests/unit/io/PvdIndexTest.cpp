#include "io/PvdIndex.h"

#include <gtest/gtest.h>

#include "support/TemporaryFolder.h"

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "core/Error.h"

namespace sphcast {
namespace {

namespace fs = std::filesystem;

PvdEntry entry(double time, const std::string& timeName, const std::string& part) {
  return {time, timeName, part, timeName + "/" + part + ".vtp"};
}

class PvdIndexTest : public testing::TemporaryFolderTest {
 protected:
  // The DataSet lines of a written file, in order.
  static std::vector<std::string> dataSetLines(const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) {
      if (line.find("<DataSet") != std::string::npos) lines.push_back(line);
    }
    return lines;
  }

  static void expectReadErrorNamingFile(const fs::path& file, const std::string& because) {
    ::testing::internal::CaptureStderr();
    std::string message;
    try {
      readPvd(file);
    } catch (const Error& error) {
      message = error.what();
    }
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
    EXPECT_NE(message.find(file.string()), std::string::npos) << "message: '" << message << "'";
    EXPECT_NE(message.find(because), std::string::npos) << message;
  }
};

TEST_F(PvdIndexTest, WriteThenReadRoundTrips) {
  const std::vector<PvdEntry> entries = {entry(0, "0", "metal"), entry(0, "0", "mold"),
                                         entry(0.05, "0.05", "metal"), entry(0.05, "0.05", "mold")};
  const fs::path pvd = folder_ / "conicalMold.pvd";
  writePvd(pvd, entries);
  EXPECT_EQ(readPvd(pvd), entries);
}

TEST_F(PvdIndexTest, FileIsAParaViewCollection) {
  const fs::path pvd = folder_ / "case.pvd";
  writePvd(pvd, {entry(0.1, "0.1", "metal")});
  EXPECT_EQ(testing::readWholeFile(pvd),
            "<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\" "
            "header_type=\"UInt64\">\n"
            "  <Collection>\n"
            "    <DataSet timestep=\"0.1\" group=\"\" part=\"0\" name=\"metal\" "
            "file=\"0.1/metal.vtp\"/>\n"
            "  </Collection>\n"
            "</VTKFile>\n");
}

TEST_F(PvdIndexTest, TimestepIsTheTimeFolderNameNotTheRoundedDouble) {
  const fs::path pvd = folder_ / "case.pvd";
  writePvd(pvd, {entry(0.1 + 0.2, "0.3", "metal")});
  ASSERT_EQ(dataSetLines(pvd).size(), 1u);
  EXPECT_NE(dataSetLines(pvd)[0].find("timestep=\"0.3\""), std::string::npos);
  EXPECT_EQ(readPvd(pvd)[0].timeName, "0.3");
  EXPECT_EQ(readPvd(pvd)[0].time, 0.3);
}

TEST_F(PvdIndexTest, EntriesAreSortedByTimeThenPart) {
  const fs::path pvd = folder_ / "case.pvd";
  writePvd(pvd, {entry(0.1, "0.1", "mold"), entry(0.02, "0.02", "metal"),
                 entry(0.1, "0.1", "metal"), entry(0, "0", "mold"), entry(0.02, "0.02", "air")});
  const std::vector<PvdEntry> read = readPvd(pvd);
  const std::vector<PvdEntry> expected = {entry(0, "0", "mold"), entry(0.02, "0.02", "air"),
                                          entry(0.02, "0.02", "metal"), entry(0.1, "0.1", "metal"),
                                          entry(0.1, "0.1", "mold")};
  EXPECT_EQ(read, expected);
}

TEST_F(PvdIndexTest, NumericTimeOrderNotTextOrder) {
  const fs::path pvd = folder_ / "case.pvd";
  writePvd(pvd, {entry(10, "10", "metal"), entry(2, "2", "metal"), entry(0.5, "0.5", "metal")});
  const std::vector<PvdEntry> read = readPvd(pvd);
  ASSERT_EQ(read.size(), 3u);
  EXPECT_EQ(read[0].timeName, "0.5");
  EXPECT_EQ(read[1].timeName, "2");
  EXPECT_EQ(read[2].timeName, "10");
}

TEST_F(PvdIndexTest, PartIndexOfACloudIsTheSameAtEveryTime) {
  const fs::path pvd = folder_ / "case.pvd";
  // "air" exists only at the later time; "metal" must keep its index anyway.
  writePvd(pvd, {entry(0, "0", "metal"), entry(0, "0", "mold"), entry(0.1, "0.1", "air"),
                 entry(0.1, "0.1", "metal"), entry(0.1, "0.1", "mold")});
  const std::vector<std::string> lines = dataSetLines(pvd);
  ASSERT_EQ(lines.size(), 5u);
  for (const std::string& line : lines) {
    const std::string expectedPart = line.find("name=\"air\"") != std::string::npos     ? "0"
                                     : line.find("name=\"metal\"") != std::string::npos ? "1"
                                                                                        : "2";
    EXPECT_NE(line.find("part=\"" + expectedPart + "\""), std::string::npos) << line;
  }
}

TEST_F(PvdIndexTest, AttributesAreXmlEscaped) {
  const fs::path pvd = folder_ / "case.pvd";
  const PvdEntry awkward{1, "1", "a&b<c>\"d'", "1/a&b<c>\"d'.vtp"};
  writePvd(pvd, {awkward});
  const std::string line = dataSetLines(pvd).at(0);
  EXPECT_NE(line.find("name=\"a&amp;b&lt;c&gt;&quot;d&apos;\""), std::string::npos) << line;
  EXPECT_EQ(readPvd(pvd), std::vector<PvdEntry>{awkward});
}

TEST_F(PvdIndexTest, RewrittenTimeKeepsTheLastEntry) {
  const fs::path pvd = folder_ / "case.pvd";
  PvdEntry rewritten = entry(0.1, "0.1", "metal");
  rewritten.file = "0.1/metalAgain.vtp";
  writePvd(pvd, {entry(0.1, "0.1", "metal"), rewritten});
  EXPECT_EQ(readPvd(pvd), std::vector<PvdEntry>{rewritten});
}

TEST_F(PvdIndexTest, RewriteReplacesTheFileAtomically) {
  const fs::path pvd = folder_ / "case.pvd";
  std::vector<PvdEntry> entries;
  for (int step = 0; step < 20; ++step) {
    const std::string name = std::to_string(step);
    entries.push_back(entry(step, name, "metal"));
    writePvd(pvd, entries);
    ASSERT_EQ(readPvd(pvd).size(), entries.size());
  }
  EXPECT_FALSE(fs::exists(folder_ / "case.pvd.tmp"));
  EXPECT_EQ(std::distance(fs::directory_iterator(folder_), fs::directory_iterator()), 1);
}

TEST_F(PvdIndexTest, EmptyCollectionRoundTrips) {
  const fs::path pvd = folder_ / "case.pvd";
  writePvd(pvd, {});
  EXPECT_TRUE(readPvd(pvd).empty());
}

TEST_F(PvdIndexTest, MissingFileIsAnErrorNamingIt) {
  expectReadErrorNamingFile(folder_ / "absent.pvd", "no such file");
}

TEST_F(PvdIndexTest, MalformedXmlIsAnErrorNamingTheFile) {
  const fs::path pvd = folder_ / "case.pvd";
  writePvd(pvd, {entry(0, "0", "metal")});
  const std::string content = testing::readWholeFile(pvd);
  std::ofstream(pvd, std::ios::binary | std::ios::trunc) << content.substr(0, content.size() / 2);
  expectReadErrorNamingFile(pvd, "");
}

TEST_F(PvdIndexTest, DataSetWithoutFileIsAnErrorNamingTheFile) {
  const fs::path pvd = folder_ / "case.pvd";
  std::ofstream(pvd) << "<VTKFile type=\"Collection\"><Collection>"
                        "<DataSet timestep=\"0\" name=\"metal\"/></Collection></VTKFile>\n";
  expectReadErrorNamingFile(pvd, "'file'");
}

TEST_F(PvdIndexTest, OtherVtkFileIsAnErrorNamingTheFile) {
  const fs::path pvd = folder_ / "case.pvd";
  std::ofstream(pvd) << "<VTKFile type=\"PolyData\"><PolyData/></VTKFile>\n";
  expectReadErrorNamingFile(pvd, "Collection");
}

}  // namespace
}  // namespace sphcast
