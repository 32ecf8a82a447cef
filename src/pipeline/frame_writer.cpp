#include "lbmshape/pipeline/frame_writer.hpp"
#include "lbmshape/pipeline/staged_frames.hpp"

#include <cxxabi.h>

#include <cstdio>
#include <system_error>
#include <type_traits>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/host_memory.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/core/stopwatch.hpp"
#include "lbmshape/core/worker_threads.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "lbmshape/surface/band_marching_cubes.hpp"
#include "lbmshape/surface/marching_cubes.hpp"

namespace lbmshape {
namespace {
constexpr size_t queueCapacity = 2;
constexpr size_t kCommitsWaiting = 2;
}  // namespace

FrameWriter::FrameWriter(const GridFrame& grid, std::filesystem::path folder, std::string extension, int frameCount,
                         Keep keep, Inspect inspect, GltfCompression compression, Decorate decorate)
    : FrameWriter(grid, std::move(folder), std::move(extension), FrameSink(), frameCount, keep, std::move(inspect),
                  compression, std::move(decorate))
{}

FrameWriter::FrameWriter(const GridFrame& grid, FrameSink sink, int frameCount, Keep keep, Inspect inspect,
                         Decorate decorate)
    : FrameWriter(grid, {}, {}, std::move(sink), frameCount, keep, std::move(inspect), GltfCompression::None,
                  std::move(decorate))
{}

FrameWriter::FrameWriter(const GridFrame& grid, std::filesystem::path folder, std::string extension, FrameSink sink,
                         int frameCount, Keep keep, Inspect inspect, GltfCompression compression, Decorate decorate)
    : grid_(grid), folder_(std::move(folder)), extension_(std::move(extension)), frameCount_(frameCount),
      digits_(std::max(4, int(std::to_string(std::max(frameCount - 1, 0)).size()))), keep_(keep),
      inspect_(std::move(inspect)), compression_(compression), decorate_(std::move(decorate)), sink_(std::move(sink))
{
  // The commits go to a thread of their own where one can be had: not
  // under an address-space limit (a thread costs a malloc arena, and
  // lavapipe's own threads need the room: see runSideBySide), nor where
  // none can be started. There the writer's thread commits each frame itself.
  if (!sink_ && addressSpaceUnlimited()) {
    try {
      committer_ = std::thread([this] { commitFrames(); });
    } catch (const std::system_error&) {}
  }
  commitBeside_ = committer_.joinable();
  try {
    thread_ = std::thread([this] { run(); });
  } catch (...) {
    stopCommitter();
    throw;
  }
}

void FrameWriter::stopCommitter()
{
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    toCommit_.clear();  // their temporary files removed
  }
  changed_.notify_all();
  if (committer_.joinable()) committer_.join();
}

FrameWriter::~FrameWriter()
{
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    queue_.clear();
  }
  changed_.notify_all();
  thread_.join();
  stopCommitter();  // drops the frames still waiting for their commit
}

bool FrameWriter::isFrameName(const std::filesystem::path& file)
{
  return file.filename().string().rfind("frame_", 0) == 0;
}

std::filesystem::path FrameWriter::framePath(int index) const
{
  char name[64];
  std::snprintf(name, sizeof name, "frame_%0*d", digits_, index);
  return folder_ / (name + extension_);
}

double FrameWriter::push(int index, FrameField field)
{
  Stopwatch waited;
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return queue_.size() < queueCapacity || error_; });
  if (error_) rethrowSayingWhatIsComplete();
  const double ms = waited.ms();
  queue_.emplace_back(index, std::move(field));
  changed_.notify_all();
  return ms;
}

std::vector<TriangleMesh> FrameWriter::finish()
{
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return (queue_.empty() && !busy_ && toCommit_.empty() && !committing_) || error_; });
  if (error_) rethrowSayingWhatIsComplete();
  return std::move(meshes_);
}

void FrameWriter::rethrowSayingWhatIsComplete() const
{
  if (sink_) std::rethrow_exception(error_);
  try {
    std::rethrow_exception(error_);
  } catch (const OutputError& e) {
    // A disk full or a file-size limit part way: the frames before the
    // failure stay, whole, and a user should not have to list the folder
    // to learn which (a stop by a signal says so too).
    // Frames staged to replace an earlier morph's are removed with their
    // hidden folder (StagedFrames): the earlier files stay.
    if (folder_.filename() == StagedFrames::hiddenFolderName)
      throw OutputError(std::string(e.what()) + "; " + folder_.parent_path().string() +
                        " keeps the earlier morph's files");
    if (written_ == 0) throw OutputError(std::string(e.what()) + "; no frame was written");
    const std::string kept = written_ == 1 ? framePath(0).filename().string() + " is complete"
                                           : framePath(0).filename().string() + " to " +
                                                 framePath(written_ - 1).filename().string() + " are complete";
    throw OutputError(std::string(e.what()) + "; " + kept + " in " + folder_.string());
  }
}

std::vector<int> FrameWriter::emptyFrames() const
{
  std::lock_guard lock(mutex_);
  return emptyFrames_;
}

int FrameWriter::stop()
{
  std::unique_lock lock(mutex_);
  stopping_ = true;
  queue_.clear();
  toCommit_.clear();  // their temporary files removed
  changed_.notify_all();
  changed_.wait(lock, [&] { return !busy_ && !committing_; });
  return written_;
}
double FrameWriter::extractMs() const
{
  std::lock_guard lock(mutex_);
  return extractMs_;
}
double FrameWriter::writeMs() const
{
  std::lock_guard lock(mutex_);
  return writeMs_;
}
double FrameWriter::commitMs() const
{
  std::lock_guard lock(mutex_);
  return commitMs_;
}

void FrameWriter::run()
{
  // Extraction runs parallel loops on this thread: their OpenMP threads are
  // made now, before the lattice takes its memory (core/worker_threads.hpp).
  prepareParallelRegions();
  FrameField previousField;
  for (;;) {
    std::pair<int, FrameField> job;
    {
      std::unique_lock lock(mutex_);
      // After an error nothing more is made: the first error is the one the
      // lattice's thread sees (a later frame's would replace it).
      changed_.wait(lock, [&] { return stopping_ || (!queue_.empty() && !error_); });
      if (stopping_) return;
      job = queue_.front();
      queue_.pop_front();
      busy_ = true;
    }
    try {
      Stopwatch extract;
      TriangleMesh mesh;
      if (job.second == previousField) {
        std::lock_guard lock(mutex_);
        mesh = meshes_.back();
      } else {
        mesh = std::visit(
            [this](const auto& field) {
              if constexpr (std::is_same_v<std::decay_t<decltype(*field)>, SurfacePieces>)
                return assembleSurface(*field, grid_);
              else
                return extractSurface(*field, grid_);
            },
            job.second);
        if (decorate_) decorate_(mesh);
      }
      const bool empty = mesh.triangles.empty();
      if (empty && job.first == frameCount_ - 1)
        throw NumericalError("frame " + std::to_string(job.first) +
                             ", the last, has no surface: the morph ended with no inside at all, on its way from "
                             "the source to a target it does not overlap; give it more " +
                             nameOf(Parameter::Steps) + " or a larger " + nameOf(Parameter::Cs) +
                             ", or place the shapes to overlap with " + nameOf(Parameter::Align));
      const double extractMs = extract.ms();
      Stopwatch write;
      std::unique_ptr<AtomicFile> file;
      if (sink_)
        sink_(job.first, mesh);
      else
        file = writeMeshUncommitted(mesh, framePath(job.first), EmptyMesh::Allowed, compression_);
      const size_t vertices = mesh.vertexCount(), triangles = mesh.triangleCount();
      double commitMs = 0.0;
      if (file && !commitBeside_) {
        const Stopwatch commit;
        commitMesh(*file, vertices, triangles);
        file.reset();
        commitMs = commit.ms();
      }
      const double writeMs = write.ms() - commitMs;
      if (inspect_) inspect_(job.first, job.second, mesh);
      previousField = job.second;
      std::unique_lock lock(mutex_);
      if (empty) emptyFrames_.push_back(job.first);
      if (keep_ == Keep::LastFrame && !meshes_.empty())
        meshes_.back() = std::move(mesh);
      else
        meshes_.push_back(std::move(mesh));
      extractMs_ += extractMs;
      writeMs_ += writeMs;
      commitMs_ += commitMs;
      if (file) {
        // At most kCommitsWaiting frames wait for their commit: each holds a
        // temporary file, listed for the last-resort cleanup (which has room
        // for a few), and the frames must not pile up on disk.
        changed_.wait(lock, [&] { return toCommit_.size() < kCommitsWaiting || stopping_ || error_; });
        if (stopping_ || error_)
          file.reset();  // dropped: its temporary file goes before stop() returns
        else
          toCommit_.push_back({std::move(file), vertices, triangles});
      } else {
        ++written_;  // committed here, or handed to the sink
      }
      busy_ = false;
    } catch (abi::__forced_unwind&) {
      // The thread is being ended (pthread_exit, as Python does to a thread
      // that takes the GIL at exit, in a FrameSink): unwinding must go on,
      // or the runtime aborts the process.
      throw;
    } catch (...) {
      std::unique_lock lock(mutex_);
      // The frames made before this one are whole: their commits end first,
      // so that the frames left are every one before the failure, whatever
      // the two threads' timing (before, 2 to 4 of them, run to run).
      if (commitBeside_)
        changed_.wait(lock, [&] { return (toCommit_.empty() && !committing_) || stopping_ || error_; });
      if (!error_) error_ = std::current_exception();
      busy_ = false;
    }
    changed_.notify_all();
  }
}

void FrameWriter::commitFrames()
{
  for (;;) {
    MadeFile made;
    {
      std::unique_lock lock(mutex_);
      // After an error nothing more is committed: the frames on disk stay
      // the first ones, in order.
      changed_.wait(lock, [&] { return stopping_ || (!toCommit_.empty() && !error_); });
      if (stopping_) return;
      made = std::move(toCommit_.front());
      toCommit_.pop_front();
      committing_ = true;
    }
    // (Its time is not the write stage's, beside which it runs: commitMs().)
    try {
      const Stopwatch commit;
      commitMesh(*made.file, made.vertices, made.triangles);
      std::lock_guard lock(mutex_);
      commitMs_ += commit.ms();
      ++written_;
      committing_ = false;
    } catch (...) {
      std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
      made.file.reset();  // its temporary file goes before stop() or finish() returns
      committing_ = false;
    }
    changed_.notify_all();
  }
}

}  // namespace lbmshape
