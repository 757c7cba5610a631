#include "castAnalysis/CastingView.h"

#include <X11/Xlib.h>
#include <vtkActor.h>
#include <vtkAutoInit.h>
#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSphereSource.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>

#include "castAnalysis/GnuplotPlot.h"
#include "castAnalysis/VoxelOccupancy.h"
#include "core/Error.h"
#include "core/Log.h"
#include "particles/FieldNames.h"
#include "sph/ParticleVolumes.h"

VTK_MODULE_INIT(vtkRenderingOpenGL2);
VTK_MODULE_INIT(vtkRenderingFreeType);

namespace sphcast {

namespace {

// The X display the views render on: one connection, opened at the first view and kept for the
// process, handed to VTK's render windows. VTK's own connection aborts the process where it
// fails, and an X server resets when its last client leaves, refusing connections meanwhile
// (measured under the test suite: "bad X server connection ... Aborting" when a first look
// closed its connection, and the second of two views not drawn when the first closed its own).
// nullptr where none opens (DISPLAY unset or unreachable).
Display* viewDisplay() {
  struct Closer {
    void operator()(Display* display) const { XCloseDisplay(display); }
  };
  static const std::unique_ptr<Display, Closer> display([]() -> Display* {
    const char* name = std::getenv("DISPLAY");
    return name == nullptr || *name == '\0' ? nullptr : XOpenDisplay(nullptr);
  }());
  return display.get();
}

}  // namespace

CastingView::CastingView(const std::string& name, const Dictionary& dict,
                         const AnalysisContext& context)
    : CastAnalysis(name, dict, context,
                   {"cloud", "field", "range", "clip", "from", "size", "times", "show"}) {
  if (context.dimension != 3) {
    throw DictionaryError(dict.location("type"),
                          "'" + name + "' in " + dict.name() +
                              ": a view draws a 3D casting; a 2D case's picture is a slice");
  }
  cloud_ = readCloud();
  field_ = dict.get<std::string>("field");
  fixedRange_ = readRange(low_, high_);
  if (dict.found("clip")) {
    const auto clip = dict.get<std::vector<Vector>>("clip");
    if (clip.size() != 2 || !(clip[1].norm() > 0)) {
      throw DictionaryError(dict.location("clip"),
                            "'clip' of " + dict.name() +
                                " must be (point normal) with a non-zero normal, e.g. "
                                "((0 0 0) (0 1 0))");
    }
    clipped_ = true;
    clipPoint_ = clip[0];
    clipNormal_ = clip[1].normalized();
  }
  if (clipped_) {  // facing the cut, from a little above and aside
    const Vector side = Vector::UnitZ().cross(clipNormal_);
    from_ = clipNormal_ + Real(0.45) * Vector::UnitZ() + Real(0.3) * side;
    if (!(from_.norm() > 0)) from_ = clipNormal_;
  }
  if (dict.found("from")) {
    from_ = dict.get<Vector>("from");
    if (!(from_.norm() > 0)) {
      throw DictionaryError(dict.location("from"), "'from' of " + dict.name() + " is zero");
    }
  }
  if (dict.found("size")) {
    const auto size = dict.get<std::vector<long>>("size");
    if (size.size() != 2 || size[0] < 64 || size[1] < 64 || size[0] > 8192 || size[1] > 8192) {
      throw DictionaryError(
          dict.location("size"),
          "'size' of " + dict.name() + " must be (width height) in pixels, each 64 to 8192");
    }
    size_ = {int(size[0]), int(size[1])};
  }
  allTimes_ = readPictureTimes(show_);
}

void CastingView::add(const WrittenTime& time) {
  if (allTimes_) {
    build(time);
  } else {
    latest_ = time;  // built in finish()
  }
}

// The metal's surface at one time: the kernel sum's level 1/2 on voxels of half a spacing, the
// field interpolated onto it; clipped by min(c, 1/2 - s / voxel), s the distance past the clip
// plane, which puts the surface on the plane where the metal is cut and closes it there.
void CastingView::build(const WrittenTime& time) {
  const ParticleCloud* cloud = cloudAt(time, cloud_);
  if (cloud == nullptr || cloud->size() == 0) return;
  const auto spacingEntry = cloud->attributes().find("spacing");
  if (spacingEntry == cloud->attributes().end()) {
    throw Error("view " + name_ + ": cloud '" + cloud_ + "' at time " + time.folder.name +
                " has no spacing attribute");
  }
  Frame frame;
  frame.timeName = time.folder.name;
  frame.time = time.folder.value;
  frame.spacing = Real(spacingEntry->second);
  const Real h = context_.supportRadius > 0 ? context_.supportRadius : 3 * frame.spacing;
  const Real voxel = frame.spacing / 2;
  Vector lower = cloud->positions()[0], upper = lower;
  for (const Vector& x : cloud->positions()) {
    lower = lower.cwiseMin(x);
    upper = upper.cwiseMax(x);
  }
  VoxelOccupancy occupancy(lower, upper, voxel, h, 3);
  occupancy.add(*cloud, 0);
  const bool coloured = cloud->hasScalarField(field_);
  if (coloured) occupancy.addField(*cloud, field_);
  const auto counts = occupancy.counts();
  vtkNew<vtkImageData> image;
  image->SetDimensions(counts[0], counts[1], counts[2]);
  image->SetOrigin(double(occupancy.origin().x()), double(occupancy.origin().y()),
                   double(occupancy.origin().z()));
  image->SetSpacing(double(voxel), double(voxel), double(voxel));
  vtkNew<vtkFloatArray> fill, values;
  fill->SetName("fill");
  values->SetName(field_.c_str());
  fill->SetNumberOfValues(vtkIdType(occupancy.size()));
  values->SetNumberOfValues(vtkIdType(occupancy.size()));
  const auto& c = occupancy.channel(0);
  for (std::size_t v = 0; v < occupancy.size(); ++v) {
    float f = c[v];
    if (clipped_) {
      const double past = double((occupancy.centre(v) - clipPoint_).dot(clipNormal_));
      f = std::min(f, float(0.5 - past / double(voxel)));
    }
    fill->SetValue(vtkIdType(v), f);
    values->SetValue(vtkIdType(v),
                     coloured && c[v] > 1e-6f ? occupancy.fieldSum()[v] / c[v] : 0.0f);
  }
  image->GetPointData()->SetScalars(fill);
  image->GetPointData()->AddArray(values);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(image);
  contour->SetValue(0, 0.5);
  contour->ComputeNormalsOn();
  contour->InterpolateAttributesOn();
  contour->Update();
  splitCavities(contour->GetOutput(), frame);
  const std::vector<Real> volume = particleVolumes(*cloud, 3);
  for (std::size_t j = 0; j < cloud->size(); ++j) {
    if (!clipped_ || (cloud->positions()[j] - clipPoint_).dot(clipNormal_) < 0) {
      frame.particleVolume += double(volume[j]);
    }
  }
  if (cloud->hasScalarField(field::solidusTime)) {
    const auto& solidus = cloud->scalarField(field::solidusTime);
    const auto last = std::max_element(solidus.begin(), solidus.end());
    const bool allSolid =
        std::all_of(solidus.begin(), solidus.end(), [](Real t) { return t >= 0; });
    if (allSolid) {
      frame.marked = true;
      frame.lastToFreeze = cloud->positions()[std::size_t(last - solidus.begin())];
      frame.lastTime = double(*last);
    }
  }
  frames_.push_back(std::move(frame));
}

// The contour's closed parts: each part's signed volume (the divergence theorem over its
// triangles, oriented alike by flying edges) has the casting's sign for a body of metal and the
// opposite one for a void inside the metal.
void CastingView::splitCavities(vtkPolyData* contour, Frame& frame) {
  vtkNew<vtkPolyDataConnectivityFilter> regions;
  regions->SetInputData(contour);
  regions->SetExtractionModeToAllRegions();
  regions->ColorRegionsOn();
  regions->Update();
  vtkPolyData* labelled = regions->GetOutput();
  const int count = regions->GetNumberOfExtractedRegions();
  vtkDataArray* region = labelled->GetPointData()->GetArray("RegionId");
  std::vector<double> volume(std::size_t(std::max(count, 0)), 0.0);
  vtkPoints* points = labelled->GetPoints();
  for (vtkIdType c = 0; region != nullptr && c < labelled->GetNumberOfCells(); ++c) {
    const vtkIdType* ids = nullptr;
    vtkIdType n = 0;
    labelled->GetCellPoints(c, n, ids);
    if (n != 3) continue;
    Eigen::Vector3d x[3];
    for (int k = 0; k < 3; ++k) points->GetPoint(ids[k], x[k].data());
    volume[std::size_t(region->GetTuple1(ids[0]))] += x[0].dot(x[1].cross(x[2])) / 6;
  }
  const auto largest = std::max_element(
      volume.begin(), volume.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
  vtkNew<vtkPolyDataConnectivityFilter> bodies, voids;
  for (auto* filter : {bodies.Get(), voids.Get()}) {
    filter->SetInputData(contour);
    filter->SetExtractionModeToSpecifiedRegions();
  }
  bool anyVoid = false;
  for (int r = 0; r < count; ++r) {
    const bool isVoid = largest != volume.end() && volume[std::size_t(r)] * *largest < 0;
    (isVoid ? voids.Get() : bodies.Get())->AddSpecifiedRegion(r);
    if (isVoid) {
      anyVoid = true;
      frame.cavityVolumes.push_back(std::abs(volume[std::size_t(r)]));
    }
  }
  std::sort(frame.cavityVolumes.rbegin(), frame.cavityVolumes.rend());
  // the metal's volume, the voids' walls subtracting: the reconstruction's check against the
  // particles' own
  double total = 0;
  for (const double v : volume) total += v;
  frame.enclosed = std::abs(total);
  bodies->Update();
  frame.surface = bodies->GetOutput();
  frame.cavities = vtkSmartPointer<vtkPolyData>::New();
  if (anyVoid) {
    voids->Update();
    frame.cavities = voids->GetOutput();
  }
}

bool CastingView::render() {
  Display* display = viewDisplay();
  if (display == nullptr) return false;
  double low = fixedRange_ ? low_ : std::numeric_limits<double>::max();
  double high = fixedRange_ ? high_ : -std::numeric_limits<double>::max();
  double bounds[6] = {1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
  for (const Frame& frame : frames_) {
    double b[6];
    frame.surface->GetBounds(b);
    if (frame.surface->GetNumberOfPoints() == 0) continue;
    for (int a = 0; a < 3; ++a) {
      bounds[2 * a] = std::min(bounds[2 * a], b[2 * a]);
      bounds[2 * a + 1] = std::max(bounds[2 * a + 1], b[2 * a + 1]);
    }
    if (auto* array = frame.surface->GetPointData()->GetArray(field_.c_str());
        array != nullptr && !fixedRange_) {
      double r[2];
      array->GetRange(r);
      low = std::min(low, r[0]);
      high = std::max(high, r[1]);
    }
  }
  if (!(low <= high)) low = high = 0;
  if (!(high > low)) high = low + 1;
  if (!(bounds[0] <= bounds[1])) {  // no surface at any time: a unit box to look at
    for (int a = 0; a < 3; ++a) bounds[2 * a] = 0, bounds[2 * a + 1] = 1;
  }
  vtkNew<vtkLookupTable> colours;  // blue - cyan - green - yellow - red, as the slices
  colours->SetHueRange(0.667, 0.0);
  colours->SetNumberOfTableValues(256);
  colours->SetTableRange(low, high);
  colours->Build();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetLookupTable(colours);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray(field_.c_str());
  mapper->UseLookupTableScalarRangeOn();
  mapper->ScalarVisibilityOn();
  vtkNew<vtkActor> casting;
  casting->SetMapper(mapper);
  casting->GetProperty()->SetSpecular(0.15);
  vtkNew<vtkPolyDataMapper> voidMapper;
  voidMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> voids;  // the enclosed voids in magenta, the casting translucent around them
  voids->SetMapper(voidMapper);
  voids->GetProperty()->SetColor(0.85, 0.0, 0.85);
  vtkNew<vtkSphereSource> ball;
  ball->SetThetaResolution(24);
  ball->SetPhiResolution(16);
  vtkNew<vtkPolyDataMapper> ballMapper;
  ballMapper->SetInputConnection(ball->GetOutputPort());
  vtkNew<vtkActor> marker;
  marker->SetMapper(ballMapper);
  marker->GetProperty()->SetColor(0, 0, 0);
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(colours);
  bar->SetTitle((field_ + fieldUnit(field_)).c_str());
  bar->SetOrientationToHorizontal();
  bar->SetPosition(0.2, 0.02);
  bar->SetPosition2(0.6, 0.1);
  bar->SetNumberOfLabels(5);
  for (vtkTextProperty* text : {bar->GetTitleTextProperty(), bar->GetLabelTextProperty()}) {
    text->SetColor(0, 0, 0);
    text->ShadowOff();
    text->ItalicOff();
  }
  vtkNew<vtkTextActor> title;
  title->GetTextProperty()->SetColor(0, 0, 0);
  title->GetTextProperty()->SetFontSize(18);
  title->SetDisplayPosition(12, size_[1] - 34);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1, 1, 1);
  renderer->AddActor(voids);
  renderer->AddActor(casting);
  renderer->AddActor(marker);
  renderer->AddViewProp(bar);
  renderer->AddViewProp(title);
  vtkNew<vtkRenderWindow> window;
  window->SetDisplayId(display);
  window->SetOffScreenRendering(1);
  window->SetSize(size_[0], size_[1]);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  const Vector centre((bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
                      (bounds[4] + bounds[5]) / 2);
  const Vector eye = centre + from_.normalized();
  camera->SetFocalPoint(double(centre.x()), double(centre.y()), double(centre.z()));
  camera->SetPosition(double(eye.x()), double(eye.y()), double(eye.z()));
  const bool lookingAlongZ = std::abs(from_.normalized().z()) > 0.99;
  camera->SetViewUp(0, lookingAlongZ ? 1 : 0, lookingAlongZ ? 0 : 1);
  renderer->ResetCamera(bounds);
  camera->SetWindowCenter(0, -0.12);  // the casting above the colour bar
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  for (std::size_t k = 0; k < frames_.size(); ++k) {
    const Frame& frame = frames_[k];
    mapper->SetInputData(frame.surface);
    const bool anyVoid = frame.cavities->GetNumberOfCells() > 0;
    voidMapper->SetInputData(frame.cavities);
    voids->SetVisibility(anyVoid);
    casting->GetProperty()->SetOpacity(anyVoid ? 0.35 : 1.0);
    marker->SetVisibility(frame.marked);
    if (frame.marked) {
      ball->SetCenter(double(frame.lastToFreeze.x()), double(frame.lastToFreeze.y()),
                      double(frame.lastToFreeze.z()));
      ball->SetRadius(double(frame.spacing));
    }
    title->SetInput(("time " + frame.timeName + " s: " + cloud_ + " by " + field_ +
                     (frame.marked ? "; black ball: last to freeze" : "") +
                     (anyVoid ? "; magenta: enclosed voids" : "") + (clipped_ ? "; cut open" : ""))
                        .c_str());
    window->Render();
    grab->Modified();
    grab->Update();
    const auto out = folder() / frame.timeName;
    std::filesystem::create_directories(out);
    vtkNew<vtkPNGWriter> png;
    png->SetInputConnection(grab->GetOutputPort());
    const auto file = out / (field_ + ".png");
    png->SetFileName(file.string().c_str());
    png->Write();
    if (png->GetErrorCode() != 0) throw Error("could not write " + file.string());
    drawn_.push_back(name_ + "/" + frame.timeName + "/" + field_ + ".png");
    info() << "    " << name_ << ": wrote " << file.string() << '\n';
  }
  if (allTimes_ && frames_.size() > 1) animate();
  return true;
}

// The frames as <name>.gif (4 a second, 640 pixels wide, looping), by ffmpeg where it is on the
// PATH (Debian package ffmpeg): an animated image shows in the report's Markdown as it is.
void CastingView::animate() {
  if (std::system("command -v ffmpeg > /dev/null 2>&1") != 0) {
    animation_ = "ffmpeg is not on the PATH (apt-get install ffmpeg): the frames are not animated";
    return;
  }
  const auto frames = folder() / ".frames";
  std::filesystem::remove_all(frames);
  std::filesystem::create_directories(frames);
  char number[32];
  for (std::size_t k = 0; k < drawn_.size(); ++k) {
    std::snprintf(number, sizeof number, "%05zu.png", k);
    std::filesystem::copy_file(folder().parent_path() / drawn_[k], frames / number);
  }
  const auto gif = folder() / (name_ + ".gif");
  std::filesystem::remove(gif);
  const std::string command =
      "ffmpeg -y -loglevel error -framerate 4 -i " + shellQuoted((frames / "%05d.png").string()) +
      " -vf 'scale=640:-1:flags=lanczos,split[a][b];[a]palettegen[p];[b][p]paletteuse' "
      "-loop 0 " +
      shellQuoted(gif.string()) + " > /dev/null 2>&1";
  const bool made = std::system(command.c_str()) == 0 && std::filesystem::exists(gif);
  std::filesystem::remove_all(frames);
  if (!made) {
    animation_ = "ffmpeg could not make " + gif.string();
    warning("view " + name_ + ": " + animation_);
    return;
  }
  animation_ = name_ + "/" + name_ + ".gif";
  info() << "    " << name_ << ": wrote " << gif.string() << '\n';
}

ReportSection CastingView::finish() {
  if (!allTimes_ && !latest_.folder.name.empty()) build(latest_);
  ReportSection section;
  if (frames_.empty()) {
    section.markdown = "No view: cloud '" + cloud_ + "' has no particles at the selected times.\n";
    return section;
  }
  const Frame& last = frames_.back();
  section.markdown =
      "The " + cloud_ + "'s surface (its particles' kernel sum at 1/2) by " + field_ +
      (clipped_ ? ", cut open by the plane through " + formatPoint(clipPoint_) + " normal to (" +
                      formatNumber(clipNormal_.x(), 3) + " " + formatNumber(clipNormal_.y(), 3) +
                      " " + formatNumber(clipNormal_.z(), 3) + ")"
                : "") +
      ". At time " + last.timeName + " it encloses " + formatNumber(last.enclosed * 1e6, 4) +
      " cm^3; the particles" + (clipped_ ? " on the kept side" : "") + " hold " +
      formatNumber(last.particleVolume * 1e6, 4) + " cm^3 (sum m / rho)";
  if (last.marked) {
    section.markdown += "; the last particle to freeze (black ball) at " +
                        formatPoint(last.lastToFreeze) + ", t = " + formatNumber(last.lastTime, 4) +
                        " s";
  }
  section.markdown += ". " + std::to_string(last.cavityVolumes.size()) + " void" +
                      (last.cavityVolumes.size() == 1 ? "" : "s") + " enclosed in the metal";
  for (std::size_t k = 0; k < last.cavityVolumes.size() && k < 5; ++k) {
    section.markdown +=
        (k == 0 ? " (magenta): " : ", ") + formatNumber(last.cavityVolumes[k] * 1e6, 3) + " cm^3";
  }
  if (last.cavityVolumes.size() > 5) section.markdown += ", ...";
  section.markdown += ".\n";
  if (!render()) {
    section.markdown +=
        "\nNot drawn: no X display (DISPLAY unset or unreachable). VTK renders through X: run "
        "castPostProcess under `xvfb-run -a` (Debian package xvfb), as the tutorials' Allrun "
        "do.\n";
    warning("view " + name_ + ": no X display, not drawn (run castPostProcess under xvfb-run -a)");
    return section;
  }
  std::vector<double> times;
  for (const Frame& frame : frames_) times.push_back(frame.time);
  const std::vector<std::size_t> shown = shownPictures(times, show_);
  for (const std::size_t k : shown) section.images.push_back(drawn_[k]);
  if (allTimes_ && frames_.size() > 1) {
    section.markdown += "\nEvery written time: " + name_ + "/<time>/" + field_ + ".png; ";
    if (animation_.ends_with(".gif")) {
      section.markdown += "all of them animated:\n\n![" + animation_ + "](" + animation_ + ")\n";
    } else {
      section.markdown += animation_ + ".\n";
    }
  }
  return section;
}

}  // namespace sphcast
