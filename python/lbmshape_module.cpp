// lbmshape for Python (pybind11): meshes as numpy arrays in and out.
//
//   import lbmshape
//   V2, F2 = lbmshape.denoise(V, F, res=128)      # V: (n, 3) floats, F: (m, 3) ints
//   V2, F2, report = lbmshape.denoise(V, F, res=128, report=True)
//   V, F = lbmshape.read_mesh("scan.ply"); lbmshape.write_mesh("out.glb", V2, F2)
//   frames = lbmshape.morph(V, F, V2, F2, frames=24)  # [(vertices, triangles), ...]
//   lbmshape.morph(V, F, V2, F2, on_frame=lambda k, v, f: ...)  # each as it is made
//   for k, v, f in lbmshape.iter_morph(V, F, V2, F2, frames=24): ...  # a generator
//
// Each thread's Vulkan device is opened at its first call and kept
// (lbmshape.Device chooses another); the GIL is released while the device
// works, so other Python threads run (calls that share a Device take
// turns; each thread's default one is its own), and Ctrl-C stops a call within a fraction of a second
// (KeyboardInterrupt), as lbmshape.request_stop() does from another thread
// (lbmshape.Interrupted). Errors: lbmshape.UsageError (a ValueError: a
// parameter out of range), lbmshape.InputError (a ValueError: a mesh that is
// unusable), lbmshape.OutputError (an OSError), lbmshape.DeviceError (a
// RuntimeError), lbmshape.NumericalError (a RuntimeError: a result that is
// not a number), lbmshape.Interrupted, all from lbmshape.Error.
#include <stop_token>
#include <unistd.h>
#include <atomic>
#include <cmath>
#include <exception>
#include <initializer_list>
#include <memory>
#include <optional>
#include <thread>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <utility>

#include <pybind11/eval.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "lbmshape/pipeline/compute_device.hpp"
#include "lbmshape/pipeline/denoise.hpp"
#include "lbmshape/pipeline/morph.hpp"
#include "log_handler.hpp"

namespace py = pybind11;

namespace lbmshape::python {
namespace {

using Vertices = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Triangles = py::array_t<int64_t, py::array::c_style | py::array::forcecast>;

// Triangles as given (an array or nested lists), as int64: integers only,
// for forcecast would truncate 2.9 to vertex 2 without a word. An empty
// list, which numpy makes of floats, is let through for toMesh to refuse.
// (pybind11 takes a py::array argument only as an array: nested lists were
// refused with a TypeError, so the argument is any object, made an array here.)
Triangles integerTriangles(const py::object& object, const std::string& name)
{
  const py::array given = py::module_::import("numpy").attr("asarray")(object);
  const char kind = given.dtype().kind();
  if (given.size() != 0 && kind != 'i' && kind != 'u')
    throw UsageError(name + " must hold integers (vertex indices), not " + py::str(given.dtype()).cast<std::string>());
  // As int64, an index of 2^63 or more would wrap to a negative one and be named so.
  if (given.size() != 0 && kind == 'u')
    if (const auto largest = given.attr("max")().cast<uint64_t>(); largest > uint64_t(INT64_MAX))
      throw InputError(name + " has index " + std::to_string(largest) + ", beyond any mesh's vertices");
  return Triangles::ensure(given);
}

// The mesh of two arrays, checked for shape, finite coordinates and index
// range here (the rest, a surface that is not flat, denoiseMesh checks).
// `prefix` names the pair in messages: "" (vertices, triangles) or
// "source_", "target_".
TriangleMesh toMesh(const Vertices& vertices, const py::object& givenTriangles, const std::string& prefix = "")
{
  const std::string vertexName = prefix + "vertices", triangleName = prefix + "triangles";
  const Triangles triangles = integerTriangles(givenTriangles, triangleName);
  if (vertices.ndim() != 2 || vertices.shape(1) != 3)
    throw UsageError(
        vertexName + " must be an array of shape (n, 3), not of " + std::to_string(vertices.ndim()) + " dimensions" +
        (vertices.ndim() == 2 ? " with " + std::to_string(vertices.shape(1)) + " columns" : std::string()));
  if (triangles.ndim() != 2 || triangles.shape(1) != 3)
    throw UsageError(triangleName + " must be an array of shape (m, 3) of vertex indices");
  TriangleMesh mesh;
  const auto v = vertices.unchecked<2>();
  for (py::ssize_t i = 0; i < v.shape(0); ++i) {
    // Named as numpy indexes it (the library's checks count vertices from 1, as files do).
    if (!std::isfinite(v(i, 0)) || !std::isfinite(v(i, 1)) || !std::isfinite(v(i, 2)))
      throw InputError(vertexName + "[" + std::to_string(i) + "] has a coordinate that is not a finite number");
    mesh.positions.push_back({v(i, 0), v(i, 1), v(i, 2)});
  }
  const auto t = triangles.unchecked<2>();
  for (py::ssize_t i = 0; i < t.shape(0); ++i) {
    for (int k = 0; k < 3; ++k)
      if (t(i, k) < 0 || t(i, k) >= v.shape(0))
        throw InputError(triangleName + "[" + std::to_string(i) + "] has index " + std::to_string(t(i, k)) +
                         ", but there are " + std::to_string(v.shape(0)) + " " + vertexName);
    mesh.triangles.push_back({uint32_t(t(i, 0)), uint32_t(t(i, 1)), uint32_t(t(i, 2))});
  }
  return mesh;
}

py::tuple toArrays(const TriangleMesh& mesh)
{
  Vertices vertices({py::ssize_t(mesh.positions.size()), py::ssize_t(3)});
  auto v = vertices.mutable_unchecked<2>();
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    for (int k = 0; k < 3; ++k) v(py::ssize_t(i), k) = mesh.positions[i][k];
  Triangles triangles({py::ssize_t(mesh.triangles.size()), py::ssize_t(3)});
  auto t = triangles.mutable_unchecked<2>();
  for (size_t i = 0; i < mesh.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) t(py::ssize_t(i), k) = mesh.triangles[i][k];
  return py::make_tuple(vertices, triangles);
}

// The library's calls under way, counted so that a stop request stops
// those and no later one: the first call to begin, and the last to end,
// forget any request left standing.
class CallUnderWay {
public:
  CallUnderWay()
  {
    refuseAForkedProcess();
    if (underWay++ == 0) interrupt::clearStopRequest();
  }
  ~CallUnderWay()
  {
    if (--underWay == 0) interrupt::clearStopRequest();
  }
  CallUnderWay(const CallUnderWay&) = delete;
  CallUnderWay& operator=(const CallUnderWay&) = delete;
  static int count() { return underWay; }

private:
  // A process forked from one that made a call (multiprocessing's default
  // start method on Linux) hung at its first call: OpenMP's threads, and
  // the device's, do not survive fork(). Refused instead.
  static void refuseAForkedProcess()
  {
    static std::atomic<pid_t> usedIn{0};
    pid_t expected = 0;
    const pid_t now = ::getpid();
    if (!usedIn.compare_exchange_strong(expected, now) && expected != now)
      throw UsageError(
          "lbmshape cannot run in a process forked from one that already used it (OpenMP's and the "
          "device's threads do not survive fork()): start the processes with multiprocessing's "
          "'spawn' or 'forkserver' method, or fork before the first lbmshape call");
  }

  static inline std::atomic<int> underWay{0};
};

bool onPythonsMainThread()
{
  const py::module_ threading = py::module_::import("threading");
  return threading.attr("main_thread")().is(threading.attr("current_thread")());
}

// `work()` (a call into the library) without the GIL, so that other Python
// threads run, and stoppable. Python's SIGINT handler runs only once control
// comes back to Python, so a Ctrl-C would wait for the whole call: on the
// main thread SIGINT stops the call at its next check instead (the library's
// checks come a fraction of a second apart), and is then handed to Python's
// handler, which raises KeyboardInterrupt as usual. Where the call ended of
// itself the Ctrl-C is handed on all the same, for Python to act on next.
template <class Work>
auto stoppable(Work&& work) -> decltype(work())
{
  std::optional<decltype(work())> result;
  std::exception_ptr failure;
  bool sigint = false;
  {
    CallUnderWay call;
    std::optional<interrupt::SigintStopsCalls> sigintStops;
    if (onPythonsMainThread()) sigintStops.emplace();
    try {
      py::gil_scoped_release released;
      result.emplace(work());
    } catch (...) {
      failure = std::current_exception();
    }
    sigint = sigintStops && sigintStops->caughtOne();
  }  // Python's own handler is back
  if (sigint) {
    PyErr_SetInterrupt();  // as if SIGINT came now
    bool stoppedByIt = false;
    try {
      if (failure) std::rethrow_exception(failure);
    } catch (const Interrupted&) {
      stoppedByIt = true;
    } catch (...) {}
    // Python's handler raises KeyboardInterrupt (or whatever a handler of
    // the program's own raises); one that raises nothing leaves
    // lbmshape.Interrupted.
    if (stoppedByIt && PyErr_CheckSignals() != 0) throw py::error_already_set();
  }
  if (failure) std::rethrow_exception(failure);
  return std::move(*result);
}

// A thread's default device, closed when the thread ends, unless the
// process is ending. A thread that ends as the process does (a daemon
// thread whose morph was just stopped at exit, or one Python ends at
// finalization) closed its device while exit() ran the Vulkan layers'
// static destructors: the instance's dlclose unmapped the validation layer
// under them (a segfault, one exit in three under load). From
// keepFromNowOn() on, a thread's device is left to the process's end, and
// it waits for the closings already begun.
struct ThreadsDevice {
  std::shared_ptr<ComputeDevice> held;

  ~ThreadsDevice()
  {
    std::unique_lock lock(mutex);
    if (processEnding) {
      new std::shared_ptr<ComputeDevice>(std::move(held));  // never closed: the process ends
      return;
    }
    ++closing;
    lock.unlock();
    held.reset();
    lock.lock();
    --closing;
    closed.notify_all();
  }

  static void keepFromNowOn()
  {
    std::unique_lock lock(mutex);
    processEnding = true;
    closed.wait(lock, [] { return closing == 0; });
  }

private:
  static inline std::mutex mutex;
  static inline std::condition_variable closed;
  static inline bool processEnding = false;
  static inline int closing = 0;
};

// At exit Python ends its daemon threads where they next take the GIL
// (pthread_exit, on Python 3.11), an unwinding no C++ frame of a call under
// way survives: a morph left running on a daemon thread (an iter_morph loop
// not finished, a thread of the program's) aborted the process half the
// time. Registered with atexit, which runs while those threads may still
// take the GIL: stops the calls under way, as Ctrl-C does, and waits for
// them to end (at most a few seconds), without the GIL; then leaves every
// thread's device to the process's end (ThreadsDevice).
void stopCallsAtExit()
{
  py::gil_scoped_release released;
  if (CallUnderWay::count() > 0) {
    interrupt::requestStop();
    for (int waited = 0; waited < 500 && CallUnderWay::count() > 0; ++waited)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ThreadsDevice::keepFromNowOn();
  releaseLogHandlerAtExit();
}

// The device the functions use unless given one: the calling thread's
// own, opened at its first use. Calls that share a device take turns
// (ComputeDevice::takeTurn), so one shared by every thread would make a
// thread pool's calls wait for each other, and a call in an iter_morph loop
// wait for the morph that waits for the loop.
std::shared_ptr<ComputeDevice>& defaultDevice()
{
  thread_local ThreadsDevice device;
  if (!device.held) device.held = std::make_shared<ComputeDevice>("", false);
  return device.held;
}

// The value a keyword's `name` chooses among `choices`; anything else is
// "parameter must be 'a', 'b' or 'c', not 'x'".
template <class Value>
Value chosen(const std::string& parameter, const std::string& name,
             std::initializer_list<std::pair<const char*, Value>> choices)
{
  std::string listed;
  size_t i = 0;
  for (const auto& [choice, value] : choices) {
    if (name == choice) return value;
    listed += std::string(i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + "'" + choice + "'";
    ++i;
  }
  throw UsageError(parameter + " must be " + listed + ", not '" + name + "'");
}

// The grid: cells along the longest side, or a voxel size; not both.
GridOptions gridOf(std::optional<int> res, std::optional<double> voxel, double margin)
{
  if (res && voxel) throw UsageError("give res or voxel, not both");
  GridOptions grid;
  grid.resolution = res.value_or(grid.resolution);
  grid.voxel = voxel;
  grid.marginVoxels = margin;
  return grid;
}

py::object denoise(const Vertices& vertices, const py::object& triangles, std::optional<int> res,
                   std::optional<int> steps, std::optional<double> radius, double gamma, const std::string& smoothing,
                   bool keepVolume, std::optional<bool> twicing, bool dense, std::shared_ptr<ComputeDevice> device,
                   bool report, int relax, const std::optional<std::stop_source>& stop, std::optional<double> voxel,
                   double margin)
{
  DenoiseOptions options;
  if (stop) options.stop = stop->get_token();
  options.grid = gridOf(res, voxel, margin);
  options.steps = steps;
  options.radius = radius;
  options.gamma = gamma;
  options.smoothing = chosen<Smoothing>("smoothing", smoothing,
                                        {{"isotropic", Smoothing::Isotropic},
                                         {"anisotropic", Smoothing::Anisotropic},
                                         {"preserve-features", Smoothing::PreserveFeatures}});
  options.keepVolume = keepVolume;
  options.twicing = twicing;
  options.relaxRounds = relax;
  options.dense = dense;
  const TriangleMesh mesh = toMesh(vertices, triangles);
  if (!device) device = defaultDevice();
  const DenoiseResult result =
      stoppable([&] { return denoiseMesh(mesh, "the vertices and triangles", options, *device); });
  py::tuple arrays = toArrays(result.mesh);
  if (!report) return arrays;
  py::object figures = py::module_::import("json").attr("loads")(result.report.dump());
  return py::make_tuple(arrays[0], arrays[1], figures);
}

// `parameter` ("sdf", "extract") named `name`.
RunsOn runsOnNamed(const std::string& parameter, const std::string& name)
{
  return chosen<RunsOn>(parameter, name, {{"auto", RunsOn::Auto}, {"cpu", RunsOn::Cpu}, {"device", RunsOn::Device}});
}

// The morph's frames, each handed to `onFrame(index, vertices, triangles)`
// as the frame writer's thread makes it (with the GIL taken for the call),
// or gathered into a list. An exception the callback raises stops the morph
// and is raised again as it was, its type and traceback kept.
py::object morph(const Vertices& sourceVertices, const py::object& sourceTriangles, const Vertices& targetVertices,
                 const py::object& targetTriangles, int frames, std::optional<int> res, std::optional<int> steps,
                 double cs, double gamma, const std::string& align, bool band, std::shared_ptr<ComputeDevice> device,
                 py::object onFrame, bool report, const std::optional<std::stop_source>& stop,
                 std::optional<double> voxel, double margin, double tolerance, std::optional<int> stepsPerFrame,
                 double noise, uint32_t seed)
{
  MorphOptions options;
  if (stop) options.stop = stop->get_token();
  options.frames = frames;
  options.grid = gridOf(res, voxel, margin);
  options.steps = steps;
  options.stepsPerFrame = stepsPerFrame;
  options.tolerance = tolerance;
  options.noise.amplitude = noise;
  options.noise.seed = seed;  // noise > 0 runs on the grid: the paper adds it to every cell
  options.cs = cs;
  options.gamma = gamma;
  options.align = chosen<Alignment>(
      "align", align, {{"none", Alignment::None}, {"center", Alignment::Center}, {"fit", Alignment::Fit}});
  options.band = band;
  const TriangleMesh source = toMesh(sourceVertices, sourceTriangles, "source_"),
                     target = toMesh(targetVertices, targetTriangles, "target_");
  if (!device) device = defaultDevice();
  py::list gathered;
  std::optional<py::error_already_set> raised;  // by on_frame
  const FrameSink sink = [&](int index, const TriangleMesh& mesh) {
    py::gil_scoped_acquire held;
    try {
      py::tuple arrays = toArrays(mesh);
      if (onFrame.is_none())
        gathered.append(arrays);
      else
        onFrame(index, arrays[0], arrays[1]);
    } catch (py::error_already_set& e) {
      raised.emplace(std::move(e));
    }
    // The morph stops on a C++ error; the Python one is raised below.
    if (raised) throw std::runtime_error("the on_frame callback raised an exception");
  };
  nlohmann::json figures;
  try {
    figures = stoppable([&] { return morphMeshes(source, target, options, *device, sink); });
  } catch (...) {
    if (raised) throw *raised;
    throw;
  }
  py::object result = onFrame.is_none() ? py::object(gathered) : py::object(py::none());
  if (!report) return result;
  return py::make_tuple(result, py::module_::import("json").attr("loads")(figures.dump()));
}

}  // namespace
}  // namespace lbmshape::python

PYBIND11_MODULE(lbmshape, m)
{
  using namespace lbmshape;
  using namespace lbmshape::python;
  m.doc() = "Surface denoising with a lattice Boltzmann scheme on Vulkan (lbmshape)";
  useParameterNames(ParameterNaming::Python);  // messages name the keywords
  m.attr("__version__") = LBMSHAPE_VERSION;

  // Each error is both an lbmshape.Error and the built-in exception it is
  // of (a tuple of bases), so that `except lbmshape.Error` catches them all
  // and `except ValueError` the parameters and inputs.
  static py::exception<Error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<UsageError> usage(m, "UsageError", py::make_tuple(error, py::handle(PyExc_ValueError)));
  static py::exception<InputError> input(m, "InputError", py::make_tuple(error, py::handle(PyExc_ValueError)));
  static py::exception<OutputError> output(m, "OutputError", py::make_tuple(error, py::handle(PyExc_OSError)));
  static py::exception<DeviceError> device(m, "DeviceError", py::make_tuple(error, py::handle(PyExc_RuntimeError)));
  static py::exception<Interrupted> interrupted(m, "Interrupted", error);
  static py::exception<NumericalError> numerical(m, "NumericalError",
                                                 py::make_tuple(error, py::handle(PyExc_RuntimeError)));
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const UsageError& e) {
      PyErr_SetString(usage.ptr(), e.what());
    } catch (const InputError& e) {
      PyErr_SetString(input.ptr(), e.what());
    } catch (const OutputError& e) {
      PyErr_SetString(output.ptr(), e.what());
    } catch (const DeviceError& e) {
      PyErr_SetString(device.ptr(), e.what());
    } catch (const Interrupted& e) {
      PyErr_SetString(interrupted.ptr(), e.what());
    } catch (const NumericalError& e) {
      PyErr_SetString(numerical.ptr(), e.what());
    } catch (const Error& e) {
      PyErr_SetString(error.ptr(), e.what());
    }
  });

  py::class_<ComputeDevice, std::shared_ptr<ComputeDevice>>(
      m, "Device", "A Vulkan device, or the CPU reference solver ('reference')")
      .def(py::init([](const std::string& name, bool validation, const std::string& sdf, const std::string& extract) {
             auto device = std::make_shared<ComputeDevice>(name, validation, runsOnNamed("sdf", sdf),
                                                           runsOnNamed("extract", extract));
             // A name that matches no device, or no driver, is refused here,
             // where the program names the device, not at its first call
             // (the CLI opens its device lazily so that usage errors cost
             // nothing; here the Device is the choice).
             py::gil_scoped_release released;
             device->name();
             return device;
           }),
           py::arg("name") = "", py::arg("validation") = false, py::arg("sdf") = "auto", py::arg("extract") = "auto",
           "name: empty for the best device, an index, part of a device's name, or 'reference'; sdf: where the "
           "narrow band's distances are computed, 'auto' (the device on a GPU, the CPU on lavapipe), 'cpu' or "
           "'device' (lbmshape --sdf); extract: where a morph's frames' marching cubes run, the same choices "
           "(lbmshape --extract)")
      .def_property_readonly("name", &ComputeDevice::name)
      // iter_morph's: the loop's thread, or none (ComputeDevice::setFramesLoopThread).
      .def("_set_frames_loop_here", [](const ComputeDevice& device, bool here) {
        device.setFramesLoopThread(here ? std::this_thread::get_id() : std::thread::id());
      });

  // One call's own stop (C++: the options' std::stop_token), where
  // request_stop() stops every call under way.
  py::class_<std::stop_source>(m, "Stop",
                               "Pass as stop= to a call; request() from any thread stops that call alone, at its "
                               "next check, with lbmshape.Interrupted. One Stop may serve several calls; once "
                               "requested it stays so: make a new one for the next call.")
      .def(py::init<>())
      .def(
          "request", [](std::stop_source& s) { s.request_stop(); }, "Ask the calls given this Stop to stop.")
      .def_property_readonly(
          "requested", [](const std::stop_source& s) { return s.stop_requested(); }, "Whether request() was called.");

  m.def("denoise", &denoise, py::arg("vertices"), py::arg("triangles"), py::arg("res") = py::none(),
        py::arg("steps") = py::none(), py::arg("radius") = py::none(), py::arg("gamma") = 0.2,
        py::arg("smoothing") = "preserve-features", py::arg("keep_volume") = true, py::arg("twicing") = py::none(),
        py::arg("dense") = false, py::arg("device") = nullptr, py::arg("report") = false,
        // Last: a call that passes the ones before it by position keeps its meaning.
        py::arg("relax") = defaultRelaxationRounds, py::arg("stop") = py::none(), py::arg("voxel") = py::none(),
        py::arg("margin") = GridOptions().marginVoxels,
        "Smooth a closed triangle mesh: (vertices, triangles) in, (vertices, triangles) out, as `lbmshape denoise` "
        "with the same defaults; with report=True also the figures `denoise --json` prints, as a dict. stop: an "
        "lbmshape.Stop whose request() stops this call alone (lbmshape.Interrupted). res (cells along the longest "
        "side, 128) or voxel (a cell's size in the mesh's units), and margin (empty cells around the mesh).");
  m.def("morph", &morph, py::arg("source_vertices"), py::arg("source_triangles"), py::arg("target_vertices"),
        py::arg("target_triangles"), py::arg("frames") = 48, py::arg("res") = py::none(), py::arg("steps") = py::none(),
        py::arg("cs") = 0.1, py::arg("gamma") = 0.05, py::arg("align") = "fit", py::arg("band") = true,
        py::arg("device") = nullptr, py::arg("on_frame") = py::none(), py::arg("report") = false,
        py::arg("stop") = py::none(), py::arg("voxel") = py::none(), py::arg("margin") = GridOptions().marginVoxels,
        py::arg("tolerance") = MorphOptions().tolerance, py::arg("steps_per_frame") = py::none(),
        py::arg("noise") = 0.0, py::arg("seed") = FieldNoise().seed,
        "Morph one closed mesh into another, as `lbmshape morph` with the same defaults: a list of `frames` "
        "(vertices, triangles) pairs, or each passed to on_frame(index, vertices, triangles) as it is made (then "
        "None); with report=True also the figures `morph --json` prints, as a dict. stop: an lbmshape.Stop whose "
        "request() stops this call alone (lbmshape.Interrupted). res (128) or voxel, margin, tolerance (voxels: "
        "where the morph has arrived), steps or steps_per_frame (the paper's scheme, ending where the steps end), "
        "noise and seed (the paper's noise on the source's field, on the grid).");
  // iter_morph: morph's frames as a generator, in Python on top of morph's
  // on_frame: the morph runs on a thread of its own, two frames ahead at
  // most; leaving the loop early stops it.
  m.def("_stop_calls_at_exit", &stopCallsAtExit);
  py::exec(R"(
# The stop events of the iter_morph loops under way: set at exit, before the
# calls under way are stopped (a morph waiting for its loop to take a frame
# waits in Python, where no library check sees the stop).
_loops_under_way = set()

def _stop_at_exit():
    for stop in list(_loops_under_way):
        stop.set()
    _stop_calls_at_exit()

import atexit as _atexit
_atexit.register(_stop_at_exit)

def iter_morph(*args, **kwargs):
    """Yield (index, vertices, triangles) for each frame of lbmshape.morph(*args, **kwargs)
    as it is made. The morph runs on a thread of its own, at most two frames ahead;
    leaving the loop early stops it."""
    import queue, threading
    if "on_frame" in kwargs:
        raise TypeError("iter_morph() yields the frames itself: on_frame is lbmshape.morph()'s")
    if kwargs.get("report"):
        raise TypeError("iter_morph() yields frames, not a report: use lbmshape.morph(..., report=True) instead")
    frames, stop, done, failure = queue.Queue(maxsize=2), threading.Event(), object(), []
    _loops_under_way.add(stop)
    # A call in the loop on the morph's own device would wait for the morph,
    # which waits for the loop: refused (UsageError), not a hang.
    device = kwargs.get("device")
    if device is not None:
        device._set_frames_loop_here(True)
    # Leaving the loop stops the morph at its next check, not at its next
    # frame; a Stop the caller gave stops it too.
    own_stop, callers_stop = Stop(), kwargs.pop("stop", None)

    class _Left(Exception):
        pass

    def on_frame(k, v, f):
        while not stop.is_set():
            try:
                frames.put((k, v, f), timeout=0.05)
                return
            except queue.Full:
                pass
        raise _Left()

    def run():
        try:
            morph(*args, on_frame=on_frame, stop=own_stop, **kwargs)
        except BaseException as e:
            failure.append(e)
        finally:
            frames.put(done)

    worker = threading.Thread(target=run, daemon=True)
    worker.start()
    try:
        while True:
            if callers_stop is not None and callers_stop.requested:
                own_stop.request()
            try:
                item = frames.get(timeout=0.05)
            except queue.Empty:
                continue
            if item is done:
                break
            yield item
    finally:
        if device is not None:
            device._set_frames_loop_here(False)
        _loops_under_way.discard(stop)
        stop.set()
        own_stop.request()
        while worker.is_alive():
            try:
                frames.get(timeout=0.05)
            except queue.Empty:
                pass
        worker.join()
    if failure:
        raise failure[0]
)",
           m.attr("__dict__"));
  m.def(
      "set_log_level",
      [](const std::string& level) {
        log::setLevel(chosen<log::Level>(
            "level", level,
            {{"quiet", log::Level::Quiet}, {"normal", log::Level::Normal}, {"verbose", log::Level::Verbose}}));
      },
      py::arg("level"),
      "What the calls print on stderr: 'quiet' (warnings alone), 'normal' (the default: progress and what was "
      "written, as the command prints) or 'verbose' (each stage's time, as lbmshape -v).");
  m.def("set_log_handler", &setLogHandler, py::arg("handler"),
        "Send the calls' messages to handler(kind, message) instead of stderr (which a Jupyter notebook does not "
        "show): kind 'info', 'verbose', 'warning' or 'progress', the message without 'lbmshape: '; called on the "
        "thread that logs it, after set_log_level's filter. An exception it raises goes to sys.unraisablehook and "
        "the call goes on. None: stderr again. For the logging module: lbmshape.set_log_handler(lambda kind, "
        "message: logging.getLogger('lbmshape').log(logging.WARNING if kind == 'warning' else logging.DEBUG if "
        "kind == 'verbose' else logging.INFO, message))");
  m.def(
      "request_stop", [] { interrupt::requestStop(); },
      "Stop every lbmshape call under way, on any thread, at its next check (within a fraction of a second): "
      "each raises lbmshape.Interrupted, having written nothing partial. Calls that begin later run as usual.");
  m.def(
      "read_mesh",
      [](const std::filesystem::path& path) { return toArrays(stoppable([&] { return readMesh(path); })); },
      py::arg("path"), "Read an OBJ, PLY, OFF, STL, glTF or GLB file: (vertices, triangles)");
  m.def(
      "write_mesh",
      [](const std::filesystem::path& path, const Vertices& vertices, const py::object& triangles) {
        const TriangleMesh mesh = toMesh(vertices, triangles);
        stoppable([&] {
          writeMesh(mesh, path);
          return true;
        });
      },
      py::arg("path"), py::arg("vertices"), py::arg("triangles"),
      "Write a mesh; the format follows the extension (.obj, .ply, .off, .stl, .gltf, .glb)");
}
