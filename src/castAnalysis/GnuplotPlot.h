#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sphcast {

// A PNG line plot of columns of a CSV file (one header line, comma-separated, first column the
// x axis), drawn by gnuplot as OpenFOAM's foamMonitor does: the script is written beside the
// picture (<png without .png>.gp), so a user can restyle and rerun it. Without gnuplot on the
// PATH the script is still written and drawPlot says so once.
struct PlotSeries {
  int column;  // 1-based, as gnuplot counts
  std::string title;
};

struct PlotLevel {  // a horizontal line, e.g. the liquidus on a cooling curve
  double value;
  std::string title;
};

struct Plot {
  std::string title;
  std::string xLabel = "time (s)";
  std::string yLabel;
  std::filesystem::path csv;
  std::vector<PlotSeries> series;
  std::vector<PlotLevel> levels;
};

// Returns true when the PNG was drawn.
bool drawPlot(const Plot& plot, const std::filesystem::path& png);

// text in single quotes for sh, its own single quotes escaped: for the commands castPostProcess
// runs (gnuplot, ffmpeg)
std::string shellQuoted(const std::string& text);

}  // namespace sphcast
