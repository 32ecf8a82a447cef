#include "mesh/gltf_animation.hpp"

#include <cmath>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "mesh/gltf_builder.hpp"
#include "mesh/mesh_format.hpp"
#include "mesh/writable_mesh.hpp"

namespace lbmshape {
namespace {

// The keys of frame i's scale: shown (1) from i/fps to (i+1)/fps, hidden (0)
// otherwise. Each node needs at most three keys, so the file grows linearly
// with the number of frames; a key at t = 0 is needed because glTF holds the
// first key's value before it. The last frame ends the animation at n/fps.
struct ScaleKeys {
  std::vector<float> times;
  std::vector<float> scales;  // xyz per key
};

ScaleKeys scaleKeys(size_t frame, size_t frames, double fps)
{
  ScaleKeys keys;
  auto add = [&](size_t step, float scale) {
    keys.times.push_back(float(double(step) / fps));
    keys.scales.insert(keys.scales.end(), {scale, scale, scale});
  };
  if (frame > 0) add(0, 0.0f);
  add(frame, 1.0f);
  add(frame + 1, frame + 1 < frames ? 0.0f : 1.0f);
  return keys;
}

}  // namespace

void writeGltfAnimation(const std::vector<TriangleMesh>& frames, double fps, const std::filesystem::path& path,
                        GltfCompression compression)
{
  const std::string prefix = "cannot write " + path.string() + ": ";
  const auto format = meshFormatOf(path);
  if (format != MeshFormat::Gltf && format != MeshFormat::Glb)
    throw UsageError(prefix + "an animation is written as glTF, so the file name must end in .gltf or .glb, not '" +
                     path.extension().string() + "'");
  if (frames.empty()) throw UsageError(prefix + "the animation has no frames");
  if (!std::isfinite(fps) || fps <= 0)
    throw UsageError(prefix + "the frame rate must be a positive number, not " + std::to_string(fps));
  // Keys closer than float resolution would not be increasing any more.
  if (float(double(frames.size()) / fps) <= float(double(frames.size() - 1) / fps))
    throw UsageError(prefix + std::to_string(frames.size()) + " frames at " + std::to_string(fps) +
                     " per second are too many to time in single precision");
  // A frame may be empty (a morph through nothing): its node has no mesh.
  for (size_t i = 0; i < frames.size(); ++i)
    requireWritable(frames[i], path, "frame " + std::to_string(i), EmptyMesh::Allowed);

  AtomicFile file(path);
  GltfBuilder builder(compression);
  tinygltf::Animation animation;
  animation.name = "morph";
  for (size_t i = 0; i < frames.size(); ++i) {
    const std::string name = "frame " + std::to_string(i);
    // At rest (no animation playing) only frame 0 is shown.
    const int node = builder.addNode(builder.addMesh(frames[i], name), name,
                                     i == 0 ? std::vector<double>{} : std::vector<double>{0, 0, 0});
    const ScaleKeys keys = scaleKeys(i, frames.size(), fps);
    tinygltf::AnimationSampler sampler;
    sampler.input = builder.addFloatAccessor(keys.times, TINYGLTF_TYPE_SCALAR, true);  // glTF requires bounds on times
    sampler.output = builder.addFloatAccessor(keys.scales, TINYGLTF_TYPE_VEC3, false);
    sampler.interpolation = "STEP";
    animation.samplers.push_back(sampler);
    tinygltf::AnimationChannel channel;
    channel.sampler = int(animation.samplers.size() - 1);
    channel.target_node = node;
    channel.target_path = "scale";
    animation.channels.push_back(channel);
  }
  builder.model().animations.push_back(animation);
  saveGltf(builder.model(), *format, file);
  file.commit();
  log::verbose("wrote " + path.string() + ": " + std::to_string(frames.size()) + " frames, " +
               std::to_string(double(frames.size()) / fps) + " s");
}

}  // namespace lbmshape
