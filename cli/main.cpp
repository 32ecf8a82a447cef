// lbmshape: the command-line front end. It parses the command, runs it, and
// turns every failure into one line on stderr and its exit code:
// 0 ok, 2 usage, 3 input, 4 output, 5 device or numerical failure.
#include <csignal>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <vulkan/vulkan.hpp>

#include "bench_command.hpp"
#include "common_options.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/log.hpp"
#include "info_command.hpp"
#include "mesh_commands.hpp"
#include "run_command.hpp"
#include "usage_messages.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/core/last_resort.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/core/process_settings.hpp"
#include "lbmshape/core/worker_threads.hpp"

namespace {

// What to say when memory runs out: a grid is what usually takes it, and
// the commands that have one can be told to use a coarser one.
std::string outOfMemory(const CLI::App& app, const std::string& where = "")
{
  const std::string what = "out of memory" + (where.empty() ? "" : " " + where);
  for (const CLI::App* command : app.get_subcommands())
    if (command->get_option_no_throw("--res")) return what + "; use a coarser grid (--res)";
  return what;
}

// CLI11 reports a first word that names no command as "A subcommand is
// required"; name the word and the commands instead.
std::string usageMessage(const CLI::App& app, const CLI::ParseError& e)
{
  if (app.get_subcommands().empty())
    for (const std::string& word : app.remaining())
      if (!word.empty() && word[0] != '-') {
        std::string commands;
        for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; }))
          commands += (commands.empty() ? "" : ", ") + command->get_name();
        return "unknown command '" + word + "'; the commands are " + commands + " (see lbmshape --help)";
      }
  const auto given = app.get_subcommands();
  return lbmshape::cli::plainParseError(app, e) + " (see lbmshape " +
         (given.empty() ? "" : given.front()->get_name() + " ") + "--help)";
}

// An empty value ("--res ''", "$UNSET" in a script) is refused, naming the
// option: CLI11 would read it as 0 for a number, and as no folder at all
// for a path.
void refuseEmptyValues(CLI::App& app)
{
  const CLI::Validator notEmpty(
      [](std::string& value) { return value.empty() ? std::string("the value is empty") : std::string(); }, "");
  std::vector<CLI::App*> apps = app.get_subcommands([](const CLI::App*) { return true; });
  apps.push_back(&app);
  for (CLI::App* command : apps)
    for (CLI::Option* option : command->get_options())
      if (option->get_type_size() != 0) option->check(notEmpty);
}

int fail(lbmshape::ExitCode code, const std::string& message)
{
  // One line, whatever the message: scripts grep for it, terminals show
  // it. Control characters go; bytes of 0x80 and up stay, so that a path
  // in UTF-8 ("scans/ü.obj") is named as it is (a file's own bytes are
  // quoted printable where a reader quotes them: text::printable).
  std::string line = message;
  for (char& c : line)
    if (c == '\n' || c == '\r' || c == '\t')
      c = ' ';
    else if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) == 0x7f)
      c = '?';
  std::cerr << "lbmshape: error: " << line << std::endl;
  return int(code);
}

// --sdf's and --extract's values, in any case.
CLI::Validator runsOnNames()
{
  using lbmshape::RunsOn;
  return lbmshape::cli::namedChoices<RunsOn>(
      {{"auto", RunsOn::Auto}, {"cpu", RunsOn::Cpu}, {"device", RunsOn::Device}});
}

}  // namespace

int main(int argc, char** argv)
{
  using namespace lbmshape;
  restartWithProcessSettings(argv);                 // before anything else (core/process_settings.hpp)
  useParameterNames(ParameterNaming::CommandLine);  // messages name the flags
  // Named, so that help and the man page say "lbmshape", not the path it
  // was started by.
  CLI::App app("lbmshape: surface denoising and morphing with a lattice Boltzmann scheme on Vulkan", "lbmshape");
  app.set_version_flag("--version", LBMSHAPE_VERSION);
  // At the end of --help, and so the man page's EXIT STATUS and ENVIRONMENT
  // sections (help2man reads these headings); docs/batch.md says more.
  app.footer(R"(Exit status:
  0    done
  2    usage: an unknown command or option, a parameter out of range; found before any work
  3    input: a mesh or jobs file that cannot be read or used
  4    output: a file or folder that cannot be written
  5    device or numerical failure: no usable Vulkan device, a job too big for it or for memory
  130  interrupted by SIGINT (143 SIGTERM, 129 SIGHUP); only complete files remain

Environment:
  XDG_CACHE_HOME              the pipeline cache is kept in $XDG_CACHE_HOME/lbmshape (else ~/.cache/lbmshape)
  LBMSHAPE_NO_PIPELINE_CACHE  1: keep no pipeline cache
  LBMSHAPE_VALIDATION         1: as --validate
  LBMSHAPE_PROGRESS_MS        the interval of progress lines in a log file (5000; 0 for every stage)
  LBMSHAPE_DEVICE_TRACE       1: each device submission's time on stderr
  OMP_NUM_THREADS             the CPU stages' threads (default: every core)
)");
  app.require_subcommand(1);
  app.fallthrough();  // common options may follow the command name

  cli::CommonOptions common;
  auto* verbose = app.add_flag("-v,--verbose", common.verbose, "Print each stage's time and the chosen device");
  app.add_flag("-q,--quiet", common.quiet, "Print only warnings and errors: no progress or information lines")
      ->excludes(verbose);  // together, one was silently dropped
  app.add_flag("--json", common.json, "Print the result as one JSON object on stdout");
  app.add_option("--device", common.device,
                 "Vulkan device: index or part of its name, or 'reference' for the CPU reference");
  app.add_option("--sdf", common.distances,
                 "Where the band's signed distances are computed: auto (the device on a GPU, the CPU on "
                 "lavapipe), cpu or device")
      ->transform(runsOnNames())
      ->default_str("auto");
  app.add_option("--extract", common.surfaces,
                 "Where a morph's frames' marching cubes run: auto (the device on a GPU, the CPU on lavapipe), "
                 "cpu or device")
      ->transform(runsOnNames())
      ->default_str("auto");
  app.add_flag("--validate", common.validation, "Run with the Khronos validation layer; any message fails the run");
  app.parse_complete_callback([&common] {
    log::setLevel(common.quiet ? log::Level::Quiet : common.verbose ? log::Level::Verbose : log::Level::Normal);
  });

  common.report = [&common](const nlohmann::json& report) {
    if (common.json) cli::printJson(report);
  };
  cli::addDenoiseCommand(app, common);
  cli::addMorphCommand(app, common);
  cli::addRunCommand(app, common);
  cli::addCompareCommand(app, common);
  cli::addRenderCommand(app, common);
  cli::addNoiseCommand(app, common);
  cli::addInfoCommand(app, common);
  cli::addBenchCommand(app, common);
  refuseEmptyValues(app);

  interrupt::installHandler();
  installLastResortHandler();
  // A reader of stdout that went away is an output error (exit 4), not a
  // silent death by SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  // Likewise a file-size limit (ulimit -f): a write beyond it fails with
  // EFBIG, an output error that removes the temporary file, instead of
  // SIGXFSZ killing the process with the file half-written.
  std::signal(SIGXFSZ, SIG_IGN);
  prepareParallelRegions();
  try {
    app.parse(argc, argv);
    // Closing the device can draw validation messages too (objects still
    // alive, for one); they fail the run like any other.
    common.closeDevice();
    // Results on stdout that did not arrive (a full disk, a closed pipe)
    // are a failed command, like a mesh that could not be written.
    if (!std::cout.flush())
      return fail(ExitCode::Output,
                  "cannot write the results to standard output (is the disk full, or the pipe closed?)");
    // A signal that came after the last check (while the last figures were
    // made, the device closed): the outputs are complete, but the process
    // was asked to stop and says so, so that a shell loop stops too (it
    // went on after an exit code of 0).
    interrupt::check("every output was complete");
    return 0;
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return fail(ExitCode::Usage, usageMessage(app, e));
  } catch (const Error& e) {
    return fail(e.code(), e.what());
  } catch (const vk::OutOfDeviceMemoryError& e) {
    return fail(ExitCode::Device, outOfMemory(app, std::string("on the Vulkan device (") + e.what() + ")"));
  } catch (const vk::OutOfHostMemoryError& e) {
    return fail(ExitCode::Device, outOfMemory(app, std::string("in the Vulkan driver (") + e.what() + ")"));
  } catch (const vk::SystemError& e) {
    return fail(ExitCode::Device, std::string("Vulkan: ") + e.what());
  } catch (const std::filesystem::filesystem_error& e) {
    return fail(ExitCode::Output, e.what());
  } catch (const std::bad_alloc&) {
    return fail(ExitCode::Device, outOfMemory(app));
  } catch (const std::exception& e) {
    return fail(ExitCode::Device, std::string("internal error: ") + e.what());
  }
}
