#pragma once

#include <vtkSmartPointer.h>

#include <array>
#include <string>
#include <vector>

#include "castAnalysis/CastAnalysis.h"

class vtkPolyData;

namespace sphcast {

// type view: a 3D picture of the casting, as the paper's Figs. 13, 14 and 18 show one. The
// metal's surface is reconstructed from its particles: the level 1/2 of their kernel sum
//
//   c(x) = sum_j V_j W(|x - x_j|, h)      (1 inside, 1/2 half a spacing beyond the last particles)
//
// on voxels of half a spacing (VoxelOccupancy.h), contoured by VTK's flying edges, and coloured by
// a field interpolated onto it (sum_j V_j f_j W / c). A clip plane cuts the casting open: the
// cut face shows the field inside. The voids enclosed in the metal (the surface's closed parts
// whose orientation is the opposite of the casting's: their metal is outside them) are drawn in
// magenta through the casting, then translucent: shrinkage cavities and gas pockets where they
// are, with their volumes in the report. The last particle to reach the solidus is marked with
// a black ball. Rendered by VTK, off-screen.
//
//   casting
//   {
//       type        view;
//       cloud       metal;
//       field       solidusTime;          // colours the surface
//       range       (0 12);               // optional: else the field's range over the times
//       clip        ((0 0 0) (0 1 0));    // optional: (point normal), the normal's side cut away
//       from        (1 -2 1);             // optional: where the camera looks from (a
//                                         // direction); facing the cut when clipped
//       size        (1000 750);           // optional: pixels
//       times       latest;               // latest | all: a frame per time, and <name>.gif
//       show        (0.2 0.4);            // optional, with times all: frames in the report
//   }
//
// Writes postProcessing/<name>/<time>/<field>.png and, with times all, <name>.gif (the frames
// animated, 4 a second, by ffmpeg where it is installed: Debian's VTK has no video writer); the
// report gives the surface's enclosed volume against the
// particles' sum of m / rho (the reconstruction's check) and the last particle to freeze.
// VTK renders through X: without a display (DISPLAY unset or unreachable) the view is skipped
// with a note and nothing else changes; castPostProcess under `xvfb-run -a` (Debian package
// xvfb) draws it on a machine without one, as the tutorials' Allrun do.
class CastingView : public CastAnalysis {
 public:
  CastingView(const std::string& name, const Dictionary& dict, const AnalysisContext& context);

  void add(const WrittenTime& time) override;
  ReportSection finish() override;

 private:
  struct Frame {
    std::string timeName;
    double time = 0;
    vtkSmartPointer<vtkPolyData> surface;     // the casting's outer surface (and any droplets)
    vtkSmartPointer<vtkPolyData> cavities;    // the walls of the voids enclosed in it
    std::vector<double> cavityVolumes;        // m^3, largest first
    double enclosed = 0, particleVolume = 0;  // m^3: the metal inside the surface, sum m / rho
    bool marked = false;                      // a last particle to freeze
    Vector lastToFreeze = Vector::Zero();
    double lastTime = 0;
    Real spacing = 0;
  };
  void build(const WrittenTime& time);
  void splitCavities(vtkPolyData* contour, Frame& frame);
  // Renders every frame with one camera; false without a display.
  bool render();
  void animate();

  std::string cloud_, field_;
  bool fixedRange_ = false;
  double low_ = 0, high_ = 1;
  bool clipped_ = false;
  Vector clipPoint_ = Vector::Zero(), clipNormal_ = Vector::UnitY();
  Vector from_ = Vector(1, -2, 1);
  std::array<int, 2> size_{1000, 750};
  bool allTimes_ = false;
  std::vector<double> show_;
  std::vector<Frame> frames_;
  WrittenTime latest_;
  std::vector<std::string> drawn_;  // PNGs, relative to postProcessing/
  std::string animation_;           // the GIF, relative to postProcessing/, or why there is none
};

}  // namespace sphcast
