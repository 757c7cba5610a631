#pragma once

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace sphcast::testing {

// A case folder of its own for one test, under the system's temporary folder, removed after.
class TemporaryCase {
 public:
  explicit TemporaryCase(const std::string& name = "case") {
    static std::atomic<int> counter{0};
    root_ = std::filesystem::temp_directory_path() /
            ("sphCastTest-" + std::to_string(getpid()) + "-" + std::to_string(counter++)) / name;
    std::filesystem::create_directories(root_ / "system");
    std::filesystem::create_directories(root_ / "constant");
  }
  ~TemporaryCase() { std::filesystem::remove_all(root_.parent_path()); }
  TemporaryCase(const TemporaryCase&) = delete;
  TemporaryCase& operator=(const TemporaryCase&) = delete;

  const std::filesystem::path& root() const { return root_; }

  // Writes a file relative to the case root; its modification time is moved forward so that a
  // re-read sees the change even within the file system's timestamp granularity.
  void write(const std::string& relative, const std::string& text) const {
    const auto path = root_ / relative;
    std::filesystem::create_directories(path.parent_path());
    const bool existed = std::filesystem::exists(path);
    const auto before = existed ? std::filesystem::last_write_time(path)
                                : std::filesystem::file_time_type::clock::now();
    std::ofstream(path) << text;
    if (existed) std::filesystem::last_write_time(path, before + std::chrono::seconds(1));
  }

 private:
  std::filesystem::path root_;
};

}  // namespace sphcast::testing
