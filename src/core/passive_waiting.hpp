// OpenMP's idle threads wait for work by spinning (libgomp's default), and
// a lbmshape process has other threads that need the cores then: lavapipe's
// (the lattice runs on the CPU there), the device's warm-up (it compiles
// while the distances are computed), the frame writer, and other processes
// of a batch. Waiting passively instead, measured on two cores (armadillo,
// --res 128): one denoise 0.951 -> 0.901 s, two at once 2.19 -> 1.78 s, the
// test suite under ctest -j2 240 -> 168 s. libgomp reads OMP_WAIT_POLICY as
// it loads, before main, so a program sets it by starting itself again.
#pragma once

namespace lbmshape {

// Unless OMP_WAIT_POLICY is set (a user's choice stands), sets it to
// "passive" and replaces the process with the same program and arguments
// (`argv` as main got it). Returns if the variable was set, or if the
// program cannot be started again (it then runs on, only slower).
void restartWithPassiveOpenMpWaiting(char** argv);

}  // namespace lbmshape
