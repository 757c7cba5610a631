#include "io/VtpCloud.h"

#include <vtkAOSDataArrayTemplate.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDataCompressor.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <exception>
#include <fstream>
#include <numeric>
#include <sstream>
#include <system_error>
#include <type_traits>

#include "core/AtomicFile.h"
#include "core/Error.h"
#include "particles/FieldNames.h"

namespace sphcast {

namespace {

namespace fs = std::filesystem;

// A vector field is then one flat xyz array that VTK can use in place, without a copy.
static_assert(sizeof(Vector) == 3 * sizeof(Real), "Vector must be three contiguous Reals");

using RealArray = vtkAOSDataArrayTemplate<Real>;
using IdArray = vtkAOSDataArrayTemplate<std::int64_t>;

// Collects the errors and warnings of the VTK objects it watches, so that VTK prints nothing and
// the caller can throw one Error that names the file.
class VtkMessageCollector : public vtkCommand {
 public:
  static VtkMessageCollector* New() { return new VtkMessageCollector; }

  void watch(vtkObject* object) {
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
  }

  void Execute(vtkObject*, unsigned long, void* callData) override {
    const std::string message = withoutSourceLocation(static_cast<const char*>(callData));
    if (messages_.find(message) != std::string::npos) return;  // the reader repeats itself
    if (!messages_.empty()) messages_ += "; ";
    messages_ += message;
  }

  bool empty() const { return messages_.empty(); }
  const std::string& messages() const { return messages_; }

 private:
  // VTK's text is "ERROR: In <source file>, line <n>\n<class> (<address>): <message>\n\n"; the
  // user needs only the first line of the message.
  static std::string withoutSourceLocation(const char* text) {
    std::string message = text ? text : "unknown VTK error";
    const std::size_t addressEnd = message.find("): ");
    if (addressEnd != std::string::npos) message.erase(0, addressEnd + 3);
    message.erase(std::min(message.find('\n'), message.size()));
    while (!message.empty() &&
           (std::isspace(static_cast<unsigned char>(message.back())) || message.back() == '.')) {
      message.pop_back();
    }
    return message;
  }

  std::string messages_;
};

// ---- writing ------------------------------------------------------------------------------

// A VTK array over the cloud's own storage, without a copy. The writer only reads it, and it
// lives no longer than writeCloudVtp (save = 1: VTK never frees the memory).
template <typename Array, typename Value>
vtkSmartPointer<Array> arrayOver(const Value* values, std::size_t tupleCount, int components,
                                 const std::string& name) {
  auto array = vtkSmartPointer<Array>::New();
  array->SetName(name.c_str());
  array->SetNumberOfComponents(components);
  if (tupleCount > 0) {
    array->SetArray(const_cast<Value*>(values), static_cast<vtkIdType>(tupleCount) * components, 1);
  }
  return array;
}

const Real* flatXyz(const ParticleCloud::VectorField& field) {
  return field.empty() ? nullptr : field.front().data();
}

Real* flatXyz(ParticleCloud::VectorField& field) {
  return field.empty() ? nullptr : field.front().data();
}

// One vertex cell per particle, given directly as offsets 0..n and connectivity 0..n-1 (the
// cheapest form: vtkIdTypeArray is vtkCellArray's own storage type, so it is not copied).
vtkSmartPointer<vtkCellArray> oneVertexPerParticle(std::size_t particleCount) {
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(particleCount) + 1);
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(particleCount));
  std::iota(offsets->GetPointer(0), offsets->GetPointer(0) + particleCount + 1, vtkIdType{0});
  if (particleCount > 0) {
    std::iota(connectivity->GetPointer(0), connectivity->GetPointer(0) + particleCount,
              vtkIdType{0});
  }
  auto vertices = vtkSmartPointer<vtkCellArray>::New();
  vertices->SetData(offsets, connectivity);
  return vertices;
}

void addAttributes(const ParticleCloud& cloud, vtkFieldData& fieldData) {
  for (const auto& [name, value] : cloud.attributes()) {
    vtkNew<vtkDoubleArray> attribute;
    attribute->SetName(name.c_str());
    attribute->SetNumberOfValues(1);
    attribute->SetValue(0, value);
    fieldData.AddArray(attribute);
  }
}

// A vtkPolyData whose arrays are views of the cloud's storage.
// A cloud's halo (copies of other ranks' particles) is not written: their owners write them.
vtkSmartPointer<vtkPolyData> polyDataView(const ParticleCloud& cloud) {
  const std::size_t count = cloud.ownedSize();
  vtkNew<vtkPoints> points;
  points->SetData(arrayOver<RealArray>(flatXyz(cloud.positions()), count, 3, "position"));
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetVerts(oneVertexPerParticle(count));
  vtkPointData& pointData = *polyData->GetPointData();
  for (const auto& [name, field] : cloud.scalarFields()) {
    pointData.AddArray(arrayOver<RealArray>(field.data(), count, 1, name));
  }
  for (const auto& [name, field] : cloud.vectorFields()) {
    pointData.AddArray(arrayOver<RealArray>(flatXyz(field), count, 3, name));
  }
  for (const auto& [name, field] : cloud.idFields()) {
    pointData.AddArray(arrayOver<IdArray>(field.data(), count, 1, name));
  }
  addAttributes(cloud, *polyData->GetFieldData());
  return polyData;
}

// Appended data, zlib, UInt64 headers, base64-encoded: exact, compact where the data allows, and
// well-formed XML. Raw appended bytes (VTK's default, 25 % smaller) are not XML: parsers with
// expat's stricter checks refuse them, Debian 12's ParaView 5.11 among them (issue #51).
void writePolyData(vtkPolyData* polyData, const fs::path& file) {
  vtkNew<vtkXMLPolyDataWriter> writer;
  vtkNew<VtkMessageCollector> messages;
  vtkNew<VtkMessageCollector> pipelineMessages;  // "algorithm failed": only if nothing better
  messages->watch(writer);
  pipelineMessages->watch(writer->GetExecutive());
  writer->SetInputData(polyData);
  writer->SetFileName(file.c_str());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOn();
  writer->SetCompressorTypeToZLib();
  // Level 1: full-precision doubles barely compress (level 5 saves 0.4% more) but level 5 writes
  // at half the speed (tests/benchmarks/CloudIoBenchmark.cpp).
  writer->SetCompressionLevel(1);
  writer->SetHeaderTypeToUInt64();
  const int written = writer->Write();
  if (!messages->empty()) throw Error(messages->messages());
  if (written != 1 || !pipelineMessages->empty()) {
    throw Error(pipelineMessages->empty() ? "VTK could not write it"
                                          : pipelineMessages->messages());
  }
}

// ---- reading ------------------------------------------------------------------------------

// Every file writeCloudVtp writes ends with "</VTKFile>"; one that does not was cut short (or is
// no VTK XML file). VTK would not notice a cut in the closing tags, so check it here.
void checkEndsWithClosingTag(const fs::path& file) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) throw Error("cannot open it");
  const std::streamoff size = in.tellg();
  const std::streamoff tailSize = std::min<std::streamoff>(size, 256);
  std::string tail(static_cast<std::size_t>(tailSize), '\0');
  in.seekg(size - tailSize);
  in.read(tail.data(), tailSize);
  const std::size_t end = tail.find_last_not_of(" \t\r\n");
  if (end == std::string::npos || !tail.substr(0, end + 1).ends_with("</VTKFile>")) {
    throw Error("the file is truncated or not a VTK XML file (it does not end with </VTKFile>)");
  }
}

// VTK creates the zlib compressor deep inside the reader, where no observer of ours reaches it,
// and would print its errors. These two subclasses hand it to the collector: the reader through
// its parser factory (CreateXMLParser), the parser when it is given its compressor.
class ObservedDataParser : public vtkXMLDataParser {
 public:
  static ObservedDataParser* New() {
    auto* object = new ObservedDataParser;
    object->InitializeObjectBase();
    return object;
  }

  void setCollector(VtkMessageCollector* collector) {
    collector_ = collector;
    collector_->watch(this);
  }
  void SetCompressor(vtkDataCompressor* compressor) override {
    vtkXMLDataParser::SetCompressor(compressor);
    if (compressor != nullptr && collector_ != nullptr) collector_->watch(compressor);
  }

 private:
  VtkMessageCollector* collector_ = nullptr;
};

class ObservedPolyDataReader : public vtkXMLPolyDataReader {
 public:
  static ObservedPolyDataReader* New() {
    auto* object = new ObservedPolyDataReader;
    object->InitializeObjectBase();
    return object;
  }

  void setCollectors(VtkMessageCollector* collector, VtkMessageCollector* pipelineCollector) {
    collector_ = collector;
    collector_->watch(this);
    pipelineCollector->watch(GetExecutive());
  }

 protected:
  void CreateXMLParser() override {
    if (XMLParser != nullptr) DestroyXMLParser();
    ObservedDataParser* parser = ObservedDataParser::New();
    if (collector_ != nullptr) parser->setCollector(collector_);
    XMLParser = parser;
  }

 private:
  VtkMessageCollector* collector_ = nullptr;
};

vtkSmartPointer<vtkPolyData> readPolyData(const fs::path& file) {
  vtkNew<VtkMessageCollector> messages;
  vtkNew<VtkMessageCollector> pipelineMessages;  // "algorithm failed": only if nothing better
  vtkNew<ObservedPolyDataReader> reader;
  reader->setCollectors(messages, pipelineMessages);
  reader->SetFileName(file.c_str());
  try {
    reader->Update();
  } catch (const std::exception& error) {
    // A corrupt block header can ask VTK for an absurd allocation (std::bad_alloc).
    throw Error(std::string("VTK failed reading it (") + error.what() + ")");
  }
  if (!messages->empty()) throw Error(messages->messages());
  if (!pipelineMessages->empty()) throw Error(pipelineMessages->messages());
  vtkSmartPointer<vtkPolyData> polyData = reader->GetOutput();
  if (polyData == nullptr) throw Error("VTK read no PolyData from it");
  return polyData;
}

std::string nameOf(vtkAbstractArray& array) {
  return array.GetName() != nullptr ? array.GetName() : "";
}

// Copies a Float64 or Float32 array into Real storage (a plain copy when the types match).
template <typename Source>
bool copyIfOfType(vtkDataArray& array, Real* out, std::size_t valueCount) {
  auto* typed = vtkArrayDownCast<vtkAOSDataArrayTemplate<Source>>(&array);
  if (typed == nullptr) return false;
  if (valueCount == 0) return true;
  const Source* values = typed->GetPointer(0);
  std::transform(values, values + valueCount, out,
                 [](Source value) { return static_cast<Real>(value); });
  return true;
}

void copyReals(vtkDataArray& array, const std::string& name, Real* out, std::size_t valueCount) {
  if (copyIfOfType<double>(array, out, valueCount)) return;
  if (copyIfOfType<float>(array, out, valueCount)) return;
  throw Error("array '" + name + "' has the unsupported type " + array.GetDataTypeAsString() +
              "; particle fields are Float64 or Float32");
}

template <typename Source>
bool copyIdsIfOfType(vtkDataArray& array, std::int64_t* out, std::size_t valueCount) {
  auto* typed = vtkArrayDownCast<vtkAOSDataArrayTemplate<Source>>(&array);
  if (typed == nullptr) return false;
  if (valueCount == 0) return true;
  const Source* values = typed->GetPointer(0);
  std::transform(values, values + valueCount, out,
                 [](Source value) { return static_cast<std::int64_t>(value); });
  return true;
}

void copyIds(vtkDataArray& array, const std::string& name, std::int64_t* out,
             std::size_t valueCount) {
  if (copyIdsIfOfType<long>(array, out, valueCount)) return;
  if (copyIdsIfOfType<long long>(array, out, valueCount)) return;
  if (copyIdsIfOfType<int>(array, out, valueCount)) return;
  throw Error("array '" + name + "' has the unsupported type " + array.GetDataTypeAsString() +
              "; id fields are Int64 or Int32");
}

// Fields that hold a positive quantity wherever sphCast writes them; zero or less in a file is
// a damaged or hand-made cloud, which the flow would divide by (rho, mass, the harmonic mean of
// two viscosities) or weigh with (a wall particle's volume).
bool mustBePositive(const std::string& fieldName) {
  for (const char* name :
       {field::mass, field::restDensity, field::rho, field::viscosity, field::volume}) {
    if (fieldName == name) return true;
  }
  return false;
}

// The first value that breaks the rules, named with its particle: NaN or infinity anywhere (it
// would surface far from here, in the neighbour grid or as a negative density, without a file
// to look at), zero or less in a field that holds a positive quantity.
void checkValues(const Real* values, std::size_t valueCount, int components,
                 const std::string& fieldName, const ParticleCloud& cloud) {
  const bool positive = mustBePositive(fieldName);
  const Real* end = values + valueCount;
  const Real* bad = std::find_if(values, end, [positive](Real value) {
    return !std::isfinite(value) || (positive && !(value > 0));
  });
  if (bad == end) return;
  const std::size_t particle =
      static_cast<std::size_t>(bad - values) / static_cast<std::size_t>(components);
  std::ostringstream message;
  message << "cloud '" << cloud.name()
          << "': " << (fieldName.empty() ? "the position" : "field '" + fieldName + "'")
          << " of particle " << particle << " is " << *bad
          << (std::isfinite(*bad) ? "; it must be positive (valid range: > 0)"
                                  : "; particle positions and fields must be finite");
  throw Error(message.str());
}

bool isFloatingPoint(const vtkDataArray& array) {
  return array.GetDataType() == VTK_DOUBLE || array.GetDataType() == VTK_FLOAT;
}

void readPointArray(vtkAbstractArray& abstractArray, ParticleCloud& cloud) {
  const std::string name = nameOf(abstractArray);
  if (name.empty()) throw Error("a point data array has no name");
  auto* array = vtkDataArray::SafeDownCast(&abstractArray);
  if (array == nullptr) throw Error("point data array '" + name + "' is not numeric");
  const std::size_t count = cloud.size();
  if (array->GetNumberOfTuples() != static_cast<vtkIdType>(count)) {
    throw Error("point data array '" + name + "' has " +
                std::to_string(array->GetNumberOfTuples()) + " values for " +
                std::to_string(count) + " particles");
  }
  const int components = array->GetNumberOfComponents();
  if (!isFloatingPoint(*array) && components == 1) {
    copyIds(*array, name, cloud.addIdField(name).data(), count);
  } else if (isFloatingPoint(*array) && components == 1) {
    Real* values = cloud.addScalarField(name).data();
    copyReals(*array, name, values, count);
    checkValues(values, count, 1, name, cloud);
  } else if (isFloatingPoint(*array) && components == 3) {
    Real* values = flatXyz(cloud.addVectorField(name));
    copyReals(*array, name, values, 3 * count);
    checkValues(values, 3 * count, 3, name, cloud);
  } else {
    throw Error("point data array '" + name + "' (" + array->GetDataTypeAsString() + ") has " +
                std::to_string(components) +
                " components; particle fields have 1 (scalar, id) or 3 (vector, floating-point)");
  }
}

void readAttribute(vtkAbstractArray& abstractArray, ParticleCloud& cloud) {
  const std::string name = nameOf(abstractArray);
  auto* array = vtkDataArray::SafeDownCast(&abstractArray);
  if (name.empty() || array == nullptr || array->GetNumberOfTuples() != 1 ||
      array->GetNumberOfComponents() != 1) {
    throw Error("field data array '" + name +
                "' is not a cloud attribute (a named array of one number)");
  }
  const double value = array->GetComponent(0, 0);
  if (!std::isfinite(value)) {
    throw Error("cloud '" + cloud.name() + "': attribute '" + name + "' is " +
                std::to_string(value) + "; it must be finite");
  }
  cloud.attributes()[name] = value;
}

ParticleCloud cloudFrom(vtkPolyData& polyData, const std::string& cloudName) {
  ParticleCloud cloud(cloudName);
  const auto count = static_cast<std::size_t>(polyData.GetNumberOfPoints());
  cloud.resize(count);
  if (count > 0) {
    copyReals(*polyData.GetPoints()->GetData(), "Points", flatXyz(cloud.positions()), 3 * count);
    checkValues(flatXyz(cloud.positions()), 3 * count, 3, "", cloud);
  }
  vtkPointData& pointData = *polyData.GetPointData();
  for (int i = 0; i < pointData.GetNumberOfArrays(); ++i) {
    readPointArray(*pointData.GetAbstractArray(i), cloud);
  }
  vtkFieldData& fieldData = *polyData.GetFieldData();
  for (int i = 0; i < fieldData.GetNumberOfArrays(); ++i) {
    readAttribute(*fieldData.GetAbstractArray(i), cloud);
  }
  return cloud;
}

}  // namespace

void writeCloudVtp(const ParticleCloud& cloud, const fs::path& file) {
  const fs::path temporary = temporaryPathFor(file);
  try {
    writePolyData(polyDataView(cloud), temporary);
    syncFileToDisk(temporary);
    renameAtomically(temporary, file);
  } catch (const Error& error) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw Error("cannot write cloud '" + cloud.name() + "' to '" + file.string() +
                "': " + error.what());
  }
}

ParticleCloud readCloudVtp(const fs::path& file, const std::string& cloudName) {
  std::error_code ignored;
  if (!fs::exists(file, ignored)) {
    throw Error("cannot read cloud file '" + file.string() + "': no such file");
  }
  try {
    if (!fs::is_regular_file(file, ignored)) throw Error("it is not a regular file");
    checkEndsWithClosingTag(file);
    vtkSmartPointer<vtkPolyData> polyData = readPolyData(file);
    return cloudFrom(*polyData, cloudName);
  } catch (const Error& error) {
    throw Error("cannot read cloud file '" + file.string() + "': " + error.what());
  }
}

}  // namespace sphcast
