#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sphcast {

// How time folder names are printed (controlDict timeFormat), as OpenFOAM prints them.
enum class TimeFormat { general, fixed, scientific };

// OpenFOAM's folder name for a time: timeName(0.1, general, 6) == "0.1".
std::string timeName(double time, TimeFormat format, int precision);

struct TimeFolder {
  double value;      // parsed from the name; the exact time is in <name>/uniform/time
  std::string name;  // the folder name as written
};

// The times a -time option selects: "0.1,0.5" (listed), "0.1:0.5" (a closed range), ":0.5",
// "0.1:" or a mix of these, comma-separated. Throws an Error for a malformed list.
std::vector<TimeFolder> selectTimes(const std::vector<TimeFolder>& times, const std::string& list);

// The case folder contract of doc/design.md §2: system/, constant/, one folder per written time.
class CaseFolder {
 public:
  // Throws an Error when the folder or its system/ is missing, or the folder is not writable
  // (every tool writes its results into the case).
  explicit CaseFolder(const std::filesystem::path& root);

  const std::filesystem::path& root() const { return root_; }
  // The folder's own name, used for <case>.pvd.
  std::string name() const;
  std::filesystem::path system() const { return root_ / "system"; }
  std::filesystem::path constant() const { return root_ / "constant"; }
  std::filesystem::path systemFile(const std::string& fileName) const { return system() / fileName; }
  std::filesystem::path constantFile(const std::string& fileName) const {
    return constant() / fileName;
  }
  std::filesystem::path pvdFile() const { return root_ / (name() + ".pvd"); }

  // Complete time folders, ascending. Folders being written (hidden names) never count.
  std::vector<TimeFolder> times() const;

  // Repairs what a process killed inside a time-folder write can leave behind: a complete old
  // folder set aside while its replacement was being moved in is put back, unfinished folders
  // are removed. Returns the names it repaired or removed, for the log.
  std::vector<std::string> recoverInterruptedWrites() const;

  // Names used while a time folder is written (doc/design.md §2: write, then rename).
  std::filesystem::path writingFolder(const std::string& timeFolderName) const;
  std::filesystem::path replacedFolder(const std::string& timeFolderName) const;
  std::filesystem::path purgedFolder(const std::string& timeFolderName) const;

 private:
  std::filesystem::path root_;
};

}  // namespace sphcast
