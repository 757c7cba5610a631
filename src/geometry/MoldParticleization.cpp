#include "geometry/MoldParticleization.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "core/Error.h"
#include "core/Log.h"
#include "core/dictionary/Dictionary.h"
#include "geometry/GmshGeometry.h"
#include "geometry/LatticeSolid.h"
#include "geometry/MoldPatchRequest.h"
#include "geometry/WallSurfacePatches.h"
#include "particles/FieldNames.h"

namespace sphcast {

namespace {

constexpr double defaultMaxParticles = 2e7;
constexpr int layersWithoutSupportRadius = 3;  // complete for any h <= 3 dx
const Dimensions length{{0, 1, 0, 0, 0, 0, 0}};

// The shells of one geometry file share the file's cavity; volumes are filled one by one.
struct ShellJob {
  TriangleMesh wall;
  TriangleMesh cavityBoundary;
};
struct VolumeJob {
  TriangleMesh boundary;
  int patch;
  VolumeGrading grading;
  TriangleMesh fineSurfaces;  // the grading's fineSurfaces; empty: the boundary
};

// A volume patch's `grading { maxSpacing ...; fineLayers ...; }` (MoldParticleization.h).
VolumeGrading readGrading(const Dictionary& grading, const std::string& mode, double spacing,
                          int wallLayers) {
  grading.checkKeys({"maxSpacing", "fineLayers", "layersPerLevel", "fineSurfaces"});
  if (mode != "volume") {
    throw DictionaryError(grading.location(),
                          "'grading' is for the volume patches (mode volume; in 2D Physical "
                          "Surfaces), in " +
                              grading.name());
  }
  VolumeGrading result;
  result.maxSpacing = grading.get<double>("maxSpacing", length);
  if (!(result.maxSpacing >= 2.0 * spacing * (1.0 - 1e-9))) {
    throw DictionaryError(grading.location("maxSpacing"),
                          "'maxSpacing' must be at least twice the spacing (" +
                              std::to_string(2.0 * spacing) + " m) in " + grading.name());
  }
  const int fineLayers = grading.getOrDefault<int>("fineLayers", 2 * wallLayers);
  if (fineLayers < wallLayers) {
    throw DictionaryError(
        grading.location("fineLayers"),
        "'fineLayers' must be at least wallLayers (" + std::to_string(wallLayers) +
            "): the flow's walls need that many layers at dx, in " + grading.name());
  }
  result.fineDepth = fineLayers * spacing;
  result.layersPerLevel = grading.getOrDefault<int>("layersPerLevel", wallLayers);
  if (result.layersPerLevel < 2) {
    throw DictionaryError(grading.location("layersPerLevel"),
                          "'layersPerLevel' must be at least 2 in " + grading.name());
  }
  if (grading.found("fineSurfaces")) {
    result.fineSurfaces = grading.get<std::vector<std::string>>("fineSurfaces");
    if (result.fineSurfaces.empty()) {
      throw DictionaryError(grading.location("fineSurfaces"),
                            "'fineSurfaces' names no surface in " + grading.name() +
                                " (leave it out to keep every surface fine)");
    }
  }
  return result;
}

std::vector<PatchRequest> readPatches(const Dictionary& patches, double spacing, int wallLayers) {
  std::vector<PatchRequest> requests;
  for (const std::string& name : patches.keys()) {
    const Dictionary& entry = patches.subDict(name);
    entry.checkKeys({"cloud", "type", "mode", "grading"});
    PatchRequest request;
    request.where = patches.location(name);
    request.patch.name = name;
    request.patch.id = static_cast<int>(requests.size());
    request.patch.cloud = entry.get<std::string>("cloud");
    request.patch.type = entry.getChoice("type", {"fixedWall", "rigidBody", "fixedTemperature"});
    request.patch.mode = entry.getChoiceOrDefault("mode", {"shell", "volume"}, "shell");
    if (entry.found("grading")) {
      request.patch.grading =
          readGrading(entry.subDict("grading"), request.patch.mode, spacing, wallLayers);
    }
    requests.push_back(std::move(request));
  }
  if (requests.empty()) {
    throw DictionaryError(patches.location(), "no patches in " + patches.name());
  }
  return requests;
}

int readWallLayers(const Dictionary& dict, double spacing) {
  if (dict.found("wallLayers")) {
    const int layers = dict.get<int>("wallLayers");
    if (layers < 1) {
      throw DictionaryError(dict.location("wallLayers"),
                            "'wallLayers' must be at least 1 in " + dict.name());
    }
    return layers;
  }
  if (!dict.found("supportRadius")) {
    info() << "wallLayers " << layersWithoutSupportRadius
           << " (default: complete for a kernel support radius up to 3 dx; give supportRadius "
              "or wallLayers to choose)\n";
    return layersWithoutSupportRadius;
  }
  const double supportRadius = dict.get<double>("supportRadius", length);
  if (!(supportRadius > 0.0)) {
    throw DictionaryError(dict.location("supportRadius"),
                          "'supportRadius' must be positive in " + dict.name());
  }
  // 1e-9: h = 3 dx written in decimals must not become 4 layers.
  const int layers = static_cast<int>(std::ceil(supportRadius / spacing - 1e-9));
  info() << "wallLayers " << layers << " = ceil(supportRadius / spacing) = ceil(" << supportRadius
         << " / " << spacing << ")\n";
  return std::max(layers, 1);
}

void logGroups(const GmshGeometry& geometry) {
  for (const auto& group : geometry.groups()) {
    const auto& box = group.boundingBox;
    info() << "    physical group " << std::setw(20) << std::left << group.name << std::right
           << " dimension " << group.dimension << ", " << group.entityCount << " entities, bounds ("
           << box[0] << ' ' << box[1] << ' ' << box[2] << ") (" << box[3] << ' ' << box[4] << ' '
           << box[5] << ")\n";
  }
}

ParticleCloud makeCloud(const std::string& name, const WallParticles& particles,
                        const std::vector<MoldPatch>& patches, double spacing) {
  std::vector<std::size_t> members;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (patches[static_cast<std::size_t>(particles.owners[i])].cloud == name) members.push_back(i);
  }
  ParticleCloud cloud(name);
  cloud.resize(members.size());
  auto& volume = cloud.addScalarField(field::volume);
  auto& wallDistance = cloud.addScalarField(field::wallDistance);
  auto& normal = cloud.addVectorField(field::normal);
  auto& patch = cloud.addIdField(field::patch);
  auto& id = cloud.addIdField(field::id);
  const bool withPatchRadii = particles.patchRadii.size() == particles.size();
  std::vector<Real>* patchRadius =
      withPatchRadii ? &cloud.addScalarField(field::wallPatchRadius) : nullptr;
  const bool graded = particles.spacings.size() == particles.size() &&
                      std::any_of(members.begin(), members.end(),
                                  [&](std::size_t i) { return particles.spacings[i] > spacing; });
  std::vector<Real>* localSpacing = graded ? &cloud.addScalarField(field::localSpacing) : nullptr;
  const bool withRims = particles.patchesAtRim.size() == particles.size();
  std::vector<Real>* atRim = withRims ? &cloud.addScalarField(field::wallPatchAtRim) : nullptr;
  const bool withSecondFeet = particles.secondPatchRadii.size() == particles.size();
  std::vector<Vector>* secondNormal =
      withSecondFeet ? &cloud.addVectorField(field::secondNormal) : nullptr;
  std::vector<Real>* secondDepth =
      withSecondFeet ? &cloud.addScalarField(field::secondWallDistance) : nullptr;
  std::vector<Real>* secondRadius =
      withSecondFeet ? &cloud.addScalarField(field::secondWallPatchRadius) : nullptr;
  for (std::size_t m = 0; m < members.size(); ++m) {
    const std::size_t i = members[m];
    cloud.positions()[m] = particles.positions[i].cast<Real>();
    volume[m] = static_cast<Real>(particles.volumes[i]);
    wallDistance[m] = static_cast<Real>(particles.wallDistances[i]);
    normal[m] = particles.normals[i].cast<Real>();
    patch[m] = particles.owners[i];
    id[m] = static_cast<std::int64_t>(m);
    if (patchRadius != nullptr) (*patchRadius)[m] = static_cast<Real>(particles.patchRadii[i]);
    if (withRims) (*atRim)[m] = static_cast<Real>(particles.patchesAtRim[i]);
    if (graded) (*localSpacing)[m] = static_cast<Real>(std::max(particles.spacings[i], spacing));
    if (withSecondFeet) {
      (*secondNormal)[m] = particles.secondNormals[i].cast<Real>();
      (*secondDepth)[m] = static_cast<Real>(particles.secondWallDistances[i]);
      (*secondRadius)[m] = static_cast<Real>(particles.secondPatchRadii[i]);
    }
  }
  cloud.attributes()["spacing"] = spacing;
  return cloud;
}

const char* kindOfDimension(int dimension) {
  return dimension == 1 ? "curve" : dimension == 2 ? "surface" : "volume";
}

// How far the wall particles' feet had to reach to cover the surface (WallSurfacePatches.h): on
// a face on the lattice a foot stands for 0.8 dx about it (the cell's corners, and the sampling
// margin); beside an edge off the lattice, for more.
void logPatchRadii(const WallParticles& particles, double spacing) {
  std::size_t wide = 0;
  double widest = 0.0;
  for (const double radius : particles.patchRadii) {
    if (radius > spacing) ++wide;
    widest = std::max(widest, radius);
  }
  const auto seconds = static_cast<std::size_t>(
      std::count_if(particles.secondPatchRadii.begin(), particles.secondPatchRadii.end(),
                    [](double radius) { return radius > 0.0; }));
  info() << "    wall surface patches: " << wide << " of " << particles.size()
         << " particles stand for more than a spacing of surface about them (beside edges off "
            "the lattice), the widest "
         << std::setprecision(3) << widest / spacing << std::setprecision(6) << " dx; " << seconds
         << " stand for a second face too (thin parts, acute edges)\n";
}

// The particles of the 3D patches: shells behind surface groups, volumes filling volume groups.
WallParticles particleizeSolidMold(const std::vector<GeometryFilePatches>& files,
                                   const std::vector<PatchRequest>& requests, double spacing,
                                   int layers) {
  // Mesh the files and take the triangles of every patch.
  std::vector<ShellJob> shells;
  std::vector<VolumeJob> volumes;
  for (const auto& [path, patchesOfFile] : files) {
    if (patchesOfFile.empty()) continue;
    // Triangles of dx/2 keep the faceting error of a curved wall small: the sag of a chord s on
    // a radius R is s^2 / (8 R), the normal's error s / (2 R).
    const GmshGeometry geometry(path, 0.5 * spacing);
    std::vector<GmshGeometry::OwnedGroup> shellGroups;
    std::vector<int> cavityVolumes;
    for (const std::size_t p : patchesOfFile) {
      const PhysicalGroup* group = geometry.findGroup(requests[p].patch.name);
      const MoldPatch& patch = requests[p].patch;
      if (patch.mode == "shell") {
        shellGroups.push_back({group, patch.id});
        try {
          const auto bounded = geometry.volumesBoundedBy(*group);
          cavityVolumes.insert(cavityVolumes.end(), bounded.begin(), bounded.end());
        } catch (const DictionaryError&) {
          throw;
        } catch (const Error& error) {
          throw DictionaryError(requests[p].where, error.what());
        }
      } else {
        VolumeJob job{
            geometry.boundaryOfVolumes(geometry.volumesOf(*group)), patch.id, patch.grading, {}};
        const std::size_t freeEdges = job.boundary.freeEdgeCount();
        if (job.boundary.size() == 0 || freeEdges > 0) {
          throw DictionaryError(requests[p].where,
                                "patch '" + patch.name + "' has mode volume, but physical group '" +
                                    patch.name + "' of '" + path.string() +
                                    "' is not a closed volume: " + std::to_string(freeEdges) +
                                    " edges of its boundary mesh belong to one triangle only");
        }
        for (const std::string& name : patch.grading.fineSurfaces) {
          const PhysicalGroup* surface = geometry.findGroup(name);
          if (surface == nullptr || surface->dimension != 2) {
            throw DictionaryError(requests[p].where,
                                  "patch '" + patch.name + "': grading's fineSurfaces names '" +
                                      name + "', which is not a Physical Surface of '" +
                                      path.string() + "'; the groups present are (" +
                                      groupNames(geometry.groups()) + " )");
          }
          job.fineSurfaces.append(geometry.surfacesOf({{surface, patch.id}}));
        }
        volumes.push_back(std::move(job));
      }
    }
    if (!shellGroups.empty()) {
      std::sort(cavityVolumes.begin(), cavityVolumes.end());
      cavityVolumes.erase(std::unique(cavityVolumes.begin(), cavityVolumes.end()),
                          cavityVolumes.end());
      shells.push_back(
          {geometry.surfacesOf(shellGroups), geometry.boundaryOfVolumes(cavityVolumes)});
    }
  }

  const auto patchCount = static_cast<int>(requests.size());
  WallParticles all;
  for (const auto& shell : shells) {
    const LatticeSolid cavity(shell.cavityBoundary, spacing);
    const auto planarFaces = findPlanarFaces(shell.wall, shell.cavityBoundary, spacing);
    const auto tilted = std::count_if(planarFaces.begin(), planarFaces.end(),
                                      [](const PlanarFace& face) { return !face.globalLattice; });
    info() << "Shell walls: flat faces on their own lattice " << planarFaces.size()
           << " (tilted to the axes " << tilted << "); other faces follow their curvature\n";
    WallParticles shellParticles =
        generateShellParticles(shell.wall, cavity, spacing, layers, patchCount, planarFaces);
    addWallSurfacePatches(shellParticles, shell.wall, spacing);
    logPatchRadii(shellParticles, spacing);
    all.append(shellParticles);
  }
  for (const auto& volume : volumes) {
    WallParticles filled = fillVolumeParticles(volume.boundary, spacing, volume.patch);
    // The lattice count misses the volume by up to ~1.5% on a radius of a dozen spacings; share
    // the geometry's volume among the particles, so the mold's mass and heat capacity are right.
    const double volumePerParticle = volume.boundary.enclosedVolume() /
                                     static_cast<double>(std::max<std::size_t>(filled.size(), 1));
    info() << "Volume " << requests[static_cast<std::size_t>(volume.patch)].patch.name << ": "
           << filled.size() << " lattice points x dx^3 = "
           << static_cast<double>(filled.size()) * spacing * spacing * spacing
           << " m^3 of the geometry's " << volume.boundary.enclosedVolume()
           << " m^3; particle volume set to " << volumePerParticle << " m^3\n";
    std::fill(filled.volumes.begin(), filled.volumes.end(), volumePerParticle);
    if (gradingLevels(volume.grading, spacing) > 0) {
      const std::size_t uniform = filled.size();
      std::vector<double> depth = filled.wallDistances;
      if (volume.fineSurfaces.size() > 0) {  // the distance to the surfaces kept fine
        const TriangleDistanceTree fine(volume.fineSurfaces);
#pragma omp parallel for schedule(dynamic, 4096)
        for (std::ptrdiff_t i = 0; i < static_cast<std::ptrdiff_t>(depth.size()); ++i) {
          const auto p = static_cast<std::size_t>(i);
          depth[p] = fine.closest(filled.positions[p], std::numeric_limits<double>::max()).distance;
        }
      }
      filled = gradeVolumeParticles(filled, depth, volume.boundary, spacing, volumePerParticle,
                                    volume.grading);
      info() << "    graded: " << filled.size() << " particles for the " << uniform << " at dx ("
             << std::setprecision(3)
             << static_cast<double>(uniform) / static_cast<double>(filled.size())
             << " times fewer), dx within " << volume.grading.fineDepth << std::setprecision(6)
             << " m of " << (volume.fineSurfaces.size() > 0 ? "its fineSurfaces" : "its surface")
             << ", coarser inward up to " << volume.grading.maxSpacing << " m\n";
    }
    addWallSurfacePatches(filled, volume.boundary, spacing);
    logPatchRadii(filled, spacing);
    all.append(filled);
  }
  return all;
}

}  // namespace

std::string groupNames(const std::vector<PhysicalGroup>& groups) {
  std::ostringstream names;
  for (const auto& group : groups) names << ' ' << group.name;
  return names.str();
}

ParticleizedMold particleizeMold(const CaseFolder& caseFolder) {
  const Dictionary dict = Dictionary::read(caseFolder.systemFile("particleizeMoldDict"));
  dict.checkKeys({"dimension", "geometry", "spacing", "supportRadius", "wallLayers", "maxParticles",
                  "cavity", "patches"});
  const int dimension = dict.getOrDefault<int>("dimension", 3);
  if (dimension != 2 && dimension != 3) {
    throw DictionaryError(dict.location("dimension"),
                          "'dimension' must be 2 or 3 in " + dict.name());
  }
  CavityRequest cavity;
  if (dict.found("cavity")) {
    cavity = {dict.get<std::string>("cavity"), dict.location("cavity")};
    if (dimension == 3) {
      throw DictionaryError(cavity.where,
                            "'cavity' is for a 2D case (dimension 2); in 3D the cavity is the "
                            "volume the shell surfaces bound");
    }
  }
  ParticleizedMold mold;
  mold.spacing = dict.get<double>("spacing", length);
  if (!(mold.spacing > 0.0)) {
    throw DictionaryError(dict.location("spacing"), "'spacing' must be positive in " + dict.name());
  }
  const double spacing = mold.spacing;
  mold.wallLayers = readWallLayers(dict, spacing);
  const double maxParticles = dict.getOrDefault<double>("maxParticles", defaultMaxParticles);
  std::vector<PatchRequest> requests =
      readPatches(dict.subDict("patches"), spacing, mold.wallLayers);
  std::vector<GeometryFilePatches> files;
  for (const std::string& file : dict.get<std::vector<std::string>>("geometry")) {
    const auto path = caseFolder.constant() / "geometry" / file;
    if (!std::filesystem::is_regular_file(path)) {
      throw DictionaryError(dict.location("geometry"),
                            "geometry file '" + path.string() + "' does not exist");
    }
    files.push_back({path, {}});
  }

  // First look at the files without meshing them: groups present, kinds, and how many
  // particles the spacing would make (meshing a wall at dx/2 is itself costly at a tiny dx).
  // A shell is a group one dimension below the case's (a surface in 3D, a curve in 2D), a
  // volume one of the case's dimension (a volume in 3D, a surface in 2D).
  std::vector<bool> resolved(requests.size(), false);
  std::vector<PhysicalGroup> allGroups;
  double estimate = 0.0;
  for (auto& [path, patchesOfFile] : files) {
    info() << "Reading " << path.string() << '\n';
    const GmshGeometry geometry(path, 0.0);
    logGroups(geometry);
    allGroups.insert(allGroups.end(), geometry.groups().begin(), geometry.groups().end());
    for (std::size_t p = 0; p < requests.size(); ++p) {
      const PhysicalGroup* group = geometry.findGroup(requests[p].patch.name);
      if (group == nullptr || resolved[p]) continue;
      resolved[p] = true;
      patchesOfFile.push_back(p);
      const MoldPatch& patch = requests[p].patch;
      const int wantedDimension = patch.mode == "shell" ? dimension - 1 : dimension;
      if (group->dimension != wantedDimension) {
        throw DictionaryError(
            requests[p].where,
            "patch '" + patch.name + "' has mode " + patch.mode + ", but physical group '" +
                patch.name + "' of '" + path.string() + "' is not a " +
                kindOfDimension(wantedDimension) + " (dimension " +
                std::to_string(group->dimension) + ")" +
                (patch.mode == "shell" && group->dimension == dimension ? "; use mode volume"
                                                                        : "") +
                (dimension == 3 && group->dimension < 2 ? "; is the case 2D (dimension 2)?" : ""));
      }
      const double measure = geometry.groupMeasure(*group);
      estimate += patch.mode == "shell"
                      ? measure * mold.wallLayers / std::pow(spacing, dimension - 1)
                      : measure / std::pow(spacing, dimension);
    }
  }
  for (std::size_t p = 0; p < requests.size(); ++p) {
    if (!resolved[p]) {
      throw DictionaryError(requests[p].where,
                            "patch '" + requests[p].patch.name +
                                "' is not a physical group of the geometry; the groups present "
                                "are (" +
                                groupNames(allGroups) + " )");
    }
  }
  if (!cavity.name.empty() &&
      std::none_of(allGroups.begin(), allGroups.end(), [&](const PhysicalGroup& group) {
        return group.name == cavity.name && group.dimension == 2;
      })) {
    throw DictionaryError(cavity.where, "cavity '" + cavity.name +
                                            "' is not a physical surface of the geometry; the "
                                            "groups present are (" +
                                            groupNames(allGroups) + " )");
  }
  if (estimate > maxParticles) {
    std::ostringstream message;
    const bool graded = std::any_of(requests.begin(), requests.end(), [](const PatchRequest& r) {
      return r.patch.grading.maxSpacing > 0.0;
    });
    message << "spacing " << spacing << " m would make about " << std::llround(estimate)
            << " mold particles, more than maxParticles " << maxParticles
            << (graded ? " (a graded volume is filled at the spacing before it is graded, and "
                         "that fill's memory and time are these)"
                       : "")
            << " (raise maxParticles in " << dict.name() << " if you mean it); nothing was written";
    throw DictionaryError(dict.location("spacing"), message.str());
  }

  WallParticles all = dimension == 3
                          ? particleizeSolidMold(files, requests, spacing, mold.wallLayers)
                          : particleizePlaneMold(files, requests, cavity, spacing, mold.wallLayers);
  const auto patchCount = static_cast<int>(requests.size());
  const auto statistics = nearestNeighbourStatistics(all, patchCount, spacing);
  for (auto& request : requests) {
    MoldPatch& patch = request.patch;
    patch.spacing = statistics[static_cast<std::size_t>(patch.id)];
    patch.particleCount = patch.spacing.count;
    info() << "Patch " << patch.name << " (" << patch.mode << ", " << patch.type << ") -> cloud "
           << patch.cloud << ": " << patch.particleCount
           << " particles; nearest-neighbour distance / dx: min " << std::setprecision(3)
           << patch.spacing.min / spacing << ", mean " << patch.spacing.mean / spacing << ", max "
           << patch.spacing.max / spacing << std::setprecision(6) << '\n';
    mold.patches.push_back(patch);
  }
  std::vector<std::string> cloudNames;
  for (const auto& patch : mold.patches) {
    if (std::find(cloudNames.begin(), cloudNames.end(), patch.cloud) == cloudNames.end()) {
      cloudNames.push_back(patch.cloud);
    }
  }
  for (const auto& name : cloudNames)
    mold.clouds.push_back(makeCloud(name, all, mold.patches, spacing));
  return mold;
}

namespace {
std::string groupNamesOf(const std::vector<std::string>& names) {
  std::string joined;
  for (const auto& name : names) joined += ' ' + name;
  return joined;
}
}  // namespace

std::string patchesDictionaryText(const ParticleizedMold& mold) {
  std::ostringstream text;
  text << foamFileHeader("constant/particles", "patches")
       << "// Written by particleizeMold: spacing " << mold.spacing << " m, " << mold.wallLayers
       << " wall layers. 'id' is the value of the particles' 'patch' field.\n\n";
  for (const auto& patch : mold.patches) {
    text << patch.name << "\n{\n    id          " << patch.id << ";\n    cloud       "
         << patch.cloud << ";\n    type        " << patch.type << ";\n    mode        "
         << patch.mode << ";\n    particles   " << patch.particleCount << ";\n";
    if (patch.grading.maxSpacing > 0.0) {
      text << "    // graded: dx within " << patch.grading.fineDepth << " m of "
           << (patch.grading.fineSurfaces.empty()
                   ? std::string("the surface")
                   : "the fineSurfaces (" + groupNamesOf(patch.grading.fineSurfaces) + " )")
           << ", coarser inward up to " << patch.grading.maxSpacing << " m\n";
    }
    text << "}\n\n";
  }
  return text.str();
}

}  // namespace sphcast
