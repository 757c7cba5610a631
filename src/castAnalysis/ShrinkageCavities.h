#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "castAnalysis/CastAnalysis.h"
#include "castAnalysis/VoxelOccupancy.h"

namespace sphcast {

// type shrinkageCavities: the voids inside the casting (VoxelOccupancy.h).
//
//   cavities
//   {
//       type        shrinkageCavities;
//       cloud       metal;
//       molds       (mold);          // optional: the clouds that bound the casting (of the time
//                                    // folder, or constant/particles); every other cloud by
//                                    default
//       voxelSize   0.0015;          // optional, m: half the metal's spacing by default
//       threshold   0.5;             // optional: void where metal + molds fill less than this
//   }
//
// At every selected time, on voxels over the metal and molds: the enclosed voids (not joined to
// the outside: a pipe open to the top surface is a sink, not a cavity), the casting's envelope
// (voxels not joined to the outside where the metal fills more than the molds: the casting as a
// foundry would fill it, cavities included) and the shrinkage the mass balance asks for,
// sum m / rho_s(T) at the first selected time less now. Writes
//   postProcessing/<name>/cavities.csv     time, count, total and largest volume, envelope,
//                                          the mass balance's shrinkage
//   postProcessing/<name>/<time>/cavities.csv   each cavity at the last time: volume, centroid,
//                                          extent
//   postProcessing/<name>/<time>/occupancy.vti  the voxels (metal, molds, cavity number) for
//                                          ParaView (contour metal at the threshold)
class ShrinkageCavities : public CastAnalysis {
 public:
  ShrinkageCavities(const std::string& name, const Dictionary& dict,
                    const AnalysisContext& context);

  void add(const WrittenTime& time) override;
  ReportSection finish() override;

 private:
  std::string cloud_;
  std::vector<std::string> molds_;
  Real voxelSize_ = 0;
  double threshold_ = 0.5;
  std::string rows_;
  double firstBalance_ = -1, firstEnvelope_ = -1;
  struct Last {
    std::string timeName;
    double time = 0, balance = 0, envelope = 0, expected = 0;
    std::string cavities;  // the per-cavity CSV
    std::size_t count = 0;
    double total = 0, largest = 0;
    Vector largestAt = Vector::Zero();
  } last_;
  std::optional<VoxelOccupancy> lastOccupancy_;
};

}  // namespace sphcast
