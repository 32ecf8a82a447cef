// Where a morph writes its frames and morph.glb. Into the output folder
// itself, unless the folder holds an earlier morph's files (--force): then
// into a hidden folder inside it, whose files replace the earlier ones only
// once the morph is complete. A morph stopped or failed on its way (Ctrl-C,
// a bad frame) leaves the earlier morph as it was; before, the earlier files
// were removed first, and a stopped rerun left neither set whole.
#pragma once

#include <filesystem>

namespace lbmshape {

// The files a morph writes into its folder: frame_* meshes and morph.glb.
bool isMorphOutputFile(const std::filesystem::path& file);

class StagedFrames {
public:
  // The hidden folder's name: a fixed one, so that the one an aborted run
  // left behind (a second Ctrl-C ends the process without unwinding) is
  // removed by the next.
  static constexpr const char* hiddenFolderName = ".lbmshape-new-frames";

  // `folder` exists and is locked for this morph (FolderLock).
  explicit StagedFrames(const std::filesystem::path& folder);
  // Unless committed: removes the hidden folder and the new files in it.
  ~StagedFrames();
  StagedFrames(const StagedFrames&) = delete;
  StagedFrames& operator=(const StagedFrames&) = delete;

  // Where the frames and morph.glb are written now.
  const std::filesystem::path& destination() const { return destination_; }
  // Whether they replace an earlier morph's files at commit().
  bool replacesEarlierFiles() const { return destination_ != folder_; }

  // Puts the new files in the folder: removes the earlier morph's files,
  // moves the new ones in and removes the hidden folder. Throws OutputError.
  void commit();

private:
  std::filesystem::path folder_, destination_;
  bool committed_ = false;
};

}  // namespace lbmshape
