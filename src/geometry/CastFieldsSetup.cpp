#include "geometry/CastFieldsSetup.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

#include "core/Error.h"
#include "core/Log.h"
#include "core/dictionary/Dictionary.h"
#include "geometry/CloudFields.h"
#include "geometry/FillRegion.h"
#include "geometry/LatticeFill.h"
#include "geometry/LatticeSolid.h"
#include "geometry/MoldObstacles.h"
#include "geometry/PackingRelaxation.h"
#include "particles/CellGrid.h"
#include "particles/Domain.h"
#include "particles/FieldNames.h"
#include "particles/NeighbourList.h"

namespace sphcast {

namespace {

constexpr double defaultMaxParticles = 2e7;
constexpr double defaultMoldClearance = 0.75;  // x spacing; see CastFieldsSetup.h
const Dimensions length{{0, 1, 0, 0, 0, 0, 0}};

struct RegionFill {
  std::unique_ptr<FillRegion> region;
  bool ownLattice;          // a top-level box: today's lattice centred in the box
  std::string name;         // for the messages
  SourceLocation location;  // where the region is given
};

struct CloudPlan {
  std::string name;
  SourceLocation location;  // where the cloud is given
  std::vector<RegionFill> regions;
  int relaxationIterations = 0;
  SourceLocation relaxationAt;  // where relaxation was asked for
  std::optional<DensityStart> density;
};

// Points of the shared lattice inside the region's bounding box grown by `margin` cells; in a
// 2D case the one layer z = 0.
template <class Keep>
std::vector<Vector> sharedLatticeAround(const FillRegion& region, double spacing,
                                        std::int64_t margin, int dimension, const Keep& keep) {
  std::vector<Vector> points;
  const Eigen::Vector3d lower = region.lower(), upper = region.upper();
  const std::int64_t grow = margin + 1;
  const std::int64_t kFirst = dimension == 2 ? 0 : latticeIndex(lower.z(), spacing) - grow;
  const std::int64_t kLast = dimension == 2 ? 0 : latticeIndex(upper.z(), spacing) + grow;
  for (std::int64_t k = kFirst; k <= kLast; ++k) {
    const double z = dimension == 2 ? 0.0 : latticeCoordinate(k, spacing);
    for (std::int64_t j = latticeIndex(lower.y(), spacing) - grow;
         j <= latticeIndex(upper.y(), spacing) + grow; ++j) {
      for (std::int64_t i = latticeIndex(lower.x(), spacing) - grow;
           i <= latticeIndex(upper.x(), spacing) + grow; ++i) {
        const Eigen::Vector3d p(latticeCoordinate(i, spacing), latticeCoordinate(j, spacing), z);
        if (keep(p)) points.push_back(p.cast<Real>());
      }
    }
  }
  return points;
}

// The lattice a region is filled on, within `margin` cells around it (0: the fill itself).
std::vector<Vector> latticeOf(const RegionFill& fill, double spacing, std::int64_t margin,
                              int dimension) {
  if (fill.ownLattice) {
    // Growing the box by whole cells on each side keeps its centred lattice where it was. A
    // flat axis is not grown; in a 2D case the box is cut by the plane z = 0.
    Vector lower = fill.region->lower().cast<Real>(), upper = fill.region->upper().cast<Real>();
    if (dimension == 2) {
      if (lower.z() > Real(0) || upper.z() < Real(0)) return {};
      lower.z() = upper.z() = Real(0);
    }
    Vector grow = Vector::Zero();
    for (int axis = 0; axis < 3; ++axis) {
      if (upper[axis] > lower[axis]) {
        grow[axis] = static_cast<Real>(static_cast<double>(margin) * spacing);
      }
    }
    return fillBoxOnLattice(lower - grow, upper + grow, spacing);
  }
  if (margin == 0) {
    return sharedLatticeAround(*fill.region, spacing, 0, dimension,
                               [&](const Eigen::Vector3d& p) { return fill.region->contains(p); });
  }
  return sharedLatticeAround(*fill.region, spacing, margin, dimension,
                             [](const Eigen::Vector3d&) { return true; });
}

bool insideAnyRegion(const CloudPlan& plan, const Vector& x) {
  const Eigen::Vector3d p = x.cast<double>();
  return std::any_of(plan.regions.begin(), plan.regions.end(),
                     [&](const RegionFill& fill) { return fill.region->contains(p); });
}

// The points of `points` for which keep[i] is true.
std::vector<Vector> keptPoints(const std::vector<Vector>& points, const std::vector<bool>& keep) {
  std::vector<Vector> kept;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (keep[i]) kept.push_back(points[i]);
  }
  return kept;
}

// The lattice of the regions continued `margin` cells beyond them: points outside every region,
// clear of the mold, not behind its walls (where the shell has gaps between its particles) and
// within `reach` of a metal particle: the fixed image of the metal beyond its free surface.
std::vector<Vector> latticeBeyondFreeSurface(const CloudPlan& plan, double spacing,
                                             std::int64_t margin, int dimension, double reach,
                                             const std::vector<Vector>& metal,
                                             const MoldObstacles& mold) {
  std::vector<Vector> beyond;
  for (const RegionFill& fill : plan.regions) {
    for (const Vector& p : latticeOf(fill, spacing, margin, dimension)) {
      if (!insideAnyRegion(plan, p)) beyond.push_back(p);
    }
  }
  auto lexical = [](const Vector& a, const Vector& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  };
  std::sort(beyond.begin(), beyond.end(), lexical);
  beyond.erase(std::unique(beyond.begin(), beyond.end()), beyond.end());

  CellGrid metalGrid(static_cast<Real>(reach));
  metalGrid.build(metal);
  NeighbourList nearMetal;
  nearMetal.buildBetween(beyond, metal, metalGrid);
  std::vector<bool> keep(beyond.size());
  for (std::size_t i = 0; i < beyond.size(); ++i) keep[i] = !nearMetal.of(i).empty();
  beyond = keptPoints(beyond, keep);

  const auto clear = mold.clear(beyond);
  const auto behind = mold.behindWall(beyond, 1.5 * spacing);
  keep.assign(beyond.size(), false);
  for (std::size_t i = 0; i < beyond.size(); ++i) keep[i] = clear[i] && !behind[i];
  return keptPoints(beyond, keep);
}

void logPacking(const std::string& cloudName, const char* when, const PackingStatistics& s,
                double spacing) {
  info() << "Cloud " << cloudName << ": " << when << ": number density sum V W mean "
         << s.densityMean << ", deviation " << s.densityDeviation << " (min " << s.densityMin
         << ", max " << s.densityMax << "); nearest neighbour min " << s.nearestMin / spacing
         << " dx, mean " << s.nearestMean / spacing << " dx, max " << s.nearestMax / spacing
         << " dx\n";
}

// Lattice points of the cloud's regions, each point once (a point of a region that an earlier
// region of the cloud holds already is left out), the region each came from, and the regions'
// volume (their area in a 2D case). A region that holds no lattice point is an error that says
// why.
std::vector<Vector> fillRegions(const CloudPlan& plan, double spacing, int dimension,
                                std::vector<std::size_t>& regionOf, double& regionVolume,
                                bool& volumeExact) {
  std::vector<Vector> centres;
  regionOf.clear();
  regionVolume = 0.0;
  volumeExact = true;
  for (std::size_t k = 0; k < plan.regions.size(); ++k) {
    const RegionFill& fill = plan.regions[k];
    const std::vector<Vector> lattice = latticeOf(fill, spacing, 0, dimension);
    if (lattice.empty()) {
      const Eigen::Vector3d lower = fill.region->lower(), upper = fill.region->upper();
      const bool offPlane = dimension == 2 && (lower.z() > 0.0 || upper.z() < 0.0);
      std::ostringstream message;
      message << "region '" << fill.name << "' of cloud '" << plan.name
              << "' holds no lattice point of spacing " << spacing << " m: ";
      if (offPlane) {
        message << "it does not reach the plane z = 0 of a 2D case (its z runs from " << lower.z()
                << " to " << upper.z() << " m)";
      } else {
        message << "it is thinner than a spacing, or lies between the lattice points (the "
                   "lattice is at (i + 1/2) spacing; a top-level box keeps its own); make it "
                   "larger or the spacing smaller";
      }
      throw DictionaryError(fill.location, message.str());
    }
    std::size_t overlapping = 0;
    for (const Vector& p : lattice) {
      const Eigen::Vector3d x = p.cast<double>();
      const bool held =
          std::any_of(plan.regions.begin(), plan.regions.begin() + static_cast<std::ptrdiff_t>(k),
                      [&](const RegionFill& earlier) { return earlier.region->contains(x); });
      if (held) {
        ++overlapping;
      } else {
        centres.push_back(p);
        regionOf.push_back(k);
      }
    }
    if (dimension == 2) {
      regionVolume += fill.region->sectionAreaBound();
      volumeExact = volumeExact && fill.region->sectionAreaIsExact() && overlapping == 0;
    } else {
      regionVolume += fill.region->volumeBound();
      volumeExact = volumeExact && fill.region->volumeIsExact() && overlapping == 0;
    }
  }
  return centres;
}

// After the fill is cleared of the mold: a region that lost every particle to the mold, or a
// cloud lying wholly outside the domain (the mold particles' box grown by half on each side, as
// the flow's health check takes it), is a mistake (a region drawn inside the mold material, or
// in other units than the mold); say which region and why. Some particles outside the domain
// are a warning: a flow stops them at its first step.
void checkFillAgainstMold(const CloudPlan& plan, const std::vector<std::size_t>& regionOf,
                          const std::vector<bool>& clear, const std::vector<Vector>& centres,
                          const MoldObstacles& mold, const Domain& domain) {
  std::vector<std::size_t> filled(plan.regions.size(), 0), kept(plan.regions.size(), 0);
  for (std::size_t i = 0; i < regionOf.size(); ++i) {
    ++filled[regionOf[i]];
    if (clear[i]) ++kept[regionOf[i]];
  }
  for (std::size_t k = 0; k < plan.regions.size(); ++k) {
    if (filled[k] == 0 || kept[k] > 0) continue;
    std::ostringstream message;
    message << "region '" << plan.regions[k].name << "' of cloud '" << plan.name
            << "' is filled by no particle: all of its " << filled[k]
            << " lattice points lie within moldClearance " << mold.clearance()
            << " m of a mold particle (the region lies inside the mold, or is thinner than the "
               "gap the clearance leaves between the walls)";
    throw DictionaryError(plan.regions[k].location, message.str());
  }
  const auto outside = static_cast<std::size_t>(std::count_if(
      centres.begin(), centres.end(), [&](const Vector& x) { return !inside(domain, x); }));
  if (outside == 0) return;
  std::ostringstream where;
  where << "the domain (the mold particles' box grown by half on each side: ("
        << domain.lower.transpose() << ") to (" << domain.upper.transpose() << ") m)";
  if (outside == centres.size()) {
    throw DictionaryError(plan.location, "cloud '" + plan.name + "' lies wholly outside " +
                                             where.str() +
                                             ": check the regions' coordinates and units "
                                             "against the mold's");
  }
  warning("cloud " + plan.name + ": " + std::to_string(outside) + " of " +
          std::to_string(centres.size()) + " particles lie outside " + where.str() +
          "; a flow spills them at its first step, and stops if they are more than "
          "healthChecks' maxSpilledFraction (5 % by default) of the metal");
}

// `domain` is the mold clouds' (defaultDomain), for the check of the fill against it.
ParticleCloud fillCloud(const CloudPlan& plan, double spacing, int dimension,
                        const MoldObstacles& mold, const Domain& domain,
                        CastCaseSettings& settings) {
  double regionVolume = 0.0;
  bool volumeExact = true;
  std::vector<std::size_t> regionOf;
  std::vector<Vector> centres =
      fillRegions(plan, spacing, dimension, regionOf, regionVolume, volumeExact);
  if (!mold.empty()) {
    const std::size_t before = centres.size();
    const std::vector<bool> clear = mold.clear(centres);
    checkFillAgainstMold(plan, regionOf, clear, centres, mold, domain);
    centres = keptPoints(centres, clear);
    info() << "Cloud " << plan.name << ": left out " << before - centres.size()
           << " particles closer than moldClearance " << mold.clearance()
           << " m to a mold particle\n";
    // Between the particles of a curved wall a lattice point can lie right on the wall surface
    // and still be moldClearance from every mold particle. Such a point is moved back along the
    // wall normal to the flow's default wall clearance (the flow would do it at its first step);
    // it keeps its mass, which leaving it out would lose (5 % of a column 10 dx across).
    const Real minimumGap = static_cast<Real>(settings.flowWallClearance() * spacing);
    const auto surfaces = mold.wallSurfaceDistances(centres, wallSurfaceReachInSpacings * spacing);
    std::size_t moved = 0;
    for (std::size_t i = 0; i < centres.size(); ++i) {
      if (!surfaces[i].found || surfaces[i].distance >= minimumGap) continue;
      centres[i] += (minimumGap - surfaces[i].distance) * surfaces[i].normal;
      ++moved;
    }
    info() << "Cloud " << plan.name << ": moved " << moved << " particles closer than "
           << settings.flowWallClearance() << " dx to a wall surface back to that distance\n";
  }

  const double dx3 = spacing * spacing * spacing;
  // a 2D cloud's particles each hold dx^2 (an area per unit depth)
  const double filledVolume =
      static_cast<double>(centres.size()) * (dimension == 2 ? spacing * spacing : dx3);
  info() << "Cloud " << plan.name << ": " << centres.size() << " particles, " << filledVolume
         << (dimension == 2 ? " m^2 (count x dx^2)" : " m^3 (count x dx^3)");
  if (regionVolume > 0.0) {
    const char* measure = dimension == 2 ? "area" : "volume";
    info() << ", " << 100.0 * filledVolume / regionVolume << " % of the regions' " << measure
           << (volumeExact ? " " : " bound (overlaps, booleans or curved sections) ")
           << regionVolume << (dimension == 2 ? " m^2" : " m^3");
  }
  info() << "\n";

  if (plan.regions.empty()) {
    info() << "Cloud " << plan.name
           << ": no regions: an empty cloud, for a pouring inlet (constant/inlets) to fill\n";
  } else {
    Vector lower = centres.front(), upper = centres.front();
    for (const Vector& c : centres) {
      lower = lower.cwiseMin(c);
      upper = upper.cwiseMax(c);
    }
    if (plan.relaxationIterations > 0 && (upper - lower).minCoeff() <= Real(0)) {
      throw DictionaryError(plan.relaxationAt,
                            "cloud '" + plan.name +
                                "' is one particle thick along an axis (a 2D case): the relaxation "
                                "uses the 3D kernel; remove 'relaxation' for this cloud");
    }
    if (plan.relaxationIterations > 0) {
      const double h = settings.supportRadius(spacing);
      const auto margin = static_cast<std::int64_t>(std::ceil(h / spacing));
      const auto beyond =
          latticeBeyondFreeSurface(plan, spacing, margin, dimension, h, centres, mold);
      const Vector reach = Vector::Constant(static_cast<Real>(h));
      FixedNeighbours fixed = mold.within(lower - reach, upper + reach);
      fixed.positions.insert(fixed.positions.end(), beyond.begin(), beyond.end());
      fixed.volumes.insert(fixed.volumes.end(), beyond.size(), static_cast<Real>(dx3));
      // The lattice beyond the free surface is kept at the clearance too: without it, metal next
      // to the rim rose to the region's top, dx/2 under a fixed point (measured: nearest
      // neighbour 0.52 dx on the open cone at 90,685 particles).
      CellGrid beyondGrid(static_cast<Real>(mold.clearance()));
      if (!beyond.empty()) beyondGrid.build(beyond);
      NeighbourList nearBeyond;
      // ... and no move brings a particle nearer a wall surface than the flow's clearance
      const Real minimumGap = static_cast<Real>(settings.flowWallClearance() * spacing);
      auto allowed = [&](const std::vector<Vector>& trial) {
        std::vector<bool> ok = mold.clear(trial);
        if (!beyond.empty()) nearBeyond.buildBetween(trial, beyond, beyondGrid);
        const auto surfaces =
            mold.wallSurfaceDistances(trial, wallSurfaceReachInSpacings * spacing);
        for (std::size_t i = 0; i < trial.size(); ++i) {
          ok[i] = ok[i] && (beyond.empty() || nearBeyond.of(i).empty()) &&
                  insideAnyRegion(plan, trial[i]) &&
                  (!surfaces[i].found || surfaces[i].distance >= minimumGap);
        }
        return ok;
      };
      const RelaxationSettings relaxation{plan.relaxationIterations, spacing, h, mold.clearance()};
      info() << "Cloud " << plan.name << ": relaxing the packing, " << plan.relaxationIterations
             << " iterations, h = " << h << " m, " << beyond.size()
             << " fixed lattice points beyond the free surface\n";
      const auto statistics = relaxPacking(centres, fixed, allowed, relaxation);
      logPacking(plan.name, "before relaxation", statistics[0], spacing);
      logPacking(plan.name, "after relaxation", statistics[1], spacing);
    } else {
      // Spacing only: the nearest particle, metal or mold, within 2 dx.
      const Vector reach = Vector::Constant(static_cast<Real>(2.0 * spacing));
      const auto s = packingStatistics(centres, mold.within(lower - reach, upper + reach), spacing,
                                       2.0 * spacing);
      info() << "Cloud " << plan.name << ": nearest neighbour (metal or mold) min "
             << s.nearestMin / spacing << " dx, mean " << s.nearestMean / spacing << " dx, max "
             << s.nearestMax / spacing << " dx\n";
    }
  }

  ParticleCloud cloud(plan.name);
  cloud.resize(centres.size());
  std::copy(centres.begin(), centres.end(), cloud.positions().begin());
  cloud.addVectorField(field::U);
  auto& volume = cloud.addScalarField(field::volume);
  // A 2D case's particle stands for the area dx^2 (the solver's 2D kernel integrates over area).
  const double cellVolume = dimension == 2 ? spacing * spacing : dx3;
  for (Real& v : volume) v = static_cast<Real>(cellVolume);
  auto& id = cloud.addIdField(field::id);
  for (std::size_t i = 0; i < id.size(); ++i) id[i] = static_cast<std::int64_t>(i);
  cloud.attributes()["spacing"] = spacing;
  return cloud;
}

int readRelaxation(const Dictionary& owner, int fallback) {
  if (!owner.found("relaxation")) return fallback;
  const Dictionary& relaxation = owner.subDict("relaxation");
  relaxation.checkKeys({"iterations"});
  const int iterations = relaxation.get<int>("iterations");
  if (iterations < 0) {
    throw DictionaryError(relaxation.location("iterations"),
                          "'iterations' must not be negative in " + relaxation.name());
  }
  return iterations;
}

// moldClearance, m; its former name wallClearance is still read, with a warning (the flow's
// wallClearance of system/sphSchemes is another length: spacings to the wall surface).
double readMoldClearance(const Dictionary& dict, double spacing) {
  if (dict.found("moldClearance") && dict.found("wallClearance")) {
    throw DictionaryError(
        dict.location("wallClearance"),
        "give 'moldClearance' alone in " + dict.name() + " ('wallClearance' is its former name)");
  }
  if (dict.found("wallClearance")) {
    warning(dict.location("wallClearance").str() + ": 'wallClearance' in " + dict.name() +
            " is now 'moldClearance' (the distance, in metres, from a mold particle's centre "
            "within which no metal particle is filled); read as that");
    return dict.get<double>("wallClearance", length);
  }
  return dict.getOrDefault<double>("moldClearance", defaultMoldClearance * spacing);
}

}  // namespace

std::vector<ParticleCloud> buildCastClouds(const CaseDescription& description,
                                           const std::vector<ParticleCloud>& moldClouds) {
  const CaseFolder& caseFolder = description.folder();
  const Dictionary dict = Dictionary::read(caseFolder.systemFile("setCastFieldsDict"));
  dict.checkKeys({"dimension", "spacing", "maxParticles", "moldClearance", "wallClearance",
                  "relaxation", "clouds", "setFields"});
  // the case's (constant/physicsModels), unless given here too, where it must agree
  const int dimension = dict.getOrDefault<int>("dimension", description.dimension());
  if (dimension != 2 && dimension != 3) {
    throw DictionaryError(dict.location("dimension"),
                          "'dimension' must be 2 or 3 in " + dict.name());
  }
  if (description.hasPhysicsModels() && dimension != description.dimension()) {
    throw DictionaryError(dict.location("dimension"),
                          "'dimension' is " + std::to_string(dimension) + " in " + dict.name() +
                              " but " + std::to_string(description.dimension()) +
                              " in constant/physicsModels: give it once, there");
  }
  const double spacing = dict.get<double>("spacing", length);
  if (!(spacing > 0.0)) {
    throw DictionaryError(dict.location("spacing"), "'spacing' must be positive in " + dict.name());
  }
  const double maxParticles = dict.getOrDefault<double>("maxParticles", defaultMaxParticles);
  const double clearance = readMoldClearance(dict, spacing);
  const int globalRelaxation = readRelaxation(dict, 0);
  const auto geometryFolder = caseFolder.constant() / "geometry";
  const Dictionary noClouds;
  const Dictionary& cloudsDict = dict.found("clouds") ? dict.subDict("clouds") : noClouds;

  CastCaseSettings settings(description);
  // Read every region and count first: a spacing that makes 10^9 particles is refused before
  // any memory is taken.
  double total = 0.0;
  std::vector<CloudPlan> plans;
  for (const std::string& cloudName : cloudsDict.keys()) {
    const Dictionary& cloudDict = cloudsDict.subDict(cloudName);
    cloudDict.checkKeys({"material", "regions", "fields", "relaxation"});
    const Dictionary& regions = cloudDict.subDict("regions");
    CloudPlan plan{cloudName,
                   cloudsDict.location(cloudName),
                   {},
                   readRelaxation(cloudDict, globalRelaxation),
                   cloudDict.found("relaxation") ? cloudDict.location("relaxation")
                   : dict.found("relaxation")    ? dict.location("relaxation")
                                                 : dict.location(),
                   readDensityStart(cloudDict, cloudName, settings)};
    if (cloudDict.found("fields")) {
      ParticleCloud none(cloudName);  // every key and value checked, nothing set
      setFieldValues(cloudDict.subDict("fields"), none, {}, true);
    }
    for (const std::string& regionName : regions.keys()) {
      const Dictionary& regionDict = regions.subDict(regionName);
      RegionFill fill{readFillRegion(regionDict, spacing, geometryFolder, dimension),
                      regionDict.get<std::string>("type") == "box", regionName,
                      regions.location(regionName)};
      if (dimension == 2) {
        total += fill.region->sectionAreaBound() / (spacing * spacing) +
                 (fill.region->upper() - fill.region->lower()).head<2>().sum() / spacing + 1.0;
      } else {
        total += fill.ownLattice ? latticeCountInBox(fill.region->lower().cast<Real>(),
                                                     fill.region->upper().cast<Real>(), spacing)
                                 : fill.region->volumeBound() / (spacing * spacing * spacing);
      }
      plan.regions.push_back(std::move(fill));
    }
    plans.push_back(std::move(plan));
  }
  if (total > maxParticles) {
    std::ostringstream message;
    message << "spacing " << spacing << " m would make " << total << " particles, more than "
            << "maxParticles " << maxParticles << " (raise maxParticles in " << dict.name()
            << " if you mean it)";
    throw DictionaryError(dict.location("spacing"), message.str());
  }

  // Fields on existing clouds, as OpenFOAM's setFields: all particles, or those in regions.
  // Done before the fill (which may relax for minutes), so that a mistake here stops at once.
  std::vector<ParticleCloud> setClouds;
  if (dict.found("setFields")) {
    const Dictionary& setFields = dict.subDict("setFields");
    for (const std::string& cloudName : setFields.keys()) {
      const Dictionary& entry = setFields.subDict(cloudName);
      entry.checkKeys({"fields", "regions"});
      const auto existing =
          std::find_if(moldClouds.begin(), moldClouds.end(),
                       [&](const ParticleCloud& c) { return c.name() == cloudName; });
      if (existing == moldClouds.end()) {
        std::string present;
        for (const auto& c : moldClouds) present += " " + c.name();
        throw DictionaryError(
            setFields.location(cloudName),
            "cloud '" + cloudName + "' has no file '" +
                (caseFolder.constantFile("particles") / (cloudName + ".vtp")).string() +
                "' (run particleizeMold first); the clouds there are (" + present + " )");
      }
      ParticleCloud cloud = *existing;
      std::vector<bool> selected;
      if (entry.found("regions")) {
        const Dictionary& regions = entry.subDict("regions");
        selected.assign(cloud.size(), false);
        for (const std::string& regionName : regions.keys()) {
          const auto region =
              readFillRegion(regions.subDict(regionName), spacing, geometryFolder, dimension);
          for (std::size_t i = 0; i < cloud.size(); ++i) {
            selected[i] = selected[i] || region->contains(cloud.positions()[i].cast<double>());
          }
        }
      }
      setFieldValues(entry.subDict("fields"), cloud, selected, false);
      setClouds.push_back(std::move(cloud));
    }
  }

  const MoldObstacles mold(moldClouds, spacing, clearance);
  std::vector<const ParticleCloud*> moldCloudList;
  for (const ParticleCloud& cloud : moldClouds) moldCloudList.push_back(&cloud);
  // as the flow takes it, unless controlDict's healthChecks names a domain of its own
  const Domain domain = defaultDomain(moldCloudList);
  std::vector<ParticleCloud> clouds;
  for (const CloudPlan& plan : plans) {
    ParticleCloud cloud = fillCloud(plan, spacing, dimension, mold, domain, settings);
    const Dictionary& cloudDict = cloudsDict.subDict(plan.name);
    if (cloudDict.found("fields")) setFieldValues(cloudDict.subDict("fields"), cloud, {}, true);
    if (plan.density) setMaterialDensity(*plan.density, cloud, spacing);
    clouds.push_back(std::move(cloud));
  }
  for (ParticleCloud& cloud : setClouds) clouds.push_back(std::move(cloud));
  return clouds;
}

}  // namespace sphcast
