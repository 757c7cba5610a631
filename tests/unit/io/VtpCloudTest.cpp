#include "io/VtpCloud.h"

#include <gtest/gtest.h>

#include "support/TemporaryFolder.h"

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include "core/Error.h"
#include "particles/FieldNames.h"

namespace sphcast {
namespace {

namespace fs = std::filesystem;

// Values that a text format or a careless conversion would not keep bit for bit (all finite:
// the reader refuses NaN and infinities, NonFiniteOrNonPositiveValuesAreRefused...).
std::vector<Real> awkwardValues() {
  using Limits = std::numeric_limits<Real>;
  return {
      Real(0),       -Real(0),      Limits::denorm_min(), -Limits::denorm_min(), Limits::min() / 3,
      Limits::min(), Limits::max(), Limits::lowest(),     Limits::epsilon(),     Real(1) / 3,
      Real(0.1)};
}

// A cloud with random fields, the awkward values sprinkled over the first particles.
ParticleCloud randomCloud(std::size_t count, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(-1e3, 1e3);
  const std::vector<Real> awkward = awkwardValues();
  auto value = [&](std::size_t i, std::size_t k) {
    const std::size_t pick = 3 * i + k;
    return pick < awkward.size() ? awkward[pick] : static_cast<Real>(uniform(random));
  };
  ParticleCloud cloud("metal");
  cloud.resize(count);
  auto& temperature = cloud.addScalarField(field::T);
  auto& pressure = cloud.addScalarField(field::p);  // any sign (rho, mass, ... must be positive)
  auto& velocity = cloud.addVectorField(field::U);
  auto& force = cloud.addVectorField("force");
  auto& id = cloud.addIdField("id");
  auto& origin = cloud.addIdField("origin");
  for (std::size_t i = 0; i < count; ++i) {
    cloud.positions()[i] = Vector(value(i, 0), value(i, 1), value(i, 2));
    velocity[i] = Vector(value(i, 2), value(i, 0), value(i, 1));
    force[i] = Vector(value(i, 1), value(i, 2), value(i, 0));
    temperature[i] = value(i, 0);
    pressure[i] = value(i, 1);
    id[i] = static_cast<std::int64_t>(random());
    origin[i] = -static_cast<std::int64_t>(i);
  }
  cloud.attributes()["spacing"] = 0.00225;
  cloud.attributes()["negativeZero"] = -0.0;
  cloud.attributes()["tiny"] = 4.9e-324;
  cloud.attributes()["huge"] = 1.7976931348623157e308;
  return cloud;
}

// identicalTo compares attributes with ==, which cannot tell -0.0 from 0.0.
void expectAttributesBitwiseEqual(const ParticleCloud& expected, const ParticleCloud& actual) {
  ASSERT_EQ(expected.attributes().size(), actual.attributes().size());
  for (const auto& [name, value] : expected.attributes()) {
    ASSERT_TRUE(actual.attributes().count(name)) << name;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(value),
              std::bit_cast<std::uint64_t>(actual.attributes().at(name)))
        << name;
  }
}

class VtpCloudTest : public testing::TemporaryFolderTest {
 protected:
  static void writeWhole(const fs::path& file, const std::string& content) {
    std::ofstream(file, std::ios::binary) << content;
  }

  // Reading file must throw an Error naming it, and VTK must print nothing.
  static void expectReadErrorNamingFile(const fs::path& file, const std::string& because = "") {
    ::testing::internal::CaptureStderr();
    ::testing::internal::CaptureStdout();
    std::string message;
    try {
      readCloudVtp(file, "metal");
    } catch (const Error& error) {
      message = error.what();
    }
    const std::string printed =
        ::testing::internal::GetCapturedStderr() + ::testing::internal::GetCapturedStdout();
    EXPECT_NE(message.find(file.string()), std::string::npos) << "message: '" << message << "'";
    EXPECT_NE(message.find(because), std::string::npos) << message;
    EXPECT_EQ(printed, "") << "VTK printed while reading " << file;
  }
};

TEST_F(VtpCloudTest, WriteThenReadIsBitExact) {
  const ParticleCloud cloud = randomCloud(1000, 7);
  const fs::path file = folder_ / "metal.vtp";
  writeCloudVtp(cloud, file);
  const ParticleCloud read = readCloudVtp(file, "metal");
  EXPECT_EQ(read.name(), "metal");
  EXPECT_EQ(read.size(), cloud.size());
  EXPECT_TRUE(read.identicalTo(cloud));
  expectAttributesBitwiseEqual(cloud, read);
  EXPECT_TRUE(std::signbit(read.positions()[0].y()));  // -0.0 kept
  EXPECT_EQ(read.scalarField(field::T)[2], std::numeric_limits<Real>::max());
  EXPECT_EQ(read.scalarField(field::p)[2], std::numeric_limits<Real>::lowest());
}

// A NaN or infinity in a start time's cloud, or a zero or negative mass, density, viscosity or
// volume, is refused when read, naming the file, the cloud, the position or field, the particle
// and the value; not later by the neighbour grid or as 0/0, without a file.
TEST_F(VtpCloudTest, NonFiniteOrNonPositiveValuesAreRefusedNamingFileCloudFieldAndParticle) {
  const fs::path file = folder_ / "metal.vtp";
  auto expectRefused = [&](const ParticleCloud& cloud, const std::string& because) {
    writeCloudVtp(cloud, file);
    try {
      readCloudVtp(file, "metal");
      ADD_FAILURE() << "no Error for " << because;
    } catch (const Error& error) {
      EXPECT_EQ(std::string(error.what()), "cannot read cloud file '" + file.string() +
                                               "': cloud 'metal': " + because +
                                               "; particle positions and fields must be finite");
    }
  };
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  const Real inf = std::numeric_limits<Real>::infinity();
  ParticleCloud cloud = randomCloud(20, 9);
  cloud.positions()[13].z() = nan;
  expectRefused(cloud, "the position of particle 13 is nan");
  cloud = randomCloud(20, 9);
  cloud.scalarField(field::T)[7] = -inf;
  expectRefused(cloud, "field 'T' of particle 7 is -inf");
  cloud = randomCloud(20, 9);
  cloud.vectorField(field::U)[19].y() = inf;
  expectRefused(cloud, "field 'U' of particle 19 is inf");

  // A cloud the flow would divide by zero with (mass, rho, viscosity) or weigh wrongly (volume).
  const std::string positive = "; it must be positive (valid range: > 0)";
  for (const char* field : {"mass", "restDensity", "rho", "viscosity", "volume"}) {
    cloud = randomCloud(20, 9);
    std::vector<Real>& values =
        cloud.hasScalarField(field) ? cloud.scalarField(field) : cloud.addScalarField(field);
    std::fill(values.begin(), values.end(), Real(1));
    values[11] = Real(0);
    writeCloudVtp(cloud, file);
    expectReadErrorNamingFile(
        file, std::string("cloud 'metal': field '") + field + "' of particle 11 is 0" + positive);
    values[11] = Real(-2.5);
    writeCloudVtp(cloud, file);
    expectReadErrorNamingFile(file, std::string("field '") + field + "' of particle 11 is -2.5");
  }

  cloud = randomCloud(20, 9);
  cloud.attributes()["spacing"] = nan;
  writeCloudVtp(cloud, file);
  expectReadErrorNamingFile(file, "attribute 'spacing' is nan");
}

TEST_F(VtpCloudTest, ReadKeepsFieldKinds) {
  const fs::path file = folder_ / "metal.vtp";
  writeCloudVtp(randomCloud(10, 1), file);
  const ParticleCloud read = readCloudVtp(file, "metal");
  EXPECT_TRUE(read.hasScalarField(field::T));
  EXPECT_TRUE(read.hasScalarField(field::p));
  EXPECT_TRUE(read.hasVectorField(field::U));
  EXPECT_TRUE(read.hasVectorField("force"));
  EXPECT_TRUE(read.hasIdField("id"));
  EXPECT_TRUE(read.hasIdField("origin"));
  EXPECT_EQ(read.scalarFields().size(), 2u);
  EXPECT_EQ(read.vectorFields().size(), 2u);
  EXPECT_EQ(read.idFields().size(), 2u);
}

TEST_F(VtpCloudTest, EmptyCloudRoundTrips) {
  ParticleCloud cloud("mold");
  cloud.addScalarField(field::T);
  cloud.addVectorField(field::U);
  cloud.addIdField("id");
  cloud.attributes()["spacing"] = 0.001;
  const fs::path file = folder_ / "mold.vtp";
  writeCloudVtp(cloud, file);
  const ParticleCloud read = readCloudVtp(file, "mold");
  EXPECT_EQ(read.size(), 0u);
  EXPECT_TRUE(read.identicalTo(cloud));
}

TEST_F(VtpCloudTest, CloudWithoutFieldsRoundTrips) {
  ParticleCloud cloud("air");
  cloud.resize(3);
  cloud.positions()[2] = Vector(1, 2, 3);
  const fs::path file = folder_ / "air.vtp";
  writeCloudVtp(cloud, file);
  EXPECT_TRUE(readCloudVtp(file, "air").identicalTo(cloud));
}

TEST_F(VtpCloudTest, FileIsWellFormedXmlWithBase64AppendedZlibData) {
  const fs::path file = folder_ / "metal.vtp";
  writeCloudVtp(randomCloud(100, 2), file);
  const std::string content = testing::readWholeFile(file);
  const std::string header = content.substr(0, content.find("<AppendedData"));
  EXPECT_NE(header.find("type=\"PolyData\""), std::string::npos);
  EXPECT_NE(header.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(header.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  EXPECT_NE(header.find("format=\"appended\""), std::string::npos);
  EXPECT_EQ(header.find("format=\"binary\""), std::string::npos);
  EXPECT_EQ(header.find("format=\"ascii\""), std::string::npos);
  EXPECT_NE(content.find("encoding=\"base64\""), std::string::npos);
  // well-formed: nothing after the header but base64's characters, the closing tags, blanks
  const std::size_t data = content.find('_', content.find("<AppendedData")) + 1;
  const std::size_t end = content.find("</AppendedData>");
  ASSERT_NE(end, std::string::npos);
  const std::string encoded = content.substr(data, end - data);
  EXPECT_EQ(encoded.find_first_not_of(
                "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/= \n"),
            std::string::npos);
  const std::string realType = sizeof(Real) == 8 ? "Float64" : "Float32";
  EXPECT_NE(header.find("type=\"" + realType + "\" Name=\"U\" NumberOfComponents=\"3\""),
            std::string::npos);
  EXPECT_NE(header.find("type=\"Int64\" Name=\"id\""), std::string::npos);
  EXPECT_NE(header.find("type=\"Float64\" Name=\"spacing\" NumberOfTuples=\"1\""),
            std::string::npos);
  EXPECT_NE(header.find("NumberOfVerts=\"100\""), std::string::npos);
}

// Time folders written before issue #51 hold raw appended data: a restart from them still reads.
TEST_F(VtpCloudTest, AFileWithRawAppendedDataStillReads) {
  const fs::path file = folder_ / "metal.vtp";
  const ParticleCloud cloud = randomCloud(300, 5);
  writeCloudVtp(cloud, file);
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  const fs::path raw = folder_ / "raw.vtp";
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(reader->GetOutput());
  writer->SetFileName(raw.c_str());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToZLib();
  writer->SetHeaderTypeToUInt64();
  ASSERT_EQ(writer->Write(), 1);
  ASSERT_NE(testing::readWholeFile(raw).find("encoding=\"raw\""), std::string::npos);
  EXPECT_TRUE(readCloudVtp(raw, "metal").identicalTo(cloud));
}

TEST_F(VtpCloudTest, WriteLeavesNoTemporaryFile) {
  const fs::path file = folder_ / "metal.vtp";
  writeCloudVtp(randomCloud(50, 3), file);
  writeCloudVtp(randomCloud(60, 4), file);  // replaces the first
  EXPECT_FALSE(fs::exists(folder_ / "metal.vtp.tmp"));
  EXPECT_EQ(std::distance(fs::directory_iterator(folder_), fs::directory_iterator()), 1);
  EXPECT_EQ(readCloudVtp(file, "metal").size(), 60u);
}

TEST_F(VtpCloudTest, WriteIntoMissingFolderIsAnErrorNamingTheFile) {
  const fs::path file = folder_ / "0.1" / "metal.vtp";
  ::testing::internal::CaptureStderr();
  try {
    writeCloudVtp(randomCloud(5, 5), file);
    ADD_FAILURE() << "no Error thrown";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
  }
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_FALSE(fs::exists(folder_ / "0.1"));
}

TEST_F(VtpCloudTest, TruncatedFileIsAnErrorNamingTheFile) {
  const fs::path whole = folder_ / "whole.vtp";
  writeCloudVtp(randomCloud(2000, 6), whole);
  const std::string content = testing::readWholeFile(whole);
  const std::size_t appended = content.find("<AppendedData");
  for (std::size_t length : {std::size_t{0}, std::size_t{10}, appended / 2, appended + 20,
                             content.size() / 2, content.size() - 30, content.size() - 2}) {
    SCOPED_TRACE("cut at " + std::to_string(length) + " of " + std::to_string(content.size()));
    const fs::path cut = folder_ / ("cut" + std::to_string(length) + ".vtp");
    writeWhole(cut, content.substr(0, length));
    expectReadErrorNamingFile(cut);
  }
}

TEST_F(VtpCloudTest, GarbageFileIsAnErrorNamingTheFile) {
  std::mt19937 random(11);
  std::string garbage(5000, '\0');
  for (char& byte : garbage) byte = static_cast<char>(random());
  const fs::path file = folder_ / "garbage.vtp";
  writeWhole(file, garbage);
  expectReadErrorNamingFile(file);
  // Garbage that ends like a VTK file gets past the cheap check and must be caught by VTK.
  const fs::path disguised = folder_ / "disguised.vtp";
  writeWhole(disguised, garbage + "</VTKFile>\n");
  expectReadErrorNamingFile(disguised);
}

TEST_F(VtpCloudTest, CorruptCompressedDataIsAnErrorNamingTheFile) {
  const fs::path file = folder_ / "metal.vtp";
  writeCloudVtp(randomCloud(2000, 8), file);
  std::string content = testing::readWholeFile(file);
  const std::size_t data = content.find('_', content.find("<AppendedData")) + 1;
  for (std::size_t i = data + 64; i < content.size() - 100; i += 97) content[i] ^= 0x5a;
  writeWhole(file, content);
  expectReadErrorNamingFile(file);
}

TEST_F(VtpCloudTest, OtherDatasetTypeIsAnErrorNamingTheFile) {
  const fs::path file = folder_ / "grid.vtu";
  writeWhole(file,
             "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\">\n"
             "<UnstructuredGrid><Piece NumberOfPoints=\"0\" NumberOfCells=\"0\"/>"
             "</UnstructuredGrid>\n</VTKFile>\n");
  expectReadErrorNamingFile(file);
}

TEST_F(VtpCloudTest, ArrayWithTwoComponentsIsAnErrorNamingTheArray) {
  const fs::path file = folder_ / "twoComponents.vtp";
  writeWhole(file,
             "<?xml version=\"1.0\"?>\n"
             "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
             "<PolyData><Piece NumberOfPoints=\"1\" NumberOfVerts=\"0\" NumberOfLines=\"0\" "
             "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
             "<PointData><DataArray type=\"Float64\" Name=\"uv\" NumberOfComponents=\"2\" "
             "format=\"ascii\">1 2</DataArray></PointData>\n"
             "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
             "0 0 0</DataArray></Points>\n"
             "</Piece></PolyData>\n</VTKFile>\n");
  expectReadErrorNamingFile(file, "'uv'");
}

TEST_F(VtpCloudTest, UnsupportedArrayTypeIsAnErrorNamingTheArray) {
  const fs::path file = folder_ / "unsigned.vtp";
  writeWhole(file,
             "<?xml version=\"1.0\"?>\n"
             "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
             "<PolyData><Piece NumberOfPoints=\"1\" NumberOfVerts=\"0\" NumberOfLines=\"0\" "
             "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
             "<PointData><DataArray type=\"UInt8\" Name=\"flag\" format=\"ascii\">1"
             "</DataArray></PointData>\n"
             "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
             "0 0 0</DataArray></Points>\n"
             "</Piece></PolyData>\n</VTKFile>\n");
  expectReadErrorNamingFile(file, "'flag'");
}

TEST_F(VtpCloudTest, MissingFileIsAnErrorSayingSo) {
  const fs::path file = folder_ / "absent.vtp";
  try {
    readCloudVtp(file, "metal");
    FAIL() << "no Error thrown";
  } catch (const Error& error) {
    EXPECT_EQ(std::string(error.what()),
              "cannot read cloud file '" + file.string() + "': no such file");
  }
}

}  // namespace
}  // namespace sphcast
