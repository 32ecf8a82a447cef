// A morph as one animated glTF file: every frame is its own mesh in its own
// node, and an animation shows exactly one of them at a time. Scaling a node
// to zero is the way glTF has to hide it: visibility itself cannot be
// animated, and every viewer plays scale keys.
#pragma once

#include <filesystem>
#include <string>
#include <memory>
#include <vector>

#include "lbmshape/mesh/gltf_compression.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// Writes `frames` to a .gltf or .glb file. Node i (named "frame i") has a
// `scale` channel with STEP interpolation: 1 from i/fps until (i+1)/fps, 0
// before and after, the last frame staying until the end at frames/fps
// seconds. Without the animation playing (a still viewer), frame 0 shows. A
// frame without triangles is a node without a mesh: nothing shows in its turn.
// Written atomically, like writeMesh(). Throws UsageError for an unknown
// extension, no frames or a frame rate that is not positive, and OutputError
// as writeMesh() does (naming the frame that cannot be written).
void writeGltfAnimation(const std::vector<TriangleMesh>& frames, double fps, const std::filesystem::path& path,
                        GltfCompression compression = GltfCompression::None);

// The same file made frame by frame, as a morph's frames come (on its frame
// writer's thread, while the lattice computes the next ones). A plain .glb
// is streamed (GlbStream): each frame's arrays go to the file as they come
// and none stays in memory; only the JSON is left to write when the last
// frame is in. A compressed .glb or a .gltf is assembled in memory. The same
// checks and errors as writeGltfAnimation(): the arguments' in the
// constructor (which also makes the temporary file, so an unwritable folder
// is reported at once), a frame's in add(), a frame missing in write().
// Why glTF's single-precision key times cannot time `frameCount` frames at
// `fps`, with what to do ("" where they can): at a high enough rate the
// last frames' times round to the same float, at a low enough one the last
// time is beyond the largest float.
std::string untimeableInSinglePrecision(size_t frameCount, double fps);

class GltfAnimation {
public:
  GltfAnimation(std::filesystem::path path, size_t frameCount, double fps,
                GltfCompression compression = GltfCompression::None);
  ~GltfAnimation();
  GltfAnimation(const GltfAnimation&) = delete;
  GltfAnimation& operator=(const GltfAnimation&) = delete;

  void add(const TriangleMesh& frame);  // the next frame
  void write();                         // once every frame is in

private:
  struct Model;  // the glTF assembled so far
  std::filesystem::path path_;
  size_t frameCount_;
  double fps_;
  size_t added_ = 0;
  std::unique_ptr<Model> model_;
};

}  // namespace lbmshape
