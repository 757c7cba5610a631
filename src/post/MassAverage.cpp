#include "post/MassAverage.h"
#include "particles/FieldNames.h"

#include <vector>

namespace sphcast {

MassAverage::MassAverage(const std::string& name, const Dictionary& dict,
                         const FunctionObjectContext& context)
    : FunctionObject(name, dict, context, {"fields"}),
      fields_(dict.get<std::vector<std::string>>("fields")) {
  if (fields_.empty()) {
    throw DictionaryError(dict.location("fields"), "'fields' lists no field in " + dict.name());
  }
  if (!cloud().hasScalarField(field::mass)) {
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
  const auto& mass = cloud().scalarField(field::mass);
  for (const std::string& field : fields_) {
    std::ofstream& file = openOutput(field, "# " + field + " of cloud " + cloud().name() +
                                                ", weighted by mass: sum m f / sum m\n" +
                                                "#         Time         mean\n");
    const auto& value = cloud().scalarField(field);
    double weighted = 0;
    double total = 0;
    // in particle order: no thread dependence (a decomposed run: its owned particles, then the
    // sums over the ranks)
    for (std::size_t i = 0; i < cloud().ownedSize(); ++i) {
      weighted += double(mass[i]) * double(value[i]);
      total += double(mass[i]);
    }
    if (communicator().size() > 1) {
      std::vector<double> sums{weighted, total};
      communicator().sum(sums);
      weighted = sums[0];
      total = sums[1];
    }
    writeRow(file, time, "  " + (total > 0 ? formatSample(weighted / total) : std::string("nan")));
  }
}

}  // namespace sphcast
