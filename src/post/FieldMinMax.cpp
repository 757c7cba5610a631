#include "post/FieldMinMax.h"

#include <cstdint>
#include <limits>
#include <vector>

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
    // looked up once: a look-up per particle cost more than the rest of a dam break's step
    const Vector* vectors = isVector ? cloud().vectorField(field).data() : nullptr;
    const Real* scalars = isVector ? nullptr : cloud().scalarField(field).data();
    const auto value = [&](std::size_t i) -> double {
      return isVector ? double(vectors[i].norm()) : double(scalars[i]);
    };
    std::ofstream& file = openOutput(
        field, "# " + std::string(isVector ? "magnitude of " : "") + field + " of cloud " +
                   cloud().name() +
                   ": min, max, and the positions of the particles holding them\n" +
                   "#         Time          min          max   xMin yMin zMin   xMax yMax zMax\n");
    const std::size_t owned = cloud().ownedSize();
    std::size_t lowest = 0;
    std::size_t highest = 0;
    for (std::size_t i = 1; i < owned; ++i) {
      if (value(i) < value(lowest)) lowest = i;
      if (value(i) > value(highest)) highest = i;
    }
    const Communicator& comm = communicator();
    if (comm.sum(static_cast<std::int64_t>(owned)) == 0) {
      writeRow(file, time, "  nan  nan  nan nan nan  nan nan nan");
      continue;
    }
    // over the ranks: the extreme values, and the place of the first rank's particle holding each
    const double inf = std::numeric_limits<double>::infinity();
    const double low = comm.min(owned > 0 ? value(lowest) : inf);
    const double high = comm.max(owned > 0 ? value(highest) : -inf);
    std::vector<double> holder{owned > 0 && value(lowest) == low ? double(comm.rank()) : inf,
                               owned > 0 && value(highest) == high ? double(comm.rank()) : inf};
    comm.min(holder);
    std::vector<double> places(6, 0.0);
    for (int a = 0; a < 3; ++a) {
      if (holder[0] == comm.rank()) places[static_cast<std::size_t>(a)] = x[lowest][a];
      if (holder[1] == comm.rank()) places[static_cast<std::size_t>(3 + a)] = x[highest][a];
    }
    comm.sum(places);
    const Vector lowAt(static_cast<Real>(places[0]), static_cast<Real>(places[1]),
                       static_cast<Real>(places[2]));
    const Vector highAt(static_cast<Real>(places[3]), static_cast<Real>(places[4]),
                        static_cast<Real>(places[5]));
    writeRow(file, time,
             "  " + formatSample(low) + "  " + formatSample(high) + positionColumns(lowAt) +
                 positionColumns(highAt));
  }
}

}  // namespace sphcast
