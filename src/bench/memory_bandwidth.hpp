// The memory bandwidth a lattice step can at best use on the chosen device,
// measured by the bench itself so the roofline fits the machine it runs on.
#pragma once

#include <string>

namespace lbmshape {

namespace gpu {
class GpuContext;
}

struct BandwidthMeasurement {
  double gbps = 0.0;   // bytes read + written per second, 1e9
  std::string method;  // how it was measured
};

// On a CPU device (lavapipe) device memory is host memory: a threaded
// STREAM-style scale kernel over arrays far larger than the caches. On a GPU:
// vkCmdCopyBuffer between two device-local buffers.
BandwidthMeasurement measureMemoryBandwidth(gpu::GpuContext* context);

}  // namespace lbmshape
