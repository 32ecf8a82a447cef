#include "lbmshape/mesh/gltf_animation.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>

#include "lbmshape/core/atomic_file.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/number_text.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/mesh/glb_stream.hpp"
#include "lbmshape/mesh/gltf_builder.hpp"
#include "lbmshape/mesh/mesh_format.hpp"
#include "lbmshape/mesh/writable_mesh.hpp"

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

// Room for the JSON of a streamed animation: half again the 1,072 bytes a
// frame that a 48-frame morph's took (GlbStream writes the file again in the
// rare case it is longer).
constexpr size_t jsonRoomPerFrame = 1600, jsonRoomBase = 4096;

struct GltfAnimation::Model {
  explicit Model(GltfCompression compression) : builder(compression) { animation.name = "morph"; }
  GltfBuilder builder;
  tinygltf::Animation animation;
  // A plain .glb is streamed: each frame's buffer goes to the file as it
  // comes, and the animation holds no frame. A compressed one, or a .gltf
  // (its buffer a data URI), is assembled in memory and written at the end.
  std::optional<GlbStream> stream;
};

std::string untimeableInSinglePrecision(size_t frameCount, double fps)
{
  if (frameCount == 0) return "";
  const float last = float(double(frameCount - 1) / fps);
  if (!std::isfinite(last))
    return "the last of " + std::to_string(frameCount) + " frames at " + numberText(fps) +
           " per second would come later than single precision can time; use a higher frame rate";
  // Keys closer than float resolution would not be increasing any more:
  // every pair is checked, for near zero the floats are subnormal, coarser
  // than further on (at 1e45 per second the second and third keys were one).
  for (size_t k = 1; k <= frameCount; ++k)
    if (!(float(double(k) / fps) > float(double(k - 1) / fps)))
      return std::to_string(frameCount) + " frames at " + numberText(fps) +
             " per second are closer together than single precision can time; use a lower frame rate";
  return "";
}

GltfAnimation::GltfAnimation(std::filesystem::path path, size_t frameCount, double fps, GltfCompression compression)
    : path_(std::move(path)), frameCount_(frameCount), fps_(fps)
{
  const std::string prefix = "cannot write " + path_.string() + ": ";
  const auto format = meshFormatOf(path_);
  if (format != MeshFormat::Gltf && format != MeshFormat::Glb)
    throw UsageError(prefix + "an animation is written as glTF, so the file name must end in .gltf or .glb, not '" +
                     path_.extension().string() + "'");
  if (frameCount == 0) throw UsageError(prefix + "the animation has no frames");
  if (!std::isfinite(fps) || fps <= 0)
    throw UsageError(prefix + "the frame rate must be a positive number, not " + numberText(fps));
  if (const std::string untimeable = untimeableInSinglePrecision(frameCount, fps); !untimeable.empty())
    throw UsageError(prefix + untimeable);
  model_ = std::make_unique<Model>(compression);
  if (format == MeshFormat::Glb && compression == GltfCompression::None)
    model_->stream.emplace(path_, jsonRoomBase + jsonRoomPerFrame * frameCount);
}

GltfAnimation::~GltfAnimation() = default;

void GltfAnimation::add(const TriangleMesh& frame)
{
  const size_t i = added_;
  if (i >= frameCount_)
    throw std::logic_error("the animation of " + std::to_string(frameCount_) + " frames was given one more");
  const std::string name = "frame " + std::to_string(i);
  // A frame may be empty (a morph through nothing): its node has no mesh.
  requireWritable(frame, path_, name, EmptyMesh::Allowed, CoordinatePrecision::SingleAboutAnOrigin);
  GltfBuilder& builder = model_->builder;
  // At rest (no animation playing) only frame 0 is shown.
  const int node = builder.addNode(builder.addMesh(frame, name, true), name,
                                   i == 0 ? std::vector<double>{} : std::vector<double>{0, 0, 0});
  const ScaleKeys keys = scaleKeys(i, frameCount_, fps_);
  tinygltf::AnimationSampler sampler;
  sampler.input = builder.addFloatAccessor(keys.times, TINYGLTF_TYPE_SCALAR, true);  // glTF requires bounds on times
  sampler.output = builder.addFloatAccessor(keys.scales, TINYGLTF_TYPE_VEC3, false);
  sampler.interpolation = "STEP";
  tinygltf::Animation& animation = model_->animation;
  animation.samplers.push_back(sampler);
  tinygltf::AnimationChannel channel;
  channel.sampler = int(animation.samplers.size() - 1);
  channel.target_node = node;
  channel.target_path = "scale";
  animation.channels.push_back(channel);
  if (model_->stream) model_->stream->append(builder.takeBufferData());
  ++added_;
}

void GltfAnimation::write()
{
  if (added_ != frameCount_)
    throw std::logic_error("the animation has " + std::to_string(added_) + " of its " + std::to_string(frameCount_) +
                           " frames");
  tinygltf::Model& model = model_->builder.model();
  model.animations.assign(1, model_->animation);
  if (model_->stream) {
    model_->stream->finish(plainGlbJson(model, model_->builder.bufferBytes()));
  } else {
    AtomicFile file(path_);
    saveGltf(model, *meshFormatOf(path_), file);
    file.commit();
  }
  log::verbose("wrote " + path_.string() + ": " + std::to_string(frameCount_) + " frames, " +
               std::to_string(double(frameCount_) / fps_) + " s");
}

void writeGltfAnimation(const std::vector<TriangleMesh>& frames, double fps, const std::filesystem::path& path,
                        GltfCompression compression)
{
  GltfAnimation animation(path, frames.size(), fps, compression);
  for (const TriangleMesh& frame : frames) animation.add(frame);
  animation.write();
}

}  // namespace lbmshape
