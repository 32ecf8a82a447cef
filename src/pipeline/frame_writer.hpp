// Turns the fields of a morph into frame files on a thread of its own, so
// that the lattice computes frame k+1 while frame k is extracted and written.
// What is written does not depend on this: every frame is a copy of the field
// taken between steps, and the files are written in order. A second thread
// commits the files, in the same order (forced to disk, then renamed:
// AtomicFile), while the first makes the next frame: on the H100's host a
// frame's commit took longer than its making. (Under an address-space
// limit, or where no second thread starts, the first commits them itself.)
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <variant>
#include <vector>

#include "lbmshape/band/band_field.hpp"
#include "lbmshape/core/atomic_file.hpp"
#include "lbmshape/core/volume.hpp"
#include "lbmshape/mesh/gltf_compression.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"
#include "lbmshape/sdf/grid_frame.hpp"
#include "lbmshape/surface/surface_pieces.hpp"

namespace lbmshape {

// A frame's field: on the whole grid, on the narrow band, or the pieces of
// its surface that the device listed (ComputeDevice::surfacesOnTheDevice).
using FrameField =
    std::variant<std::shared_ptr<const Volume>, std::shared_ptr<const BandField>, std::shared_ptr<const SurfacePieces>>;

// Where a morph's frames go when they are not files: called with each
// frame's index and mesh, in frame order, on the frame writer's thread.
using FrameSink = std::function<void(int frame, const TriangleMesh& mesh)>;

class FrameWriter {
public:
  // Which meshes stay in memory once written: every frame's (for the
  // animation, which holds them all), or only the latest (which the next
  // frame repeats when its field is the same, and the morph's figures use).
  enum class Keep { EveryFrame, LastFrame };

  // Runs on the writer's thread once frame k's file is written (perhaps not
  // yet committed under its name), with its field and mesh (the morph's
  // per-frame figures).
  using Inspect = std::function<void(int frame, const FrameField& field, const TriangleMesh& mesh)>;
  // Runs on the writer's thread on each frame's mesh before it is written
  // (vertex colours).
  using Decorate = std::function<void(TriangleMesh& mesh)>;

  // Frame k goes to folder/frame_<k, 4 digits or more><extension>.
  FrameWriter(const GridFrame& grid, std::filesystem::path folder, std::string extension, int frameCount, Keep keep,
              Inspect inspect = {}, GltfCompression compression = GltfCompression::None, Decorate decorate = {});
  // Frame k goes to `sink` instead of a file.
  FrameWriter(const GridFrame& grid, FrameSink sink, int frameCount, Keep keep, Inspect inspect = {},
              Decorate decorate = {});
  ~FrameWriter();  // stops both threads; frames queued or not yet committed are dropped
  FrameWriter(const FrameWriter&) = delete;
  FrameWriter& operator=(const FrameWriter&) = delete;

  std::filesystem::path framePath(int index) const;
  // Whether a file's name is a frame's (frame_<number>), as framePath makes it.
  static bool isFrameName(const std::filesystem::path& file);

  // Queues frame `index`'s field (pass the same pointer again for a frame
  // identical to the previous one: it is written without extracting again).
  // Blocks while two frames are already waiting, and returns the
  // milliseconds it waited. Rethrows an error of either thread.
  double push(int index, FrameField field);

  // Waits until every queued frame is written and committed; returns the
  // meshes kept, in frame order (with Keep::LastFrame, the last one alone).
  // Rethrows an error of either thread.
  std::vector<TriangleMesh> finish();

  // A frame may have no surface where the shape passes through nothing on
  // its way (source and target apart); it is written as a file with no
  // triangles. Only the last frame must have a surface: without one the
  // morph has failed, and the writer stops with a NumericalError instead of
  // writing it.
  std::vector<int> emptyFrames() const;

  // Stops: the frame being committed is finished, the queued ones and the
  // one being made are dropped (their temporary files removed). Returns the
  // frames complete on disk, all of them final: the first ones, in order.
  int stop();
  double extractMs() const;
  double writeMs() const;
  // The commits' time (forcing each file to disk, renaming it), on the
  // second thread beside the writing where it runs, so not in writeMs().
  double commitMs() const;

private:
  // Both public constructors: files when `sink` is empty.
  FrameWriter(const GridFrame& grid, std::filesystem::path folder, std::string extension, FrameSink sink,
              int frameCount, Keep keep, Inspect inspect, GltfCompression compression, Decorate decorate);
  void run();            // makes each frame: its mesh, its figures, its temporary file
  void commitFrames();   // puts each made file under its name, in order
  void stopCommitter();  // ends commitFrames(), dropping what waits

  GridFrame grid_;
  std::filesystem::path folder_;
  std::string extension_;
  int frameCount_;
  int digits_;
  Keep keep_;
  Inspect inspect_;
  GltfCompression compression_;
  Decorate decorate_;
  FrameSink sink_;  // set: frames go here, not to files

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::pair<int, FrameField>> queue_;
  bool stopping_ = false;
  bool busy_ = false;
  std::exception_ptr error_;
  // Rethrows error_; an OutputError with the frames it leaves complete.
  [[noreturn]] void rethrowSayingWhatIsComplete() const;
  std::vector<TriangleMesh> meshes_;
  int written_ = 0;
  std::vector<int> emptyFrames_;
  double extractMs_ = 0.0, writeMs_ = 0.0, commitMs_ = 0.0;
  struct MadeFile {
    std::unique_ptr<AtomicFile> file;
    size_t vertices = 0, triangles = 0;
  };
  std::deque<MadeFile> toCommit_;  // no bound: each waits on disk, not in memory
  bool committing_ = false;
  bool commitBeside_ = false;  // committer_ runs; set before either thread starts
  std::thread thread_, committer_;
};

}  // namespace lbmshape
