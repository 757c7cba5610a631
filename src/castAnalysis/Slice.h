#pragma once

#include <string>
#include <vector>

#include "castAnalysis/CastAnalysis.h"

namespace sphcast {

// type slice: the particles within half a thickness of a plane, as the paper's 9 mm slice
// through the cone's axis (Figs. 13, 14), for ParaView and as a picture for the report.
//
//   section
//   {
//       type        slice;
//       point       (0 0 0);  normal (0 1 0);   // the plane
//       thickness   0.009;                       // m
//       field       solidFraction;               // colours the clouds that have it (others grey)
//       range       (0 1);                       // optional: the field's range at that time
//       clouds      (metal mold);                // optional: every cloud of the time and of
//                                                // constant/particles
//       times       latest;                      // optional: latest | all (the selected times)
//       show        (0.25 0.3 0.4);              // optional, with times all: the written times
//                                                // nearest these in the report, besides the last
//       pixel       0.0003;                      // optional, m: a tenth of the finest
//                                                // spacing, or less for 800 pixels across
//       style       field;                       // optional: field | particles
//   }
//
// Writes postProcessing/<name>/<time>/<cloud>.vtp (the sliced particles with all their fields)
// and <time>/<field>.png, seen along -normal with "up" the plane's direction closest to +z (+y
// for a plane normal to z), coloured blue (low) - cyan - green - yellow - red (high), with a
// colour bar along the bottom. style field: the field on the plane itself, interpolated from the
// particles within a kernel's reach (PlaneInterpolation.h), each body (metal, mold) out to where
// its kernel sum falls through 1/2, its free surface, and outlined in dark grey: the casting as
// a continuous body. style particles: each particle within half the thickness a disc of 0.45 of
// its spacing, nearest the plane on top (to look at the particles themselves). Drawn pixel by
// pixel into a VTK image and written with VTK's PNG writer: no rendering, no display, no gnuplot
// needed. The report shows the latest time's picture, after those of `show`
// (a press's or a filling's stages, as the paper's Fig. 17).
class Slice : public CastAnalysis {
 public:
  Slice(const std::string& name, const Dictionary& dict, const AnalysisContext& context);

  void add(const WrittenTime& time) override;
  ReportSection finish() override;

 private:
  void draw(const WrittenTime& time);

  Vector point_, normal_, right_, up_;
  Real thickness_ = 0, pixel_ = 0;
  bool particles_ = false;  // style particles: discs, not the interpolated field
  std::string field_;
  bool fixedRange_ = false;
  double low_ = 0, high_ = 1;
  std::vector<std::string> clouds_;
  bool allTimes_ = false;
  std::vector<std::string> drawn_;  // PNGs, relative to postProcessing/
  std::vector<std::string> captions_;
  std::vector<double> drawnTimes_;
  std::vector<double> show_;
  const WrittenTime* pending_ = nullptr;
  WrittenTime latest_;
};

}  // namespace sphcast
