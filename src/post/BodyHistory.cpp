#include "post/BodyHistory.h"

#include <algorithm>
#include <cstdio>

#include "bodies/RigidBody.h"
#include "core/Error.h"

namespace sphcast {

BodyHistory::BodyHistory(const std::string& name, const Dictionary& dict,
                         const FunctionObjectContext& context)
    : FunctionObject(name, dict, context, {"bodies"}, Clouds::many) {
  std::vector<std::string> names;
  for (const RigidBody* body : context.bodies) names.push_back(body->settings().name);
  if (!dict.found("bodies")) {
    bodies_ = context.bodies;
    return;
  }
  for (const std::string& wanted : dict.get<std::vector<std::string>>("bodies")) {
    const auto found = std::find(names.begin(), names.end(), wanted);
    if (found == names.end()) {
      std::string present;
      for (const std::string& body : names) present += " " + body;
      throw DictionaryError(
          dict.location("bodies"),
          "unknown body '" + wanted + "' in " + dict.name() + "; the run has: (" + present + " )");
    }
    bodies_.push_back(context.bodies[static_cast<std::size_t>(found - names.begin())]);
  }
}

void BodyHistory::sample(double time) {
  for (const RigidBody* body : bodies_) {
    std::ofstream& file = openOutput(
        body->settings().name + ".dat",
        "# time displacement(x y z) m  velocity(x y z) m/s  fluidForce(x y z) N  force(x y z) N  "
        "atEndStop  appliedForce(x y z) N\n");
    char row[640];
    const Vector d = body->displacement(), v = body->velocity(), f = body->fluidForce(),
                 total = body->force(), applied = body->settings().appliedForceAt(time);
    std::snprintf(row, sizeof row,
                  "%.10g %.10g %.10g  %.10g %.10g %.10g  %.10g %.10g %.10g  %.10g %.10g %.10g  %d  "
                  "%.10g %.10g %.10g",
                  d[0], d[1], d[2], v[0], v[1], v[2], f[0], f[1], f[2], total[0], total[1],
                  total[2], body->atEndStop() ? 1 : 0, applied[0], applied[1], applied[2]);
    writeRow(file, time, row);
  }
}

}  // namespace sphcast
