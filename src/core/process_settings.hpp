// Two settings that the C runtime and OpenMP read only as the process
// starts, so a program sets them by starting itself again:
//
// OpenMP's idle threads wait for work by spinning (libgomp's default), and
// a lbmshape process has other threads that need the cores then: lavapipe's
// (the lattice runs on the CPU there), the device's warm-up (it compiles
// while the distances are computed), the frame writer, and other processes
// of a batch. Waiting passively instead (OMP_WAIT_POLICY=passive), measured
// on two cores (armadillo, --res 128): one denoise 0.951 -> 0.901 s, two at
// once 2.19 -> 1.78 s, the test suite under ctest -j2 240 -> 168 s.
//
// The band's cells live in arrays of tens to hundreds of megabytes (a
// morph at 256 signs two bands of 11 M cells, four bytes a cell an array),
// each first touched in 4 KB pages, a page fault each; on a virtual machine
// a fault costs microseconds, and the sign's two arrays took 250 ms to
// allocate on the 2-core host. glibc's malloc asks for transparent huge
// pages (2 MB) when told to (GLIBC_TUNABLES=glibc.malloc.hugetlb=1, glibc
// 2.35 on; older ones ignore it), where the kernel grants them on request
// (transparent_hugepage "madvise", the common default, or "always"):
// measured on the 2-core host (docs/performance.md, "Huge pages"): those two
// arrays 250 -> 13 ms, a denoise at 128 1.15x and at 256 1.22x faster
// whole, at the same peak memory. Not under an address-space limit (ulimit
// -v): there every block's 2 MB alignment spends the address space that the
// limit counts, and on the H100 a morph refused for memory under 374 MiB
// then left the validation layer no room for its threads.
#pragma once

namespace lbmshape {

// Unless the user chose them, sets OMP_WAIT_POLICY to "passive" and, with
// `hugePages` and no address-space limit, adds glibc.malloc.hugetlb=1 to
// GLIBC_TUNABLES; then replaces the process with the same program and
// arguments (`argv` as main got it). Returns when nothing was to be set
// (the user's choice stands, and the restarted process finds its own), or
// when the program cannot be started again (it then runs on, only slower).
// The test programs pass hugePages = false: the lbmshape processes that
// they start inherit their environment, and must choose for themselves
// under the limits some tests set.
// Calls fitMallocToTheAddressSpace() first, in either process.
void restartWithProcessSettings(char** argv, bool hugePages = true);

// Under an address-space limit (ulimit -v), at most two malloc arenas
// (process_settings.cpp says why); a no-op without one or outside glibc.
// Before the process starts its threads.
void fitMallocToTheAddressSpace();

// Whether GLIBC_TUNABLES asks malloc for huge pages (glibc.malloc.hugetlb
// set to anything but 0), for `lbmshape info`.
bool mallocAsksForHugePages();

}  // namespace lbmshape
