#include "castAnalysis/ShrinkageCavities.h"

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataWriter.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "castAnalysis/VoxelOccupancy.h"
#include "core/AtomicFile.h"
#include "core/Error.h"
#include "core/Log.h"
#include "io/VtpCloud.h"
#include "particles/FieldNames.h"

namespace sphcast {

namespace {

// The voxels of the last time for ParaView: metal and molds fill (contour metal at the threshold).
void writeOccupancy(const VoxelOccupancy& occupancy, const std::filesystem::path& file) {
  vtkNew<vtkImageData> image;
  const auto [nx, ny, nz] = occupancy.counts();
  image->SetDimensions(nx, ny, nz);
  image->SetOrigin(double(occupancy.origin().x()), double(occupancy.origin().y()),
                   double(occupancy.origin().z()));
  const double voxel = double(occupancy.voxel());
  image->SetSpacing(voxel, voxel, voxel);
  for (const auto& [channel, label] : {std::pair{0, "metal"}, std::pair{1, "molds"}}) {
    vtkNew<vtkFloatArray> array;
    array->SetName(label);
    array->SetNumberOfValues(vtkIdType(occupancy.size()));
    for (std::size_t v = 0; v < occupancy.size(); ++v) {
      array->SetValue(vtkIdType(v), occupancy.channel(channel)[v]);
    }
    image->GetPointData()->AddArray(array);
  }
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetFileName((file.string() + ".tmp").c_str());
  writer->SetInputData(image);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOn();  // base64: well-formed XML, which every ParaView opens
  writer->SetCompressorTypeToZLib();
  if (writer->Write() != 1) throw Error("could not write " + file.string());
  std::filesystem::rename(file.string() + ".tmp", file);
}

}  // namespace

ShrinkageCavities::ShrinkageCavities(const std::string& name, const Dictionary& dict,
                                     const AnalysisContext& context)
    : CastAnalysis(name, dict, context, {"cloud", "molds", "voxelSize", "threshold"}) {
  cloud_ = readCloud();
  if (dict.found("molds")) {
    molds_ = dict.get<std::vector<std::string>>("molds");
  } else {
    for (const auto& other : context.clouds) {
      if (other != cloud_) molds_.push_back(other);
    }
    for (const auto& other : constantCloudNames()) {
      if (other != cloud_ && std::find(molds_.begin(), molds_.end(), other) == molds_.end()) {
        molds_.push_back(other);
      }
    }
  }
  for (const auto& mold : molds_) {
    const bool inTimes =
        std::find(context.clouds.begin(), context.clouds.end(), mold) != context.clouds.end();
    const auto file = context.caseRoot / "constant" / "particles" / (mold + ".vtp");
    if (!inTimes && !std::filesystem::exists(file)) {
      throw DictionaryError(dict.found("molds") ? dict.location("molds") : dict.location(),
                            "no mold cloud '" + mold + "' in the time folders or " + file.string() +
                                ", for " + dict.name());
    }
  }
  voxelSize_ = dict.getOrDefault<Real>("voxelSize", 0);
  threshold_ = dict.getOrDefault<double>("threshold", 0.5);
  if (dict.found("voxelSize") && !(voxelSize_ > 0)) {
    throw DictionaryError(dict.location("voxelSize"),
                          "'voxelSize' must be positive in " + dict.name());
  }
  if (!(threshold_ > 0 && threshold_ < 1)) {
    throw DictionaryError(dict.location("threshold"),
                          "'threshold' must lie in (0, 1) in " + dict.name());
  }
  if (!(context.supportRadius > 0)) {
    throw DictionaryError(dict.location(), dict.name() +
                                               " needs h (supportRadius of "
                                               "system/sphSchemes) for the voxels' fill");
  }
}

void ShrinkageCavities::add(const WrittenTime& time) {
  const ParticleCloud* metal = time.find(cloud_);
  if (!metal || metal->size() == 0) return;
  std::vector<const ParticleCloud*> molds;
  for (const auto& name : molds_) {
    const ParticleCloud* mold = cloudAt(time, name);
    if (!mold) throw Error("no mold cloud '" + name + "' at time " + time.folder.name);
    molds.push_back(mold);
  }
  Vector lower = metal->positions().front(), upper = lower;
  for (const Vector& x : metal->positions()) {
    lower = lower.cwiseMin(x);
    upper = upper.cwiseMax(x);
  }
  for (const ParticleCloud* cloud : molds) {
    for (const Vector& x : cloud->positions()) {
      lower = lower.cwiseMin(x);
      upper = upper.cwiseMax(x);
    }
  }
  Real voxel = voxelSize_;
  if (voxel <= 0) {
    const auto spacing = metal->attributes().find("spacing");
    voxel = spacing != metal->attributes().end() ? Real(spacing->second / 2)
                                                 : context_.supportRadius / 6;
  }
  VoxelOccupancy occupancy(lower, upper, voxel, context_.supportRadius, context_.dimension);
  occupancy.add(*metal, 0);
  for (const ParticleCloud* cloud : molds) occupancy.add(*cloud, 1);
  const std::vector<EnclosedVoid> voids = enclosedVoids(occupancy, threshold_);

  // the envelope: not joined to the outside, the metal filling more than the molds
  const auto& metalFill = occupancy.channel(0);
  const auto& moldFill = occupancy.channel(1);
  std::size_t filled = 0;
  for (std::size_t v = 0; v < occupancy.size(); ++v) {
    if (metalFill[v] >= moldFill[v] && double(metalFill[v] + moldFill[v]) >= threshold_) ++filled;
  }
  double cavityVolume = 0;
  for (const EnclosedVoid& group : voids) cavityVolume += group.volume;
  const double envelope = double(filled) * occupancy.voxelVolume() + cavityVolume;
  // the mass balance: sum m / rho_s(T), rho_s(T) of the material's table (a frozen particle's
  // restDensity is the one it froze with: what the flow holds it to, not what the metal is)
  double balance = 0;
  const auto material = context_.materials.find(cloud_);
  const bool table = material != context_.materials.end() && material->second.density &&
                     metal->hasScalarField(field::T);
  // setCastFields' start has volume and rho, the solver's times mass
  const bool mass = metal->hasScalarField(field::mass) ||
                    (metal->hasScalarField(field::volume) && metal->hasScalarField(field::rho));
  if (mass && (table || metal->hasScalarField(field::restDensity))) {
    for (std::size_t i = 0; i < metal->size(); ++i) {
      const double rhoS = table
                              ? (*material->second.density)(double(metal->scalarField(field::T)[i]))
                              : double(metal->scalarField(field::restDensity)[i]);
      const double m =
          metal->hasScalarField(field::mass)
              ? double(metal->scalarField(field::mass)[i])
              : double(metal->scalarField(field::volume)[i] * metal->scalarField(field::rho)[i]);
      balance += m / rhoS;
    }
  }
  if (firstBalance_ < 0) {
    firstBalance_ = balance;
    firstEnvelope_ = envelope;
  }
  const double expected = firstBalance_ - balance;
  if (rows_.empty()) {
    rows_ =
        "time,cavities,cavityVolume,largestCavity,envelopeVolume,envelopeChange,"
        "massBalanceShrinkage\n";
  }
  rows_ += formatNumber(time.folder.value, 12) + "," + std::to_string(voids.size()) + "," +
           formatNumber(cavityVolume, 10) + "," +
           formatNumber(voids.empty() ? 0.0 : voids[0].volume, 10) + "," +
           formatNumber(envelope, 10) + "," + formatNumber(envelope - firstEnvelope_, 10) + "," +
           formatNumber(expected, 10) + "\n";

  last_ = Last{};
  last_.timeName = time.folder.name;
  last_.time = time.folder.value;
  last_.balance = balance;
  last_.envelope = envelope;
  last_.expected = expected;
  last_.count = voids.size();
  last_.total = cavityVolume;
  std::ostringstream csv;
  csv << "cavity,volume,centroidX,centroidY,centroidZ,minX,minY,minZ,maxX,maxY,maxZ\n";
  for (std::size_t g = 0; g < voids.size(); ++g) {
    const EnclosedVoid& v = voids[g];
    csv << g + 1 << ',' << formatNumber(v.volume, 10);
    for (const Vector* x : {&v.centroid, &v.lower, &v.upper}) {
      csv << ',' << formatNumber((*x).x(), 8) << ',' << formatNumber((*x).y(), 8) << ','
          << formatNumber((*x).z(), 8);
    }
    csv << '\n';
  }
  last_.cavities = csv.str();
  if (!voids.empty()) {
    last_.largest = voids[0].volume;
    last_.largestAt = voids[0].centroid;
  }
  lastOccupancy_ = std::move(occupancy);  // its image is written once, in finish()
}

ReportSection ShrinkageCavities::finish() {
  ReportSection section;
  if (last_.timeName.empty()) {
    section.markdown = "No selected time holds cloud " + cloud_ + ".\n";
    return section;
  }
  const auto out = folder();
  writeFileAtomically(out / "cavities.csv", rows_);
  std::filesystem::create_directories(out / last_.timeName);
  writeFileAtomically(out / last_.timeName / "cavities.csv", last_.cavities);
  writeOccupancy(*lastOccupancy_, out / last_.timeName / "occupancy.vti");
  info() << "    " << name_ << ": wrote " << (out / "cavities.csv").string() << " and "
         << (out / last_.timeName / "occupancy.vti").string() << '\n';
  const bool twoD = context_.dimension == 2;
  const double toUnit = twoD ? 1e6 : 1e6;  // m^3 -> cm^3 (m^2 -> mm^2 in 2D)
  const char* unit = twoD ? "mm^2" : "cm^3";
  std::ostringstream text;
  text << "At time " << last_.timeName << ": " << last_.count << " enclosed cavit"
       << (last_.count == 1 ? "y" : "ies") << ", " << formatNumber(last_.total * toUnit, 4) << ' '
       << unit;
  if (last_.count > 0) {
    text << "; the largest " << formatNumber(last_.largest * toUnit, 4) << ' ' << unit << " at ("
         << formatNumber(last_.largestAt.x(), 4) << ' ' << formatNumber(last_.largestAt.y(), 4)
         << ' ' << formatNumber(last_.largestAt.z(), 4) << ") m";
  }
  text << ".\n\n- The mass balance of rho_s asks for " << formatNumber(last_.expected * toUnit, 4)
       << ' ' << unit << " of shrinkage since the first time ("
       << formatNumber(100 * last_.expected / firstBalance_, 3) << " % of the metal's volume);\n"
       << "- the casting's envelope (cavities included) changed by "
       << formatNumber((last_.envelope - firstEnvelope_) * toUnit, 4) << ' ' << unit
       << " (a sink at the open surface shows here), the enclosed cavities hold "
       << formatNumber(last_.total * toUnit, 4) << ' ' << unit << ";\n"
       << "- the rest, "
       << formatNumber((last_.expected + (last_.envelope - firstEnvelope_) - last_.total) * toUnit,
                       4)
       << ' ' << unit
       << ", is contraction no particle shows (frozen metal keeps its place) and the voxels' "
          "error.\n\nVoxels of "
       << formatNumber(double(lastOccupancy_->voxel()), 3) << " m; void where metal and molds fill "
       << "less than " << threshold_ << " (cavities.csv by time; " << last_.timeName
       << "/cavities.csv each cavity; " << last_.timeName << "/occupancy.vti for ParaView).\n";
  section.markdown = text.str();
  return section;
}

}  // namespace sphcast
