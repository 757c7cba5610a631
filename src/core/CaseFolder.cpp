#include "core/CaseFolder.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

#include <unistd.h>

#include "core/Error.h"

namespace fs = std::filesystem;

namespace sphcast {

std::string timeName(double time, TimeFormat format, int precision) {
  // Times that are zero to within rounding print as "0", as OpenFOAM does.
  if (std::abs(time) < 1e-300) time = 0.0;
  const char* pattern = format == TimeFormat::fixed        ? "%.*f"
                        : format == TimeFormat::scientific ? "%.*e"
                                                           : "%.*g";
  char text[64];
  std::snprintf(text, sizeof text, pattern, precision, time);
  return text;
}

namespace {

// A time folder's name is a number and nothing else ("0", "0.05", "1e-05").
bool parseTimeName(const std::string& name, double& value) {
  if (name.empty() || name.front() == '.') return false;
  errno = 0;
  char* end = nullptr;
  value = std::strtod(name.c_str(), &end);
  return errno == 0 && end == name.c_str() + name.size() && std::isfinite(value);
}

constexpr const char* writingSuffix = ".writing";
constexpr const char* replacedSuffix = ".replaced";
constexpr const char* purgedSuffix = ".purged";

double parseTimeBound(const std::string& text, const std::string& list, double fallback) {
  if (text.empty()) return fallback;
  double value = 0.0;
  if (!parseTimeName(text, value)) {
    throw Error("bad time '" + text + "' in -time '" + list + "'");
  }
  return value;
}

}  // namespace

std::vector<TimeFolder> selectTimes(const std::vector<TimeFolder>& times, const std::string& list) {
  std::vector<TimeFolder> selected;
  std::size_t begin = 0;
  while (begin <= list.size()) {
    const std::size_t end = std::min(list.find(',', begin), list.size());
    const std::string item = list.substr(begin, end - begin);
    const std::size_t colon = item.find(':');
    const double lowest = -std::numeric_limits<double>::max();
    const double highest = std::numeric_limits<double>::max();
    double from = 0.0;
    double to = 0.0;
    if (colon == std::string::npos) {
      from = to = parseTimeBound(item, list, std::nan(""));
    } else {
      from = parseTimeBound(item.substr(0, colon), list, lowest);
      to = parseTimeBound(item.substr(colon + 1), list, highest);
    }
    if (std::isnan(from)) throw Error("empty time in -time '" + list + "'");
    for (const TimeFolder& time : times) {
      // A listed time matches its folder to the precision the name was printed with.
      const double slack = 1e-12 * std::max(1.0, std::abs(time.value));
      const bool inside = time.value >= from - slack && time.value <= to + slack;
      const bool known = std::any_of(selected.begin(), selected.end(),
                                     [&](const TimeFolder& s) { return s.name == time.name; });
      if (inside && !known) selected.push_back(time);
    }
    begin = end + 1;
  }
  std::sort(selected.begin(), selected.end(),
            [](const TimeFolder& a, const TimeFolder& b) { return a.value < b.value; });
  return selected;
}

CaseFolder::CaseFolder(const fs::path& root) : root_(fs::absolute(root).lexically_normal()) {
  if (!root_.has_filename()) root_ = root_.parent_path();  // "case/" normalises to "case/"
  if (!fs::is_directory(root_)) {
    throw Error("case folder '" + root.string() + "' does not exist");
  }
  if (!fs::is_directory(system())) {
    throw Error("'" + root.string() + "' is not a case folder: it has no system/ folder");
  }
  // Every tool writes into the case (time folders, <case>.pvd, postProcessing/): a case that
  // cannot be written is refused now, not at the first write after hours of running.
  if (::access(root_.c_str(), W_OK | X_OK) != 0) {
    const std::string reason = std::strerror(errno);
    throw Error("case folder '" + root_.string() + "' is not writable (" + reason +
                "): the tools write their results into it; copy the case to a writable place "
                "or make it writable");
  }
}

std::string CaseFolder::name() const { return root_.filename().string(); }

std::vector<TimeFolder> CaseFolder::times() const {
  std::vector<TimeFolder> found;
  for (const auto& entry : fs::directory_iterator(root_)) {
    double value = 0.0;
    const std::string folderName = entry.path().filename().string();
    if (entry.is_directory() && parseTimeName(folderName, value)) {
      found.push_back({value, folderName});
    }
  }
  std::sort(found.begin(), found.end(),
            [](const TimeFolder& a, const TimeFolder& b) { return a.value < b.value; });
  return found;
}

fs::path CaseFolder::writingFolder(const std::string& timeFolderName) const {
  return root_ / ("." + timeFolderName + writingSuffix);
}

fs::path CaseFolder::replacedFolder(const std::string& timeFolderName) const {
  return root_ / ("." + timeFolderName + replacedSuffix);
}

fs::path CaseFolder::purgedFolder(const std::string& timeFolderName) const {
  return root_ / ("." + timeFolderName + purgedSuffix);
}

std::vector<std::string> CaseFolder::recoverInterruptedWrites() const {
  std::vector<std::string> repaired;
  auto endsWith = [](const std::string& s, const std::string& tail) {
    return s.size() > tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
  };
  for (const auto& entry : fs::directory_iterator(root_)) {
    const std::string folderName = entry.path().filename().string();
    if (!entry.is_directory() || folderName.front() != '.') continue;
    if (endsWith(folderName, replacedSuffix)) {
      const std::string time =
          folderName.substr(1, folderName.size() - 1 - std::string(replacedSuffix).size());
      if (fs::exists(root_ / time)) {
        fs::remove_all(entry.path());  // the replacement made it: the old copy is garbage
      } else {
        fs::rename(entry.path(), root_ / time);  // killed between the two renames: put it back
      }
      repaired.push_back(folderName);
    } else if (endsWith(folderName, writingSuffix) || endsWith(folderName, purgedSuffix)) {
      fs::remove_all(entry.path());  // never completed, or half removed by purgeWrite
      repaired.push_back(folderName);
    }
  }
  return repaired;
}

}  // namespace sphcast
