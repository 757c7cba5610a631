#pragma once

#include <vector>

#include "core/Real.h"
#include "particles/FieldNames.h"
#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// The fill time of a casting: when each metal particle first touched the mold, the field
// `fillTime` of the fluid (-1 until then; castPostProcess's solidificationMaps maps it).
// "Touched": a wall particle nearer than 1.75 of the fluid's spacing. A fluid particle against a
// wall lies 1 to 1.7 spacings from the wall's first layer (that layer half a spacing behind the
// surface; the particle half a spacing in front at rest, up to about 1.2 just after an impact:
// tests/unit/sph/FillTimeTest.cpp); the next fluid layer at rest lies two spacings away.
//
// Call after every neighbour search, with the time the positions belong to; it reads the
// fluid-wall pairs the flow requested. Only particles that have not touched yet are looked at,
// so a filled casting costs one pass over a field.
class FillTime {
 public:
  static constexpr const char* field = field::fillTime;

  // Adds the field (-1) to the fluid unless it has it (a restart keeps its own).
  FillTime(ParticleCloud& fluid, std::vector<const ParticleCloud*> walls);

  void record(const Neighbourhood& neighbourhood, double time);

 private:
  ParticleCloud& fluid_;
  std::vector<const ParticleCloud*> walls_;
  Real contact_;
};

}  // namespace sphcast
