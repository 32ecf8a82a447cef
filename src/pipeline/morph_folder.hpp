// A morph's output folder, from before any work to the end of the morph.
// It is checked (a folder, empty unless --force, writable), made with any
// missing parents and locked (FolderLock) before the meshes are read, so
// that a second lbmshape writing into it fails at once. The folders it made
// go again if the morph fails before its first frame, so a failed morph
// leaves no empty folder behind.
//
// Only folders this process made go, and only while it holds the lock:
// when two morphs started on one missing folder, each used to take the
// folder for its own new one, the loser of the lock removed it while empty,
// and the winner exited 0 with its frames gone.
#pragma once

#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

#include "lbmshape/core/folder_lock.hpp"

namespace lbmshape {

class MorphFolder {
public:
  // Throws OutputError naming the folder: a file, not empty without
  // `force`, not writable, not made, or locked by another lbmshape.
  MorphFolder(const std::filesystem::path& folder, bool force);
  // Unless kept: removes the folders it made that are still empty, the
  // morph's own first, up to the topmost.
  ~MorphFolder();
  MorphFolder(const MorphFolder&) = delete;
  MorphFolder& operator=(const MorphFolder&) = delete;

  const std::filesystem::path& path() const { return folder_; }
  void keep();

private:
  void make();  // the folder and its missing parents, each noted if this process made it
  void forgetMade();
  void removeEmptyMade();  // then forgets them

  std::filesystem::path folder_;
  // Each folder made, with its ticket in temporary_files (for a process
  // that ends without unwinding, which removes the empty ones); the topmost first.
  std::vector<std::pair<std::filesystem::path, int>> made_;
  std::optional<FolderLock> lock_;
};

}  // namespace lbmshape
