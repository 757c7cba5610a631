#include "castAnalysis/BodyMotion.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "castAnalysis/GnuplotPlot.h"
#include "core/Error.h"
#include "particles/FieldNames.h"
#include "post/FunctionObject.h"

namespace sphcast {

BodyMotion::BodyMotion(const std::string& name, const Dictionary& dict,
                       const AnalysisContext& context)
    : CastAnalysis(name, dict, context, {"body", "gap"}),
      body_(dict.get<std::string>("body")),
      bodyAt_(dict.location("body")) {
  if (dict.found("gap")) {
    const Dictionary& gap = dict.subDict("gap");
    gap.checkKeys({"cloud", "faceStart", "floorPoint", "area", "volumeBelow"});
    gap_ = Gap{gap.get<std::string>("cloud"), gap.get<Vector>("faceStart"),
               gap.get<Vector>("floorPoint"), gap.get<double>("area"),
               gap.getOrDefault<double>("volumeBelow", 0)};
    if (std::find(context.clouds.begin(), context.clouds.end(), gap_->cloud) ==
        context.clouds.end()) {
      throw DictionaryError(gap.location("cloud"),
                            "'" + gap_->cloud + "' is not a cloud of the case's first time");
    }
    if (!(gap_->area > 0)) {
      throw DictionaryError(gap.location("area"), "'area' must be positive in " + gap.name());
    }
    if (!(gap_->volumeBelow >= 0)) {
      throw DictionaryError(gap.location("volumeBelow"),
                            "'volumeBelow' must not be negative in " + gap.name());
    }
  }
  const auto folder = context.caseRoot / "postProcessing" / "dynamicBodies";
  bool found = false;
  if (std::filesystem::exists(folder)) {
    for (const auto& start : std::filesystem::directory_iterator(folder)) {
      found = found || std::filesystem::exists(start.path() / (body_ + ".dat"));
    }
  }
  if (!found) {
    throw DictionaryError(bodyAt_, "body '" + body_ + "' has no history in " + folder.string() +
                                       "/<startTime>/" + body_ +
                                       ".dat: is it a body of constant/dynamicBodies, and has "
                                       "sphCastFoam run?");
  }
}

void BodyMotion::add(const WrittenTime& time) {
  if (!gap_) return;
  const ParticleCloud* cloud = time.find(gap_->cloud);
  if (!cloud) return;
  const auto& mass = cloud->scalarField(field::mass);
  const auto& rho = cloud->scalarField(field::rho);
  positions_.assign(cloud->positions().begin(), cloud->positions().end());
  volumes_.resize(cloud->size());
  for (std::size_t i = 0; i < cloud->size(); ++i) volumes_[i] = double(mass[i]) / double(rho[i]);
  lastTime_ = time.folder.name;
  lastTimeValue_ = time.folder.value;
}

std::string BodyMotion::gapReport(const std::vector<std::vector<double>>& rows,
                                  const Vector& direction) const {
  if (lastTime_.empty()) return "No time selected has the cloud " + gap_->cloud + ".\n";
  Vector travel = Vector::Zero();
  for (const auto& row : rows) {
    if (row.size() < 4 || row[0] > lastTimeValue_ * (1 + 1e-9) + 1e-12) break;
    travel = Vector(row[1], row[2], row[3]);
  }
  const Vector up = -direction;  // from the floor towards the punch's face
  const double gap = (gap_->faceStart + travel - gap_->floorPoint).dot(up);
  double above = 0, below = 0;
  for (std::size_t i = 0; i < positions_.size(); ++i) {
    ((positions_[i] - gap_->floorPoint).dot(up) < 0 ? below : above) += volumes_[i];
  }
  const double spread = (above + below - gap_->volumeBelow) / gap_->area;
  std::ostringstream text;
  text.precision(4);
  text << "The gap at t = " << lastTime_ << " s: the punch's face " << gap * 1000
       << " mm above the floor. The " << gap_->cloud << " (" << (above + below) * 1e6
       << " cm^3) holds " << below * 1e6 << " cm^3 below the floor";
  if (gap_->volumeBelow > 0) {
    text << " (" << 100 * below / gap_->volumeBelow << " % of the " << gap_->volumeBelow * 1e6
         << " cm^3 there)";
  }
  text << " and " << above * 1e6 << " cm^3 above: " << above / gap_->area * 1000
       << " mm over the area under the punch; with the space below full, the volume balance "
       << "gives " << spread * 1000 << " mm.\n";
  return text.str();
}

ReportSection BodyMotion::finish() {
  const auto rows = readFunctionObjectSeries(context_.caseRoot, "dynamicBodies", body_ + ".dat");
  ReportSection section;
  if (rows.empty()) {
    section.markdown = "Body " + body_ + ": no rows in its history.\n";
    return section;
  }
  // the main direction of travel: the final travel's, else z
  const auto& last = rows.back();
  Vector direction(last[1], last[2], last[3]);
  direction = direction.norm() > 0 ? Vector(direction.normalized()) : Vector(Vector::UnitZ());
  std::ostringstream csv;
  csv.precision(10);
  csv << "time,travelX,travelY,travelZ,velocityX,velocityY,velocityZ,fluidForceX,fluidForceY,"
         "fluidForceZ,forceX,forceY,forceZ,atEndStop,travel,velocity,fluidForce,appliedForce\n";
  double stopTime = -1, largestForce = 0, largestForceTime = 0;
  double largestLoad = 0, largestLoadTime = 0;  // the press's (histories since issue #53)
  for (const auto& row : rows) {
    if (row.size() < 14) continue;
    const Vector travel(row[1], row[2], row[3]), velocity(row[4], row[5], row[6]),
        fluidForce(row[7], row[8], row[9]);
    for (std::size_t c = 0; c < 14; ++c) csv << (c ? "," : "") << row[c];
    csv << ',' << travel.dot(direction) << ',' << velocity.dot(direction) << ','
        << fluidForce.dot(direction) << ',';
    if (row.size() >= 17) {
      const Vector applied(row[14], row[15], row[16]);
      csv << applied.dot(direction) << '\n';
      if (applied.norm() > largestLoad) {
        largestLoad = applied.norm();
        largestLoadTime = row[0];
      }
    } else {
      csv << "nan\n";
    }
    if (row[13] != 0 && stopTime < 0) stopTime = row[0];
    if (fluidForce.norm() > largestForce) {
      largestForce = fluidForce.norm();
      largestForceTime = row[0];
    }
  }
  const auto file = folder() / (body_ + ".csv");
  writeRowsByTime(body_ + ".csv", csv.str());
  Plot travel{"body " + body_ + ": travel and velocity along its travel",
              "time (s)",
              "travel (m), velocity (m/s)",
              file,
              {{15, "travel"}, {16, "velocity"}},
              {}};
  Plot force{"body " + body_ + ": the metal's force along its travel",
             "time (s)",
             "force (N)",
             file,
             {{17, "force of the metal"}},
             {}};
  if (largestLoad > 0) {
    force.title = "body " + body_ + ": the metal's force and the press's load along its travel";
    force.series.push_back({18, "the press's load"});
  }
  const std::string travelPng = name_ + "/" + body_ + "Travel.png";
  const std::string forcePng = name_ + "/" + body_ + "Force.png";
  std::ostringstream text;
  text.precision(4);
  text << "Body " << body_ << ": travelled " << Vector(last[1], last[2], last[3]).norm() * 1000
       << " mm by t = " << last[0] << " s";
  if (stopTime >= 0) {
    text << ", at its end stop from t = " << stopTime << " s";
  } else {
    text << ", never at an end stop";
  }
  text << "; the largest force of the metal " << largestForce << " N at t = " << largestForceTime
       << " s";
  if (largestLoad > 0) {
    text << "; the press's largest load " << largestLoad << " N at t = " << largestLoadTime
         << " s, " << Vector(last[14], last[15], last[16]).norm() << " N at the end";
  }
  text << " (" << name_ << "/" << body_ << ".csv).\n";
  if (gap_) text << '\n' << gapReport(rows, direction);
  section.markdown = text.str();
  if (drawPlot(travel, context_.caseRoot / "postProcessing" / travelPng)) {
    section.images.push_back(travelPng);
  }
  if (drawPlot(force, context_.caseRoot / "postProcessing" / forcePng))
    section.images.push_back(forcePng);
  return section;
}

}  // namespace sphcast
