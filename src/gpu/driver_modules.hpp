// Keeps the Vulkan driver and layer libraries loaded until the process ends,
// in a build with AddressSanitizer; does nothing in any other build.
#pragma once

namespace lbmshape::gpu {

// The Vulkan loader unloads the driver (lavapipe: libvulkan_lvp, with LLVM)
// and the validation layer when the instance is destroyed. Their own leaks
// are then reported by LeakSanitizer at exit as "<unknown module>" frames,
// which no suppression can name. Pinned, they keep their names, and
// tests/sanitizers/lsan.supp suppresses exactly those libraries.
void keepDriverModulesLoadedForLeakReports();

}  // namespace lbmshape::gpu
