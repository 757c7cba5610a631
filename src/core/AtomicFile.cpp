#include "core/AtomicFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include "core/Error.h"

namespace sphcast {

namespace {

[[noreturn]] void throwSystemError(const std::string& action, const std::filesystem::path& file,
                                   int errorNumber) {
  throw Error("cannot " + action + " '" + file.string() + "': " + std::strerror(errorNumber));
}

// Closes a POSIX file descriptor when it goes out of scope (errors at close are checked
// separately by closeChecked on the success path).
class FileDescriptor {
 public:
  explicit FileDescriptor(int descriptor) : descriptor_(descriptor) {}
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  ~FileDescriptor() {
    if (descriptor_ >= 0) ::close(descriptor_);
  }
  int get() const { return descriptor_; }
  int release() {
    const int descriptor = descriptor_;
    descriptor_ = -1;
    return descriptor;
  }

 private:
  int descriptor_;
};

void writeAll(int descriptor, std::string_view content, const std::filesystem::path& file) {
  while (!content.empty()) {
    const ssize_t written = ::write(descriptor, content.data(), content.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      throwSystemError("write", file, errno);
    }
    content.remove_prefix(static_cast<std::size_t>(written));
  }
}

void syncDescriptor(int descriptor, const std::filesystem::path& file) {
  while (::fsync(descriptor) != 0) {
    if (errno != EINTR) throwSystemError("flush to disk", file, errno);
  }
}

void closeChecked(FileDescriptor& descriptor, const std::filesystem::path& file) {
  if (::close(descriptor.release()) != 0) throwSystemError("close", file, errno);
}

// The folder a file lies in, "." for a bare file name.
std::filesystem::path folderOf(const std::filesystem::path& file) {
  const std::filesystem::path folder = file.parent_path();
  return folder.empty() ? std::filesystem::path(".") : folder;
}

}  // namespace

std::filesystem::path temporaryPathFor(const std::filesystem::path& file) {
  std::filesystem::path temporary = file;
  temporary += ".tmp";
  return temporary;
}

void syncFileToDisk(const std::filesystem::path& file) {
  FileDescriptor descriptor(::open(file.c_str(), O_RDONLY | O_CLOEXEC));
  if (descriptor.get() < 0) throwSystemError("open", file, errno);
  syncDescriptor(descriptor.get(), file);
  closeChecked(descriptor, file);
}

void renameAtomically(const std::filesystem::path& from, const std::filesystem::path& to) {
  if (std::rename(from.c_str(), to.c_str()) != 0) {
    throw Error("cannot rename '" + from.string() + "' to '" + to.string() +
                "': " + std::strerror(errno));
  }
  // The rename lives in the folder's entry list: sync the folder too, or a crash may undo it.
  // Some file systems refuse fsync on a folder (EINVAL); the rename itself is still atomic.
  const std::filesystem::path folder = folderOf(to);
  FileDescriptor folderDescriptor(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (folderDescriptor.get() >= 0) ::fsync(folderDescriptor.get());
}

void writeFileAtomically(const std::filesystem::path& file, std::string_view content) {
  const std::filesystem::path temporary = temporaryPathFor(file);
  try {
    FileDescriptor descriptor(
        ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666));
    if (descriptor.get() < 0) throwSystemError("create", temporary, errno);
    writeAll(descriptor.get(), content, temporary);
    syncDescriptor(descriptor.get(), temporary);
    closeChecked(descriptor, temporary);
    renameAtomically(temporary, file);
  } catch (const Error& error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw Error("cannot write '" + file.string() + "': " + error.what());
  }
}

}  // namespace sphcast
