#include "io/TimeFolders.h"

#include <algorithm>
#include <filesystem>
#include <set>

#include "core/AtomicFile.h"
#include "core/Error.h"
#include "core/Log.h"
#include "io/PvdIndex.h"
#include "io/PvtpCloud.h"
#include "io/VtpCloud.h"
#include "parallel/ParticleTransfer.h"

namespace fs = std::filesystem;

namespace sphcast {

namespace {

std::vector<fs::path> cloudFilesIn(const fs::path& folder) {
  std::vector<fs::path> files;
  if (!fs::is_directory(folder)) return files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const auto extension = entry.path().extension();
    if (entry.is_regular_file() && (extension == ".vtp" || extension == ".pvtp")) {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

void writeTimeFolder(const CaseFolder& caseFolder, const TimeState& time,
                     const std::vector<const ParticleCloud*>& clouds,
                     const std::vector<UniformFile>& uniformFiles, const Communicator& comm) {
  const std::string& timeName = time.name;
  const fs::path writing = caseFolder.writingFolder(timeName);
  const fs::path final = caseFolder.root() / timeName;
  const fs::path replaced = caseFolder.replacedFolder(timeName);
  const bool parallel = comm.size() > 1;
  if (comm.master()) {
    fs::remove_all(writing);
    fs::create_directories(writing / "uniform");
    for (const ParticleCloud* cloud : clouds) {
      if (!parallel) continue;
      fs::create_directories(pieceFile(writing / (cloud->name() + ".pvtp"), 0).parent_path());
    }
  }
  // in parallel each rank writes its piece of every cloud, and rank 0 the indexes and the rest
  comm.barrier();
  for (const ParticleCloud* cloud : clouds) {
    if (parallel) {
      writeCloudVtp(*cloud, pieceFile(writing / (cloud->name() + ".pvtp"), comm.rank()));
    } else {
      writeCloudVtp(*cloud, writing / (cloud->name() + ".vtp"));
    }
  }
  comm.barrier();
  if (comm.master()) {
    if (parallel) {
      for (const ParticleCloud* cloud : clouds) {
        writeCloudPvtpIndex(*cloud, writing / (cloud->name() + ".pvtp"), comm.size());
      }
    }
    writeFileAtomically(writing / "uniform" / "time", uniformTimeDictionary(time));
    for (const UniformFile& file : uniformFiles) {
      writeFileAtomically(writing / "uniform" / file.name, file.text);
    }
    // Two renames when the time exists already (a restart rewriting its start time, say); a
    // kill between them is repaired by CaseFolder::recoverInterruptedWrites.
    if (fs::exists(final)) {
      fs::remove_all(replaced);
      renameAtomically(final, replaced);
      renameAtomically(writing, final);
      fs::remove_all(replaced);
    } else {
      renameAtomically(writing, final);
    }
  }
  comm.barrier();
}

void writeCaseIndex(const CaseFolder& caseFolder) {
  std::vector<PvdEntry> entries;
  const auto staticClouds = cloudFilesIn(caseFolder.constant() / "particles");
  for (const TimeFolder& time : caseFolder.times()) {
    std::set<std::string> inTime;
    for (const fs::path& file : cloudFilesIn(caseFolder.root() / time.name)) {
      entries.push_back({time.value, time.name, file.stem().string(),
                         time.name + "/" + file.filename().string()});
      inTime.insert(file.stem().string());
    }
    // a mold as particleizeMold wrote it, unless the time has its own (a mold carrying heat,
    // with its T): the time's is the one to show
    for (const fs::path& file : staticClouds) {
      if (inTime.count(file.stem().string()) > 0) continue;
      entries.push_back({time.value, time.name, file.stem().string(),
                         "constant/particles/" + file.filename().string()});
    }
  }
  writePvd(caseFolder.pvdFile(), std::move(entries));
}

std::vector<fs::path> staleCaseIndexes(const CaseFolder& caseFolder) {
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(caseFolder.root())) {
    const fs::path& file = entry.path();
    if (!entry.is_regular_file() || file.extension() != ".pvd" || file == caseFolder.pvdFile()) {
      continue;
    }
    std::vector<PvdEntry> indexed;
    try {
      indexed = readPvd(file);
    } catch (const Error&) {
      continue;  // not an index sphCast writes
    }
    // "0.05/metal.vtp" or "constant/particles/mold.vtp", as writeCaseIndex writes them.
    const auto ofThisCase = [](const PvdEntry& dataSet) {
      const fs::path path(dataSet.file);
      const std::string folder = path.begin() == path.end() ? "" : path.begin()->string();
      return path.is_relative() && (folder == dataSet.timeName || folder == "constant") &&
             dataSet.file.find("..") == std::string::npos;
    };
    if (!indexed.empty() && std::all_of(indexed.begin(), indexed.end(), ofThisCase)) {
      stale.push_back(file);
    }
  }
  std::sort(stale.begin(), stale.end());
  return stale;
}

void warnOfStaleCaseIndexes(const CaseFolder& caseFolder) {
  for (const fs::path& stale : staleCaseIndexes(caseFolder)) {
    warning(stale.string() + " indexes this case's time folders, but is no longer updated: it " +
            "is named after another case folder (a copy?). The series is " +
            caseFolder.pvdFile().string() + "; remove " + stale.filename().string() + ".");
  }
}

std::vector<std::string> timeFolderCloudNames(const CaseFolder& caseFolder,
                                              const std::string& timeName) {
  std::vector<std::string> names;
  for (const fs::path& file : cloudFilesIn(caseFolder.root() / timeName)) {
    if (names.empty() || names.back() != file.stem().string()) {
      names.push_back(file.stem().string());
    }
  }
  return names;
}

std::vector<ParticleCloud> readTimeFolderClouds(const CaseFolder& caseFolder,
                                                const std::string& timeName,
                                                const Communicator& comm) {
  std::vector<ParticleCloud> clouds;
  for (const fs::path& file : cloudFilesIn(caseFolder.root() / timeName)) {
    const std::string name = file.stem().string();
    if (!clouds.empty() && clouds.back().name() == name) {
      throw Error(file.parent_path().string() + " holds cloud '" + name + "' twice, as " + name +
                  ".pvtp (a parallel run's) and " + name +
                  ".vtp (a serial run's): remove the one that is not wanted");
    }
    const int pieces =
        file.extension() == ".pvtp" ? static_cast<int>(readPvtpPieces(file).size()) : 1;
    if (pieces > 1) {
      // rank r of n reads pieces r, r + n, ...; a rank beyond the pieces (a restart onto more
      // ranks) reads none and takes the cloud's fields and attributes from rank 0's
      ParticleCloud cloud = comm.rank() < pieces
                                ? readCloudPvtp(file, name, comm.rank(), comm.size())
                                : ParticleCloud(name);
      if (comm.size() > pieces) {
        const std::string layout = comm.broadcast(comm.master() ? packLayout(cloud) : "");
        if (comm.rank() >= pieces) cloud = unpackLayout(layout);
      }
      clouds.push_back(std::move(cloud));
    } else {
      clouds.push_back(readOnMaster(
          [&] {
            return file.extension() == ".pvtp" ? readCloudPvtp(file, name, 0, 1)
                                               : readCloudVtp(file, name);
          },
          comm));
    }
  }
  return clouds;
}

}  // namespace sphcast
