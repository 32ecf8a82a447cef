// lbmshape as a library: the public API, for programs that link
// liblbmshape (find_package(lbmshape) and the target lbmshape::lbmshape, or
// pkg-config lbmshape). Everything works on meshes in memory; the files are
// optional.
//
//   lbmshape::ComputeDevice device("", false);   // the best Vulkan device, no validation
//   lbmshape::DenoiseOptions options;            // the command line's defaults
//   options.grid.resolution = 128;
//   lbmshape::DenoiseResult r = lbmshape::denoiseMesh(mesh, "my scan", options, device);
//   // r.mesh: the smoothed surface; r.report: the figures `denoise --json` prints
//   lbmshape::morphMeshes(source, target, lbmshape::MorphOptions{}, device,
//                         [](int k, const lbmshape::TriangleMesh& frame) {  // each frame, in order
//                           std::printf("frame %d: %zu triangles\n", k, frame.triangleCount());
//                         });
//
// Errors are exceptions derived from lbmshape::Error (core/error.hpp):
// UsageError (a parameter out of range), InputError (a mesh that cannot be
// read or encloses nothing), OutputError, DeviceError, NumericalError. Their
// messages name parameters as the option structs do ("grid.resolution 4 is
// too coarse for a margin of 4 voxels; use at least 12";
// core/parameter_names.hpp).
//
// To stop a call under way (a Cancel button, from any thread):
// lbmshape::interrupt::requestStop(); the call throws lbmshape::Interrupted
// at its next check, within a fraction of a second, having written nothing
// partial. The request stands for every call, on any thread, until
// lbmshape::interrupt::clearStopRequest() (core/interrupt.hpp). To stop one
// call alone, give it a std::stop_token in its options (DenoiseOptions::stop,
// MorphOptions::stop, RenderOptions::stop) and request_stop() its source.
//
// Threads: calls that share a ComputeDevice take turns, each holding it from
// start to end (one waits for the other; a stop request ends the wait).
// Calls meant to run at once open a device each. A morph's frame sink that
// calls on the morph's own device gets a UsageError (it would wait for the
// morph, which waits for the sink): give it another device.
//
// Messages: progress and timings go to stderr as the command's do;
// lbmshape::log::setLevel(lbmshape::log::Level::Quiet) leaves only the
// warnings, and lbmshape::log::setSink(...) sends them to a log panel or
// the host's logger instead (core/log.hpp).
#pragma once

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/library_version.hpp"
#include "lbmshape/version.hpp"
#include "lbmshape/mesh/icosphere.hpp"
#include "lbmshape/mesh/mesh_noise.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"
#include "lbmshape/pipeline/compute_device.hpp"
#include "lbmshape/pipeline/denoise.hpp"
#include "lbmshape/pipeline/morph.hpp"
