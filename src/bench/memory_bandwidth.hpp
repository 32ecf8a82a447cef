// The memory bandwidth a lattice step can at best use on the chosen device,
// measured by the bench itself so the roofline fits the machine it runs on.
#pragma once

#include <cstdint>
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
// the same kernel as a compute shader over two 256 MiB device-local arrays.
BandwidthMeasurement measureMemoryBandwidth(gpu::GpuContext* context);

// The compute-shader measurement over arrays of `bytes` (at most the
// device's storage-buffer range), after `warmupMs` of untimed passes.
BandwidthMeasurement measureDeviceBandwidth(gpu::GpuContext& context, uint64_t bytes, double warmupMs);

}  // namespace lbmshape
