// One writer per output folder: an exclusive flock(2) on the folder itself,
// held while the object lives (and released by the kernel however the
// process ends). A second lbmshape writing frames into the same folder
// fails at once instead of interleaving its frames with the first one's.
// Locking the folder, not a file in it, leaves nothing behind.
#pragma once

#include <filesystem>

namespace lbmshape {

class FolderLock {
public:
  // Throws OutputError naming the folder when another process holds it, or
  // when it cannot be opened; on a file system without locks it goes on
  // unlocked.
  explicit FolderLock(const std::filesystem::path& folder);
  ~FolderLock();

  FolderLock(FolderLock&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

private:
  int fd_ = -1;
};

}  // namespace lbmshape
