#include "post/SamplingFunctionObjects.h"

#include <cmath>
#include <sstream>

#include "post/FluidSampling.h"

namespace sphcast {

namespace {

const Dimensions length{{0, 1, 0, 0, 0, 0, 0}};

std::string locationText(const Vector& x) {
  std::ostringstream text;
  text.precision(10);
  text << '(' << x.x() << ' ' << x.y() << ' ' << x.z() << ')';
  return text.str();
}

// A radius from the dictionary, or the flow's support radius; positive either way.
Real radiusOrSupport(const Dictionary& dict, const std::string& key,
                     const FunctionObjectContext& context) {
  if (dict.found(key)) {
    const Real radius = dict.get<Real>(key, length);
    if (!(radius > 0)) {
      throw DictionaryError(dict.location(key), "'" + key + "' must be positive in " + dict.name());
    }
    return radius;
  }
  if (!(context.supportRadius > 0)) {
    throw DictionaryError(dict.location(), "no flow model gives a support radius: set '" + key +
                                               "' in " + dict.name());
  }
  return context.supportRadius;
}

std::vector<Vector> readLocations(const Dictionary& dict, const std::string& key) {
  auto locations = dict.get<std::vector<Vector>>(key);
  if (locations.empty()) {
    throw DictionaryError(dict.location(key), "'" + key + "' lists no location in " + dict.name());
  }
  return locations;
}

}  // namespace

Probes::Probes(const std::string& name, const Dictionary& dict,
               const FunctionObjectContext& context)
    : FunctionObject(name, dict, context, {"fields", "probeLocations", "supportRadius"}),
      fields_(dict.get<std::vector<std::string>>("fields")),
      locations_(readLocations(dict, "probeLocations")),
      supportRadius_(radiusOrSupport(dict, "supportRadius", context)) {
  if (fields_.empty()) {
    throw DictionaryError(dict.location("fields"), "'fields' lists no field in " + dict.name());
  }
  for (const std::string& field : fields_) {
    if (cloud().hasScalarField(field) || cloud().hasVectorField(field)) continue;
    std::string valid;
    for (const auto& [fieldName, values] : cloud().scalarFields()) valid += " " + fieldName;
    for (const auto& [fieldName, values] : cloud().vectorFields()) valid += " " + fieldName;
    throw DictionaryError(dict.location("fields"), "unknown field '" + field + "' of cloud '" +
                                                       cloud().name() + "' in " + dict.name() +
                                                       "; valid fields are: (" + valid + " )");
  }
  for (std::size_t k = 0; k < locations_.size(); ++k) {
    header_ += "# Probe " + std::to_string(k) + ' ' + locationText(locations_[k]) + '\n';
  }
  header_ += "# Shepard interpolation over particles of cloud " + cloud().name() +
             " within h = " + formatSample(supportRadius_) +
             " m; nan: no particle within h\n#        Probe";
  for (std::size_t k = 0; k < locations_.size(); ++k) header_ += "  " + std::to_string(k);
  header_ += "\n#         Time\n";
}

void Probes::sample(double time) {
  const ShepardInterpolation interpolation(cloud(), supportRadius_, communicator());
  for (const std::string& field : fields_) {
    std::ofstream& file = openOutput(field, header_);
    std::string values;
    for (const Vector& location : locations_) {
      values += "  ";
      values += cloud().hasScalarField(field)
                    ? formatSample(interpolation.scalar(cloud().scalarField(field), location))
                    : formatSample(interpolation.vector(cloud().vectorField(field), location));
    }
    writeRow(file, time, values);
  }
}

SurfaceHeights::SurfaceHeights(const std::string& name, const Dictionary& dict,
                               const FunctionObjectContext& context)
    : FunctionObject(name, dict, context, {"locations", "radius"}),
      locations_(readLocations(dict, "locations")),
      radius_(radiusOrSupport(dict, "radius", context)) {
  if (!(context.gravity.norm() > 0)) {
    throw DictionaryError(dict.location(),
                          "type surfaceHeights needs gravity (constant/g) to "
                          "know which way is up, in " +
                              dict.name());
  }
  up_ = -context.gravity.normalized();
  for (std::size_t k = 0; k < locations_.size(); ++k) {
    header_ += "# Height " + std::to_string(k) + ' ' + locationText(locations_[k]) + '\n';
  }
  header_ += "# highest particle of cloud " + cloud().name() + " within " + formatSample(radius_) +
             " m of the vertical through each location, plus half its " + "spacing, as x . " +
             locationText(up_) + "; nan: no fluid there\n#         Time\n";
}

void SurfaceHeights::sample(double time) {
  std::ofstream& file = openOutput("height", header_);
  std::string values;
  for (const Vector& location : locations_) {
    values += "  " + formatSample(surfaceHeight(cloud(), up_, location, radius_, communicator()));
  }
  writeRow(file, time, values);
}

FluidFront::FluidFront(const std::string& name, const Dictionary& dict,
                       const FunctionObjectContext& context)
    : FunctionObject(name, dict, context, {"direction"}),
      direction_(dict.get<Vector>("direction")) {
  if (!(direction_.norm() > 0)) {
    throw DictionaryError(dict.location("direction"),
                          "'direction' must not be zero in " + dict.name());
  }
  direction_.normalize();
  header_ = "# largest x . " + locationText(direction_) + " of cloud " + cloud().name() +
            ", plus half its spacing\n#         Time\n";
}

void FluidFront::sample(double time) {
  std::ofstream& file = openOutput("front", header_);
  writeRow(file, time, "  " + formatSample(fluidFront(cloud(), direction_, communicator())));
}

}  // namespace sphcast
