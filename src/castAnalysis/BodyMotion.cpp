#include "castAnalysis/BodyMotion.h"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "castAnalysis/GnuplotPlot.h"
#include "core/Error.h"
#include "post/FunctionObject.h"

namespace sphcast {

BodyMotion::BodyMotion(const std::string& name, const Dictionary& dict,
                       const AnalysisContext& context)
    : CastAnalysis(name, dict, context, {"body"}),
      body_(dict.get<std::string>("body")),
      bodyAt_(dict.location("body")) {
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
         "fluidForceZ,forceX,forceY,forceZ,atEndStop,travel,velocity,fluidForce\n";
  double stopTime = -1, largestForce = 0, largestForceTime = 0;
  for (const auto& row : rows) {
    if (row.size() < 14) continue;
    const Vector travel(row[1], row[2], row[3]), velocity(row[4], row[5], row[6]),
        fluidForce(row[7], row[8], row[9]);
    for (std::size_t c = 0; c < 14; ++c) csv << (c ? "," : "") << row[c];
    csv << ',' << travel.dot(direction) << ',' << velocity.dot(direction) << ','
        << fluidForce.dot(direction) << '\n';
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
       << " s (" << name_ << "/" << body_ << ".csv).\n";
  section.markdown = text.str();
  if (drawPlot(travel, context_.caseRoot / "postProcessing" / travelPng)) {
    section.images.push_back(travelPng);
  }
  if (drawPlot(force, context_.caseRoot / "postProcessing" / forcePng))
    section.images.push_back(forcePng);
  return section;
}

}  // namespace sphcast
