#include "post/MassAverage.h"

namespace sphcast {

MassAverage::MassAverage(const std::string& name, const Dictionary& dict,
                         const FunctionObjectContext& context)
    : FunctionObject(name, dict, context, {"fields"}),
      fields_(dict.get<std::vector<std::string>>("fields")) {
  if (fields_.empty()) {
    throw DictionaryError(dict.location("fields"), "'fields' lists no field in " + dict.name());
  }
  if (!cloud().hasScalarField("mass")) {
    throw DictionaryError(
        dict.location("type"),
        "cloud '" + cloud().name() + "' has no field 'mass' to weigh by in " + dict.name());
  }
  for (const std::string& field : fields_) {
    if (!cloud().hasScalarField(field)) {
      throw DictionaryError(dict.location("fields"), "unknown scalar field '" + field +
                                                         "' of cloud '" + cloud().name() + "' in " +
                                                         dict.name());
    }
  }
}

void MassAverage::sample(double time) {
  const auto& mass = cloud().scalarField("mass");
  for (const std::string& field : fields_) {
    std::ofstream& file = openOutput(field, "# " + field + " of cloud " + cloud().name() +
                                                ", weighted by mass: sum m f / sum m\n" +
                                                "#         Time         mean\n");
    const auto& value = cloud().scalarField(field);
    double weighted = 0;
    double total = 0;
    for (std::size_t i = 0; i < value.size(); ++i) {  // in particle order: no thread dependence
      weighted += double(mass[i]) * double(value[i]);
      total += double(mass[i]);
    }
    writeRow(file, time, "  " + (total > 0 ? formatSample(weighted / total) : std::string("nan")));
  }
}

}  // namespace sphcast
