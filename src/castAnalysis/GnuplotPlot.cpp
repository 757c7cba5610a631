#include "castAnalysis/GnuplotPlot.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/AtomicFile.h"
#include "core/Log.h"

namespace sphcast {

namespace {

// A string inside gnuplot's double quotes.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + '"';
}

// A path inside the shell's single quotes.
bool gnuplotFound() {
  static const bool found = std::system("command -v gnuplot > /dev/null 2>&1") == 0;
  return found;
}

}  // namespace

std::string shellQuoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

bool drawPlot(const Plot& plot, const std::filesystem::path& png) {
  std::ostringstream script;
  script << "# drawn by castPostProcess; rerun with: gnuplot " << png.stem().string() << ".gp\n"
         << "set terminal pngcairo size 900,560 noenhanced\n"
         << "set output " << quoted(png.filename().string()) << '\n'
         << "set datafile separator comma\n"
         << "set datafile missing 'nan'\n"
         << "set title " << quoted(plot.title) << '\n'
         << "set xlabel " << quoted(plot.xLabel) << '\n'
         << "set ylabel " << quoted(plot.yLabel) << '\n'
         << "set grid\nset key outside right top\n"
         << "plot ";
  bool first = true;
  for (const PlotSeries& series : plot.series) {
    script << (first ? "" : ", \\\n     ") << quoted(plot.csv.filename().string())
           << " skip 1 using 1:" << series.column << " with linespoints pointsize 0.5 title "
           << quoted(series.title);
    first = false;
  }
  for (const PlotLevel& level : plot.levels) {
    script << (first ? "" : ", \\\n     ") << level.value << " with lines dashtype 2 title "
           << quoted(level.title);
    first = false;
  }
  script << '\n';
  const auto scriptFile = png.parent_path() / (png.stem().string() + ".gp");
  writeFileAtomically(scriptFile, script.str());
  if (!gnuplotFound()) {
    static bool told = false;
    if (!told) {
      warning(
          "gnuplot is not on the PATH: the plots' scripts (.gp) are written, not drawn "
          "(apt-get install gnuplot-nox)");
      told = true;
    }
    return false;
  }
  std::filesystem::remove(png);  // a picture of an earlier run must not pass for this one
  // gnuplot runs in the plot's folder, so the script names files without their paths
  const std::string command = "cd " + shellQuoted(png.parent_path().string()) + " && gnuplot " +
                              shellQuoted(scriptFile.filename().string()) + " > /dev/null 2>&1";
  if (std::system(command.c_str()) != 0 || !std::filesystem::exists(png)) {
    warning("gnuplot could not draw " + png.string() + " (run " + scriptFile.string() +
            " by hand to see why)");
    return false;
  }
  return true;
}

}  // namespace sphcast
