// What this process may still allocate on the host: the machine's
// physical memory, less where a cgroup's limit leaves less
// (a container, a batch job, a systemd scope: core/cgroup_memory.hpp, the
// limit less what the cgroup's processes use) or an address-space limit
// (ulimit -v, less what is mapped already). For refusing a job that cannot
// fit before it allocates, as the device checks do for device memory.
#pragma once

#include <climits>

#include <cstdint>
#include <string>

#include "lbmshape/core/extent.hpp"

namespace lbmshape {

uint64_t hostMemoryBytes();

// Throws DeviceError when `neededBytes` exceed hostMemoryBytes(): "`what`
// needs about N MiB but this machine allows M MiB; a grid of about ...
// would fit" (gridThatWouldFit, for a job on `extent` whose size grows as
// its side to the power `power`, but for `fixedBytes` of it that any grid
// needs). `cap` bounds the grid named (gridThatWouldFit).
void checkHostMemory(double neededBytes, const std::string& what, const Extent3& extent, double power,
                     double fixedBytes = 0.0, int cap = INT32_MAX);

// The longest side of the grid checkHostMemory would name for such a job
// (0 when none fits), whether or not this one fits.
int hostLongestSideThatFits(double neededBytes, const Extent3& extent, double power, double fixedBytes = 0.0);

// Whether the process may map memory without limit (no `ulimit -v`).
bool addressSpaceUnlimited();

// Gives the pages that the heap holds free back to the system. glibc keeps
// what a stage freed in its arenas for later allocations (arrays of a few
// MiB too, once a larger block was freed: its mmap threshold grows up to
// 32 MiB); where the next stage allocates in other sizes, such as the
// lattice after the distances, that only raises its peak (armadillo at
// --res 512: 600 -> 570 MB; each call takes a few ms). A no-op elsewhere
// than glibc.
void returnFreedHeapMemory();

}  // namespace lbmshape
