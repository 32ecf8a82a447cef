// The narrow band's marching cubes on the device (band_surface.comp): the
// cut grid edges and cut cubes of the field a solver's pass writes into its
// field buffer, listed by the device and read back as SurfacePieces, so
// that a morph's frame costs a read-back of its surface, not of its field.
// listSurfacePieces() (surface/surface_pieces.hpp) is the CPU reference.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan_raii.hpp>

#include "lbmshape/surface/surface_pieces.hpp"

namespace lbmshape {

class BandField;

namespace surface_shader {
struct Parameters;
}

namespace gpu {
class GpuBuffer;
class GpuContext;
class StagedCopies;
}  // namespace gpu

class BandSurfacePass {
public:
  // What the pass reads, all of it the solver's: the field buffer (a float
  // a stored cell), the neighbours' table and the bricks' origins as the
  // steps read them, the source's base (X_target, for the error near it
  // where a request asks and `hasSource`), and the start's field, for the
  // far value and far sides beyond the band.
  struct Reads {
    const gpu::GpuBuffer& field;
    const gpu::GpuBuffer& neighbours;
    const gpu::GpuBuffer& origins;
    const gpu::GpuBuffer& sourceBase;
    const BandField& start;
    bool hasSource;
  };

  BandSurfacePass(gpu::GpuContext& context, gpu::StagedCopies& copies);
  ~BandSurfacePass();

  // A new start: its far sides are the next pass's to upload. The buffers
  // are let go until then (a denoise never asks for the pass).
  void forgetTheStart();
  // A buffer that Reads names was replaced: the pass's descriptors are
  // written again before it next runs.
  void readsReplaced() { setStale_ = true; }

  // The surface's pieces of the field that the commands `before` records
  // write into the field buffer (and the request's error near the source's
  // base), read back; `ran` runs once those commands have (a step among
  // them is taken then, whatever follows). Where a list outgrows its
  // buffer, the pass runs again (the field buffer still holds the field)
  // with room for it, up to one storage-buffer binding.
  SurfacePieces list(const SurfaceRequest& request, const Reads& reads,
                     const std::function<void(vk::CommandBuffer)>& before, const std::function<void()>& ran);

private:
  struct Buffers;
  void prepare(uint64_t crossings, uint64_t cubes, const std::vector<glm::ivec3>& probes, const Reads& reads);
  void writeDescriptors(const Reads& reads);
  void record(vk::CommandBuffer cmd, const surface_shader::Parameters& push);

  gpu::GpuContext& context_;
  gpu::StagedCopies& copies_;
  std::unique_ptr<Buffers> buffers_;
  bool setStale_ = true;                        // its set reads buffers replaced since it was written
  uint64_t lastCrossings_ = 0, lastCubes_ = 0;  // the lengths of the last lists: the next ones' room
};

}  // namespace lbmshape
