#include "lbmshape/pipeline/staged_frames.hpp"

#include <vector>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/temporary_files.hpp"
#include "lbmshape/mesh/mesh_format.hpp"
#include "lbmshape/pipeline/frame_writer.hpp"

namespace lbmshape {

namespace fs = std::filesystem;

bool isMorphOutputFile(const fs::path& file)
{
  return file.filename() == "morph.glb" || (FrameWriter::isFrameName(file) && meshFormatOf(file).has_value());
}

namespace {

bool holdsMorphOutput(const fs::path& folder)
{
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec))
    if (entry.is_regular_file(ec) && isMorphOutputFile(entry.path())) return true;
  return false;
}

}  // namespace

StagedFrames::StagedFrames(const fs::path& folder) : folder_(folder), destination_(folder)
{
  const fs::path hidden = folder / hiddenFolderName;
  std::error_code ec;
  fs::remove_all(hidden, ec);  // an aborted run's
  if (ec) throw OutputError("cannot remove " + hidden.string() + ", left by an earlier run: " + ec.message());
  if (!holdsMorphOutput(folder)) return;
  {
    const temporary_files::Creation creation;
    fs::create_directory(hidden, ec);
  }
  if (ec) throw OutputError("cannot create " + hidden.string() + " for the new frames: " + ec.message());
  destination_ = hidden;
}

StagedFrames::~StagedFrames()
{
  if (committed_ || !replacesEarlierFiles()) return;
  std::error_code ec;
  fs::remove_all(destination_, ec);
}

void StagedFrames::commit()
{
  if (!replacesEarlierFiles()) return;
  std::error_code ec;
  // Listed first, then changed: a folder is not changed while it is read.
  std::vector<fs::path> earlier, made;
  for (const auto& entry : fs::directory_iterator(folder_, ec))
    if (entry.is_regular_file() && isMorphOutputFile(entry.path())) earlier.push_back(entry.path());
  for (const auto& entry : fs::directory_iterator(destination_, ec)) made.push_back(entry.path());
  if (ec) throw OutputError("cannot list " + folder_.string() + ": " + ec.message());
  for (const fs::path& file : earlier)
    if (!fs::remove(file, ec) && ec)
      throw OutputError("cannot remove the earlier " + file.string() + ": " + ec.message());
  for (const fs::path& file : made) {
    fs::rename(file, folder_ / file.filename(), ec);
    if (ec)
      throw OutputError("cannot move the new " + file.filename().string() + " into " + folder_.string() + ": " +
                        ec.message());
  }
  fs::remove(destination_, ec);
  committed_ = true;
}

}  // namespace lbmshape
