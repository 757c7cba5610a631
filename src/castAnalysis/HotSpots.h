#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "castAnalysis/CastAnalysis.h"

namespace sphcast {

// type hotSpots: where the liquid is cut off from the rest as the casting freezes, the regions
// that will shrink without feeding.
//
//   hotSpots
//   {
//       type                 hotSpots;
//       cloud                metal;
//       feedingSolidFraction 0.5;   // optional: metal below this solid fraction still feeds
//                                   // (0.5 by default: the solver's frozenSolidFraction)
//   }
//
// At every selected time the feeding metal (f_s < feedingSolidFraction) is split into connected
// regions (particles closer than 1.5 spacings are joined: the lattice's face and edge
// neighbours). The largest is the feeding path; every other is isolated: a hot spot. A hot spot
// is followed by its particles' ids from write to write: it closed between the write before it
// was first seen isolated and that write, and froze before the first write without it.
// Writes postProcessing/<name>/hotSpots.csv (time, feeding particles, regions, isolated ones and
// their volume, sum m / rho) and hotSpotList.csv (each hot spot: closed by, volume then,
// centroid, last seen), and the last region to freeze (the last feeding metal seen) to the report.
// Written times only: a pocket that closes and freezes between two writes is not seen.
class HotSpots : public CastAnalysis {
 public:
  HotSpots(const std::string& name, const Dictionary& dict, const AnalysisContext& context);

  void add(const WrittenTime& time) override;
  ReportSection finish() override;

 private:
  struct Spot {
    double closedAfter = 0, closedBy = 0;  // the writes either side of its closing
    double volume = 0;                     // when first seen isolated
    Vector centroid = Vector::Zero();
    double lastSeen = 0;
    std::size_t particles = 0;
    std::set<std::int64_t> ids;  // of the last sighting
  };

  std::string cloud_;
  double feeding_ = 0.5;
  std::string rows_;
  std::vector<Spot> spots_;
  std::vector<std::size_t> open_;  // spots seen at the last write
  double previousTime_ = -1;
  // the last feeding metal seen
  double lastFeedingTime_ = -1;
  std::size_t lastFeedingParticles_ = 0;
  Vector lastFeedingCentroid_ = Vector::Zero();
};

}  // namespace sphcast
