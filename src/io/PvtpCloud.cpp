#include "io/PvtpCloud.h"

#include <vtkIndent.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>

#include <sstream>
#include <type_traits>

#include "core/AtomicFile.h"
#include "core/Error.h"
#include "io/VtpCloud.h"

namespace fs = std::filesystem;

namespace sphcast {

namespace {

constexpr const char* realType = std::is_same_v<Real, double> ? "Float64" : "Float32";

vtkSmartPointer<vtkXMLDataElement> element(const char* name) {
  auto e = vtkSmartPointer<vtkXMLDataElement>::New();
  e->SetName(name);
  return e;
}

vtkSmartPointer<vtkXMLDataElement> arrayDeclaration(const char* type, const std::string& name,
                                                    int components) {
  auto array = element("PDataArray");
  array->SetAttribute("type", type);
  array->SetAttribute("Name", name.c_str());
  if (components != 1) array->SetIntAttribute("NumberOfComponents", components);
  return array;
}

}  // namespace

fs::path pieceFile(const fs::path& pvtpFile, int piece) {
  return pvtpFile.parent_path() / pieceSource(pvtpFile, piece);
}

std::string pieceSource(const fs::path& pvtpFile, int piece) {
  const std::string stem = pvtpFile.stem().string();
  return stem + "/" + stem + "_" + std::to_string(piece) + ".vtp";
}

void writeCloudPvtpIndex(const ParticleCloud& cloud, const fs::path& pvtpFile, int pieces) {
  auto root = element("VTKFile");
  root->SetAttribute("type", "PPolyData");
  root->SetAttribute("version", "1.0");
  root->SetAttribute("byte_order", "LittleEndian");
  root->SetAttribute("header_type", "UInt64");
  auto data = element("PPolyData");
  data->SetIntAttribute("GhostLevel", 0);
  auto pointData = element("PPointData");
  for (const auto& [name, field] : cloud.scalarFields()) {
    pointData->AddNestedElement(arrayDeclaration(realType, name, 1));
  }
  for (const auto& [name, field] : cloud.vectorFields()) {
    pointData->AddNestedElement(arrayDeclaration(realType, name, 3));
  }
  for (const auto& [name, field] : cloud.idFields()) {
    pointData->AddNestedElement(arrayDeclaration("Int64", name, 1));
  }
  data->AddNestedElement(pointData);
  auto points = element("PPoints");
  points->AddNestedElement(arrayDeclaration(realType, "position", 3));
  data->AddNestedElement(points);
  for (int p = 0; p < pieces; ++p) {
    auto piece = element("Piece");
    piece->SetAttribute("Source", pieceSource(pvtpFile, p).c_str());
    data->AddNestedElement(piece);
  }
  root->AddNestedElement(data);
  std::ostringstream text;
  text << "<?xml version=\"1.0\"?>\n";
  vtkIndent indent;
  vtkXMLUtilities::FlattenElement(root, text, &indent);
  writeFileAtomically(pvtpFile, text.str());
}

std::vector<fs::path> readPvtpPieces(const fs::path& pvtpFile) {
  vtkSmartPointer<vtkXMLDataElement> root;
  root.TakeReference(vtkXMLUtilities::ReadElementFromFile(pvtpFile.c_str()));
  const char* type = root ? root->GetAttribute("type") : nullptr;
  if (!root || !type || std::string(type) != "PPolyData") {
    throw Error(pvtpFile.string() + ": not a readable parallel PolyData index (.pvtp)");
  }
  vtkXMLDataElement* data = root->FindNestedElementWithName("PPolyData");
  std::vector<fs::path> pieces;
  for (int i = 0; data && i < data->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* nested = data->GetNestedElement(i);
    if (std::string(nested->GetName()) != "Piece") continue;
    const char* source = nested->GetAttribute("Source");
    if (!source) throw Error(pvtpFile.string() + ": a Piece without its Source");
    pieces.push_back(pvtpFile.parent_path() / source);
  }
  if (pieces.empty()) throw Error(pvtpFile.string() + ": the index lists no piece");
  return pieces;
}

ParticleCloud readCloudPvtp(const fs::path& pvtpFile, const std::string& cloudName, int first,
                            int stride) {
  const std::vector<fs::path> pieces = readPvtpPieces(pvtpFile);
  if (first >= static_cast<int>(pieces.size())) {  // no piece: the fields of the first
    ParticleCloud cloud = readCloudVtp(pieces.front(), cloudName);
    cloud.resize(0);
    return cloud;
  }
  ParticleCloud cloud = readCloudVtp(pieces[static_cast<std::size_t>(first)], cloudName);
  for (std::size_t p = static_cast<std::size_t>(first + stride); p < pieces.size();
       p += static_cast<std::size_t>(stride)) {
    const ParticleCloud piece = readCloudVtp(pieces[p], cloudName);
    if (piece.attributes() != cloud.attributes()) {
      throw Error(pieces[p].string() + ": cloud '" + cloudName + "' has other attributes than in " +
                  pieces[static_cast<std::size_t>(first)].string());
    }
    cloud.append(piece);
  }
  return cloud;
}

}  // namespace sphcast
