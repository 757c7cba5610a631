#include "io/TimeFolders.h"

#include <algorithm>
#include <filesystem>

#include "core/AtomicFile.h"
#include "io/PvdIndex.h"
#include "io/VtpCloud.h"

namespace fs = std::filesystem;

namespace sphcast {

namespace {

std::vector<fs::path> cloudFilesIn(const fs::path& folder) {
  std::vector<fs::path> files;
  if (!fs::is_directory(folder)) return files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.is_regular_file() && entry.path().extension() == ".vtp") {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

void writeTimeFolder(const CaseFolder& caseFolder, const TimeState& time,
                     const std::vector<const ParticleCloud*>& clouds) {
  const std::string& timeName = time.name;
  const fs::path writing = caseFolder.writingFolder(timeName);
  const fs::path final = caseFolder.root() / timeName;
  const fs::path replaced = caseFolder.replacedFolder(timeName);
  fs::remove_all(writing);
  fs::create_directories(writing / "uniform");
  for (const ParticleCloud* cloud : clouds) {
    writeCloudVtp(*cloud, writing / (cloud->name() + ".vtp"));
  }
  writeFileAtomically(writing / "uniform" / "time", uniformTimeDictionary(time));

  // Two renames when the time exists already (a restart rewriting its start time, say); a kill
  // between them is repaired by CaseFolder::recoverInterruptedWrites.
  if (fs::exists(final)) {
    fs::remove_all(replaced);
    renameAtomically(final, replaced);
    renameAtomically(writing, final);
    fs::remove_all(replaced);
  } else {
    renameAtomically(writing, final);
  }
}

void writeCaseIndex(const CaseFolder& caseFolder) {
  std::vector<PvdEntry> entries;
  const auto staticClouds = cloudFilesIn(caseFolder.constant() / "particles");
  for (const TimeFolder& time : caseFolder.times()) {
    for (const fs::path& file : cloudFilesIn(caseFolder.root() / time.name)) {
      entries.push_back({time.value, time.name, file.stem().string(),
                         time.name + "/" + file.filename().string()});
    }
    for (const fs::path& file : staticClouds) {
      entries.push_back({time.value, time.name, file.stem().string(),
                         "constant/particles/" + file.filename().string()});
    }
  }
  writePvd(caseFolder.pvdFile(), std::move(entries));
}

std::vector<ParticleCloud> readTimeFolderClouds(const CaseFolder& caseFolder,
                                                const std::string& timeName) {
  std::vector<ParticleCloud> clouds;
  for (const fs::path& file : cloudFilesIn(caseFolder.root() / timeName)) {
    clouds.push_back(readCloudVtp(file, file.stem().string()));
  }
  return clouds;
}

}  // namespace sphcast
