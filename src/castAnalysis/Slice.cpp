#include "castAnalysis/Slice.h"

#include <vtkAutoInit.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "castAnalysis/PlaneInterpolation.h"
#include "core/Error.h"
#include "core/Log.h"
#include "io/VtpCloud.h"

VTK_MODULE_INIT(vtkRenderingFreeType);  // the colour bar's labels: FreeType, no display

namespace sphcast {

namespace {

// blue - cyan - green - yellow - red over [0, 1]
std::array<unsigned char, 3> colourOf(double f) {
  static const double stops[5][3] = {
      {0, 0, 255}, {0, 255, 255}, {0, 200, 0}, {255, 255, 0}, {255, 0, 0}};
  f = std::clamp(f, 0.0, 1.0) * 4;
  const int k = std::min(3, int(f));
  const double w = f - k;
  std::array<unsigned char, 3> c{};
  for (int i = 0; i < 3; ++i) {
    c[i] = static_cast<unsigned char>(std::lround((1 - w) * stops[k][i] + w * stops[k + 1][i]));
  }
  return c;
}

// Writes `text` in black into the RGB picture, its baseline row at y, starting at x (align 0),
// centred on x (align 1) or ending at x (align 2); with VTK's FreeType text renderer, which
// needs no display.
void drawText(unsigned char* pixels, int width, int height, const std::string& text, int x, int y,
              int align) {
  vtkTextRenderer* renderer = vtkTextRenderer::GetInstance();
  if (renderer == nullptr || text.empty()) return;
  vtkNew<vtkTextProperty> style;
  style->SetFontFamilyToArial();
  style->SetFontSize(16);
  style->SetColor(0, 0, 0);
  vtkNew<vtkImageData> rendered;
  int size[2] = {0, 0};
  if (!renderer->RenderString(style, text, rendered, size, 72)) return;
  const int left = x - (align == 1 ? size[0] / 2 : align == 2 ? size[0] : 0);
  const auto* alpha = static_cast<const unsigned char*>(rendered->GetScalarPointer());
  int dims[3];
  rendered->GetDimensions(dims);
  const int components = rendered->GetNumberOfScalarComponents();
  for (int j = 0; j < size[1] && j < dims[1]; ++j) {
    for (int i = 0; i < size[0] && i < dims[0]; ++i) {
      const int px = left + i, py = y + j;
      if (px < 0 || py < 0 || px >= width || py >= height) continue;
      const double a = alpha[(std::size_t(j) * dims[0] + i) * components + components - 1] / 255.0;
      unsigned char* p = pixels + (std::size_t(py) * width + px) * 3;
      for (int c = 0; c < 3; ++c) p[c] = static_cast<unsigned char>(std::lround((1 - a) * p[c]));
    }
  }
}

}  // namespace

Slice::Slice(const std::string& name, const Dictionary& dict, const AnalysisContext& context)
    : CastAnalysis(name, dict, context,
                   {"point", "normal", "thickness", "field", "range", "clouds", "times", "show",
                    "pixel", "style"}) {
  point_ = dict.get<Vector>("point");
  normal_ = dict.get<Vector>("normal");
  if (!(normal_.norm() > 0)) {
    throw DictionaryError(dict.location("normal"), "'normal' of " + dict.name() + " is zero");
  }
  normal_.normalize();
  thickness_ = dict.get<Real>("thickness");
  if (!(thickness_ > 0)) {
    throw DictionaryError(dict.location("thickness"),
                          "'thickness' must be positive in " + dict.name());
  }
  field_ = dict.get<std::string>("field");
  fixedRange_ = readRange(low_, high_);
  clouds_ = dict.getOrDefault<std::vector<std::string>>("clouds", {});  // empty: every cloud
  allTimes_ = readPictureTimes(show_);
  pixel_ = dict.getOrDefault<Real>("pixel", 0);
  particles_ = dict.getChoiceOrDefault("style", {"field", "particles"}, "field") == "particles";
  // up: +z projected into the plane (+y when the plane is normal to z)
  Vector up = Vector::UnitZ() - normal_.dot(Vector::UnitZ()) * normal_;
  if (up.norm() < 1e-6) up = Vector::UnitY() - normal_.dot(Vector::UnitY()) * normal_;
  up_ = up.normalized();
  right_ = up_.cross(normal_);   // seen along -normal: right x up = normal
  if (context.dimension == 2) {  // a 2D case is drawn in its own plane
    normal_ = Vector::UnitZ();
    up_ = Vector::UnitY();
    right_ = Vector::UnitX();
  }
}

void Slice::add(const WrittenTime& time) {
  if (allTimes_) {
    draw(time);
  } else {
    latest_ = time;  // drawn in finish()
  }
}

void Slice::draw(const WrittenTime& time) {
  struct Dot {
    Real u, v, depth, radius;
    std::array<unsigned char, 3> colour;
  };
  constexpr std::array<unsigned char, 3> grey{150, 150, 150}, outline{60, 60, 60};
  std::vector<Dot> dots;
  const auto out = folder() / time.folder.name;
  std::filesystem::create_directories(out);
  double low = std::numeric_limits<double>::max(), high = -low;
  Real finest = std::numeric_limits<Real>::max();
  std::vector<std::pair<const ParticleCloud*, std::vector<std::size_t>>> sliced;
  for (const std::string& name : clouds_.empty() ? cloudsAt(time) : clouds_) {
    const ParticleCloud* cloud = cloudAt(time, name);
    if (!cloud) continue;
    std::vector<std::size_t> inside;
    for (std::size_t i = 0; i < cloud->size(); ++i) {
      if (std::abs((cloud->positions()[i] - point_).dot(normal_)) <= thickness_ / 2 ||
          context_.dimension == 2) {
        inside.push_back(i);
      }
    }
    if (cloud->hasScalarField(field_) && !fixedRange_) {
      for (const std::size_t i : inside) {
        low = std::min(low, double(cloud->scalarField(field_)[i]));
        high = std::max(high, double(cloud->scalarField(field_)[i]));
      }
    }
    const auto spacing = cloud->attributes().find("spacing");
    if (spacing != cloud->attributes().end()) finest = std::min(finest, Real(spacing->second));
    // the sliced particles with all their fields
    ParticleCloud part(cloud->name());
    part.resize(inside.size());
    part.attributes() = cloud->attributes();
    for (std::size_t k = 0; k < inside.size(); ++k)
      part.positions()[k] = cloud->positions()[inside[k]];
    for (const auto& [field, values] : cloud->scalarFields()) {
      auto& copy = part.addScalarField(field);
      for (std::size_t k = 0; k < inside.size(); ++k) copy[k] = values[inside[k]];
    }
    for (const auto& [field, values] : cloud->vectorFields()) {
      auto& copy = part.addVectorField(field);
      for (std::size_t k = 0; k < inside.size(); ++k) copy[k] = values[inside[k]];
    }
    for (const auto& [field, values] : cloud->idFields()) {
      auto& copy = part.addIdField(field);
      for (std::size_t k = 0; k < inside.size(); ++k) copy[k] = values[inside[k]];
    }
    writeCloudVtp(part, out / (name + ".vtp"));
    sliced.emplace_back(cloud, std::move(inside));
  }
  if (fixedRange_) {
    low = low_;
    high = high_;
  }
  if (!(high > low)) high = low + 1;
  if (finest == std::numeric_limits<Real>::max()) finest = context_.supportRadius / 3;
  for (const auto& [cloud, inside] : sliced) {
    const auto spacing = cloud->attributes().find("spacing");
    const Real radius =
        Real(0.45) * (spacing != cloud->attributes().end() ? Real(spacing->second) : finest);
    const bool coloured = cloud->hasScalarField(field_);
    for (const std::size_t i : inside) {
      const Vector d = cloud->positions()[i] - point_;
      const auto colour =
          coloured ? colourOf((double(cloud->scalarField(field_)[i]) - low) / (high - low)) : grey;
      dots.push_back({d.dot(right_), d.dot(up_), std::abs(d.dot(normal_)), radius, colour});
    }
  }
  if (dots.empty()) {
    warning("slice " + name_ + ": no particle within " + formatNumber(thickness_ / 2, 4) +
            " m of the plane at time " + time.folder.name);
    return;
  }
  // the picture's extent: the sliced particles' discs, or, drawn as a field, half a spacing beyond
  // them, where the bodies' surfaces are
  const Real support = context_.supportRadius > 0 ? context_.supportRadius : 3 * finest;
  Real uMin = dots[0].u, uMax = uMin, vMin = dots[0].v, vMax = vMin;
  for (const Dot& dot : dots) {
    const Real reach = particles_ ? dot.radius : Real(0.5) * finest;
    uMin = std::min(uMin, dot.u - reach);
    uMax = std::max(uMax, dot.u + reach);
    vMin = std::min(vMin, dot.v - reach);
    vMax = std::max(vMax, dot.v + reach);
  }
  // a tenth of the finest spacing, finer where that leaves the picture under 800 pixels across
  const Real pixel =
      pixel_ > 0 ? pixel_ : std::min(finest / 10, std::max(uMax - uMin, vMax - vMin) / 800);
  const int bar = 16, margin = 4, labels = 22;  // the colour bar, its labels below it
  const int width = int(std::ceil((uMax - uMin) / pixel)) + 2 * margin;
  const int height = int(std::ceil((vMax - vMin) / pixel)) + 2 * margin + bar + margin + labels;
  if (double(width) * height > 6e7) {
    throw Error("slice " + name_ + ": a picture of " + std::to_string(width) + " x " +
                std::to_string(height) + " pixels; give a larger 'pixel'");
  }
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* pixels = static_cast<unsigned char*>(image->GetScalarPointer());
  std::fill(pixels, pixels + std::size_t(width) * height * 3, 255);
  const auto put = [&](int x, int y, const std::array<unsigned char, 3>& c) {
    unsigned char* p = pixels + (std::size_t(y) * width + x) * 3;
    p[0] = c[0];
    p[1] = c[1];
    p[2] = c[2];
  };
  const int base = labels + bar + 2 * margin;  // rows below the picture: the colour bar
  if (particles_) {
    // farthest from the plane first: the nearest particles end on top
    std::sort(dots.begin(), dots.end(),
              [](const Dot& a, const Dot& b) { return a.depth > b.depth; });
    for (const Dot& dot : dots) {
      const Real cx = (dot.u - uMin) / pixel + margin, cy = (dot.v - vMin) / pixel + base;
      const Real r = dot.radius / pixel;
      for (int y = std::max(0, int(cy - r)); y <= std::min(height - 1, int(cy + r) + 1); ++y) {
        for (int x = std::max(0, int(cx - r)); x <= std::min(width - 1, int(cx + r) + 1); ++x) {
          const Real dx = x + Real(0.5) - cx, dy = y + Real(0.5) - cy;
          if (dx * dx + dy * dy <= r * r) put(x, y, dot.colour);
        }
      }
    }
  } else {
    // the field interpolated onto the plane's pixels, each body to where its kernel sum is 1/2,
    // its outline a pixel wide in dark grey (the casting against the mold and the air)
    PlaneGrid grid;
    grid.right = right_;
    grid.up = up_;
    grid.normal = normal_;
    grid.pixel = pixel;
    grid.width = width - 2 * margin;
    grid.height = height - base - margin;
    grid.origin = point_ + (uMin + Real(0.5) * pixel) * right_ + (vMin + Real(0.5) * pixel) * up_;
    PlaneInterpolation plane(grid, context_.dimension);
    for (std::size_t k = 0; k < sliced.size(); ++k) {
      plane.add(*sliced[k].first, int(k), field_, support);
    }
    for (int y = 0; y < grid.height; ++y) {
      for (int x = 0; x < grid.width; ++x) {
        const int owner = plane.owner(x, y);
        if (owner < 0) continue;
        const bool edge = x == 0 || y == 0 || x == grid.width - 1 || y == grid.height - 1 ||
                          plane.owner(x - 1, y) != owner || plane.owner(x + 1, y) != owner ||
                          plane.owner(x, y - 1) != owner || plane.owner(x, y + 1) != owner;
        const double value = plane.value(x, y);
        put(x + margin, y + base,
            edge                ? outline
            : std::isnan(value) ? grey
                                : colourOf((value - low) / (high - low)));
      }
    }
  }
  for (int x = margin; x < width - margin; ++x) {
    const auto c = colourOf(double(x - margin) / std::max(1, width - 2 * margin - 1));
    for (int y = margin + labels; y < margin + labels + bar; ++y) put(x, y, c);
  }
  drawText(pixels, width, height, formatNumber(low, 4), margin, margin, 0);
  drawText(pixels, width, height, field_ + fieldUnit(field_), width / 2, margin, 1);
  drawText(pixels, width, height, formatNumber(high, 4), width - margin, margin, 2);
  vtkNew<vtkPNGWriter> writer;
  const auto png = out / (field_ + ".png");
  writer->SetFileName(png.string().c_str());
  writer->SetInputData(image);
  writer->Write();
  if (writer->GetErrorCode() != 0) throw Error("could not write " + png.string());
  drawn_.push_back(name_ + "/" + time.folder.name + "/" + field_ + ".png");
  drawnTimes_.push_back(time.folder.value);
  captions_.push_back("time " + time.folder.name + ": " + field_ + " from " + formatNumber(low, 4) +
                      " (blue) to " + formatNumber(high, 4) + " (red), grey: clouds without it" +
                      (particles_ ? "; the particles within " + formatNumber(thickness_ * 5e2, 4) +
                                        " mm of the plane"
                                  : "; interpolated onto the plane, each body out to its surface "
                                    "(kernel sum 1/2), outlined") +
                      "; " + std::to_string(width) + " x " + std::to_string(height) +
                      " pixels of " + formatNumber(pixel * 1e3, 4) + " mm");
  info() << "    " << name_ << ": wrote " << png.string() << '\n';
}

ReportSection Slice::finish() {
  if (!allTimes_ && !latest_.folder.name.empty()) draw(latest_);
  ReportSection section;
  section.markdown = "A slice " + formatNumber(thickness_ * 1e3, 4) + " mm thick through (" +
                     formatNumber(point_.x(), 4) + " " + formatNumber(point_.y(), 4) + " " +
                     formatNumber(point_.z(), 4) + ") normal to (" + formatNumber(normal_.x(), 4) +
                     " " + formatNumber(normal_.y(), 4) + " " + formatNumber(normal_.z(), 4) +
                     "):\n";
  if (drawn_.empty()) return section;
  // in the one-page report: the drawn times nearest those of `show`, then the latest; the others
  // are listed by folder
  const std::vector<std::size_t> shown = shownPictures(drawnTimes_, show_);
  for (const std::size_t k : shown) {
    section.markdown += "- " + captions_[k] + "\n";
    section.images.push_back(drawn_[k]);
  }
  if (drawn_.size() > shown.size()) {
    section.markdown += "- and " + std::to_string(drawn_.size() - shown.size()) + " other time" +
                        (drawn_.size() - shown.size() > 1 ? "s" : "") + " in " + name_ +
                        "/<time>/" + field_ + ".png\n";
  }
  return section;
}

}  // namespace sphcast
