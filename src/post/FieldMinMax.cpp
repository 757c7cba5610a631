#include "post/FieldMinMax.h"

namespace sphcast {

namespace {

std::string positionColumns(const Vector& x) {
  return "  " + formatSample(double(x.x())) + ' ' + formatSample(double(x.y())) + ' ' +
         formatSample(double(x.z()));
}

}  // namespace

FieldMinMax::FieldMinMax(const std::string& name, const Dictionary& dict,
                         const FunctionObjectContext& context)
    : FunctionObject(name, dict, context, {"fields"}),
      fields_(dict.get<std::vector<std::string>>("fields")) {
  if (fields_.empty()) {
    throw DictionaryError(dict.location("fields"), "'fields' lists no field in " + dict.name());
  }
  for (const std::string& field : fields_) {
    if (!cloud().hasScalarField(field) && !cloud().hasVectorField(field)) {
      throw DictionaryError(dict.location("fields"), "unknown field '" + field + "' of cloud '" +
                                                         cloud().name() + "' in " + dict.name());
    }
  }
}

void FieldMinMax::sample(double time) {
  const auto& x = cloud().positions();
  for (const std::string& field : fields_) {
    const bool isVector = cloud().hasVectorField(field);
    const auto value = [&](std::size_t i) -> double {
      return isVector ? double(cloud().vectorField(field)[i].norm())
                      : double(cloud().scalarField(field)[i]);
    };
    std::ofstream& file = openOutput(
        field, "# " + std::string(isVector ? "magnitude of " : "") + field + " of cloud " +
                   cloud().name() +
                   ": min, max, and the positions of the particles holding them\n" +
                   "#         Time          min          max   xMin yMin zMin   xMax yMax zMax\n");
    if (x.empty()) {
      writeRow(file, time, "  nan  nan  nan nan nan  nan nan nan");
      continue;
    }
    std::size_t lowest = 0;
    std::size_t highest = 0;
    for (std::size_t i = 1; i < x.size(); ++i) {
      if (value(i) < value(lowest)) lowest = i;
      if (value(i) > value(highest)) highest = i;
    }
    writeRow(file, time,
             "  " + formatSample(value(lowest)) + "  " + formatSample(value(highest)) +
                 positionColumns(x[lowest]) + positionColumns(x[highest]));
  }
}

}  // namespace sphcast
