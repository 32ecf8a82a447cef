// Bad parameters are usage errors: exit code 2 and one line on stderr naming
// what is wrong, found before any GPU work (nothing is printed on stdout).
#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "support/cli_runner.hpp"

namespace lbmshape {
namespace {

struct UsageCase {
  const char* name;
  std::vector<std::string> arguments;
  const char* mentions;  // the message must name the culprit
};

void PrintTo(const UsageCase& c, std::ostream* os) { *os << c.name; }

class UsageErrors : public ::testing::TestWithParam<UsageCase> {};

TEST_P(UsageErrors, ExitTwoWithOneLine)
{
  const UsageCase& c = GetParam();
  testing::CliResult r = testing::runLbmshape(c.arguments);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  auto lines = testing::nonEmptyLines(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_EQ(lines[0].rfind("lbmshape: error: ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find(c.mentions), std::string::npos) << lines[0];
  EXPECT_TRUE(r.out.empty()) << r.out;
}

// A grid larger than the device is the device's limit, not a mistake in the
// command: exit 5 like a band that does not fit, and before any work. Each
// device limit alone is tested in lattice_memory_test.cpp.
TEST(DeviceLimits, AGridLargerThanTheDeviceIsRefusedWithExitFive)
{
  for (const auto& [size, mentions] :
       {std::pair{"2000,2000,2000", "cells"}, std::pair{"400,400,400", "does not fit"}}) {
    const testing::CliResult r = testing::runLbmshape({"bench", "--size", size});
    EXPECT_EQ(r.exitCode, 5) << size << ": " << r.err;
    const auto lines = testing::nonEmptyLines(r.err);
    ASSERT_EQ(lines.size(), 1u) << r.err;
    EXPECT_NE(lines[0].find(mentions), std::string::npos) << lines[0];
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Bench, UsageErrors,
    ::testing::Values(
        UsageCase{"zero_gamma", {"bench", "--gamma", "0", "--size", "8,8,8"}, "--gamma"},
        UsageCase{"quiet_and_verbose", {"-q", "-v", "info"}, "--quiet"},
        // CLI11's own messages, in lbmshape's words.
        UsageCase{"res_not_whole", {"denoise", "a.obj", "b.glb", "--res", "1e2"}, "--res: '1e2' is not a whole number"},
        UsageCase{"gamma_a_word", {"denoise", "a.obj", "b.glb", "--gamma", "abc"}, "--gamma: 'abc' is not a number"},
        UsageCase{"an_argument_too_many", {"denoise", "a.obj", "b.glb", "extra"}, "unexpected argument 'extra'"},
        UsageCase{
            "unknown_option_in_words", {"denoise", "a.obj", "b.glb", "--frobnicate"}, "unknown option '--frobnicate'"},
        UsageCase{"an_argument_missing", {"compare", "a.obj"}, "missing argument 'b'"},
        UsageCase{"a_value_missing", {"denoise", "a.obj", "b.glb", "--res"}, "--res: its value is missing"},
        // A path in UTF-8 is named as it is (the error line made its bytes '?').
        UsageCase{"utf8_path_named_as_given",
                  {"denoise", "scans/\u00fc.obj", "smooth/\u00fc.xyz"},
                  "cannot write smooth/\u00fc.xyz"},
        UsageCase{"negative_gamma", {"bench", "--gamma", "-0.1", "--size", "8,8,8"}, "--gamma"},
        UsageCase{"zero_size", {"bench", "--size", "0,8,8"}, "grid size"},
        UsageCase{"negative_size", {"bench", "--size", "8,-3,8"}, "grid size"},
        UsageCase{"two_sizes", {"bench", "--size", "8,8"}, "--size"},
        UsageCase{"tiny_gamma", {"bench", "--gamma", "1e-9", "--size", "8,8,8"}, "too small"},
        UsageCase{"paper_and_size", {"bench", "--paper", "--size", "8,8,8"}, "--paper"},
        UsageCase{"no_steps", {"bench", "--steps", "0", "--size", "8,8,8"}, "--steps"},
        UsageCase{"gamma_above_one", {"bench", "--gamma", "1.5", "--size", "8,8,8"}, "above 1"},
        UsageCase{"denoise_gamma_above_one",
                  {"denoise", "in.obj", "out.glb", "--gamma", "1e9"},
                  "--gamma = 1e+09 is above 1"},
        UsageCase{"denoise_too_many_steps",
                  {"denoise", "in.obj", "out.glb", "--steps", "1000001"},
                  "--steps must be from 0 to 1000000"},
        UsageCase{"compare_too_many_samples",
                  {"compare", "a.obj", "b.obj", "--samples", "4000000000"},
                  "--samples must be from 1 to 10000000"},
        // Checked before any timing: the whole denoise timed last runs at
        // --res of the longest side, which needs 12 with the default margin.
        UsageCase{"size_too_small_for_the_denoise_line", {"bench", "--size", "8,8,11"}, "--size 8x8x11 is too small"},
        UsageCase{"too_many_runs", {"bench", "--runs", "1001", "--size", "16,16,16"}, "--runs must be from 1 to 1000"},
        UsageCase{"too_many_bench_steps",
                  {"bench", "--steps", "1000001", "--size", "16,16,16"},
                  "--steps must be from 1 to 1000000"},
        // The value as typed, not rounded to six digits ("1 is above 1").
        UsageCase{"denoise_gamma_just_above_one",
                  {"denoise", "in.obj", "out.glb", "--gamma", "1.0000001"},
                  "--gamma = 1.0000001 is above 1"},
        UsageCase{"denoise_infinite_margin",
                  {"denoise", "in.obj", "out.glb", "--margin", "inf"},
                  "--margin must be a number of voxels from 1 to 32766, not inf"},
        UsageCase{"morph_fps_too_high_to_time",
                  {"morph", "a.obj", "b.obj", "frames", "--fps", "1e300"},
                  "--fps 1e+300 does not fit the animation: 48 frames at 1e+300 per second are closer together"},
        UsageCase{"morph_format_with_its_dot",
                  {"morph", "a.obj", "b.obj", "frames", "--format", ".obj"},
                  "--format .obj: give the format without its dot (obj)"},
        // Subnormal key times: the second and third were one float.
        UsageCase{"morph_fps_subnormal_key_times",
                  {"morph", "a.obj", "b.obj", "frames", "--frames", "4", "--fps", "1e45"},
                  "--fps 1e+45 does not fit the animation: 4 frames at 1e+45 per second are closer together"},
        // An unset shell variable: not 0, not "no folder".
        UsageCase{"denoise_res_empty", {"denoise", "in.obj", "out.glb", "--res", ""}, "--res: the value is empty"},
        UsageCase{"morph_folder_empty", {"morph", "a.obj", "b.obj", ""}, "the value is empty"},
        UsageCase{"morph_fps_infinite",
                  {"morph", "a.obj", "b.obj", "frames", "--fps", "inf"},
                  "--fps must be a positive, finite number of frames a second, not inf"},
        UsageCase{"morph_fps_too_low_to_time",
                  {"morph", "a.obj", "b.obj", "frames", "--fps", "1e-40"},
                  "would come later than single precision can time; use a higher frame rate"},
        // inf made every morph "arrive" before its first step.
        UsageCase{"morph_tolerance_infinite",
                  {"morph", "a.obj", "b.obj", "frames", "--tolerance", "inf"},
                  "--tolerance must be above 0 and at most 1 voxel, not inf"},
        UsageCase{"morph_tolerance_above_a_voxel",
                  {"morph", "a.obj", "b.obj", "frames", "--tolerance", "1.5"},
                  "--tolerance must be above 0 and at most 1 voxel, not 1.5"},
        UsageCase{"denoise_noise_beyond_the_field",
                  {"denoise", "in.obj", "out.glb", "--noise", "5"},
                  "--noise must be from 0 to 1"},
        UsageCase{"morph_band_with_noise",
                  {"morph", "a.obj", "b.obj", "frames", "--band", "--noise", "0.05"},
                  "--band and --noise"},
        UsageCase{"half_width_without_band", {"bench", "--half-width", "4", "--size", "8,8,8"}, "--band"},
        // Named choices are named back, never the enum's numbers (which are refused).
        UsageCase{"sdf_unknown", {"--sdf", "gpu", "info"}, "--sdf: must be auto, cpu or device, not 'gpu'"},
        UsageCase{"sdf_by_number", {"--sdf", "1", "info"}, "--sdf: must be auto, cpu or device, not '1'"},
        UsageCase{"align_unknown",
                  {"morph", "a.obj", "b.obj", "frames", "--align", "left"},
                  "--align: must be none, center or fit, not 'left'"},
        UsageCase{
            "band_half_width_zero", {"bench", "--band", "--half-width", "0.5", "--size", "16,16,16"}, "--half-width"},
        UsageCase{
            "band_half_width_huge", {"bench", "--band", "--half-width", "65", "--size", "16,16,16"}, "--half-width"},
        UsageCase{"band_and_paper", {"bench", "--band", "--paper"}, "--paper"},
        UsageCase{"unknown_device", {"--device", "no-such-gpu", "info"}, "no-such-gpu"},
        UsageCase{"unknown_option", {"bench", "--frobnicate"}, "frobnicate"}, UsageCase{"no_command", {}, "subcommand"},
        UsageCase{"unknown_command",
                  {"frobnicate", "a.obj"},
                  "unknown command 'frobnicate'; the commands are denoise, morph"},
        UsageCase{"unknown_command_after_options", {"-v", "--device", "0", "smooth"}, "unknown command 'smooth'"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(CommandLine, HelpAndVersionSucceed)
{
  auto help = testing::runLbmshape({"--help"});
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("bench"), std::string::npos);
  auto version = testing::runLbmshape({"--version"});
  EXPECT_EQ(version.exitCode, 0);
  EXPECT_NE(version.out.find(LBMSHAPE_VERSION), std::string::npos);
}

// --help (and so the man page's EXIT STATUS) lists every exit code the
// program uses, as core/error.hpp numbers them, and the variables it reads.
TEST(CommandLine, HelpListsTheExitCodesAndTheEnvironment)
{
  const auto help = testing::runLbmshape({"--help"});
  ASSERT_EQ(help.exitCode, 0);
  const auto statusAt = help.out.find("Exit status:");
  ASSERT_NE(statusAt, std::string::npos) << help.out;
  for (ExitCode code :
       {ExitCode::Ok, ExitCode::Usage, ExitCode::Input, ExitCode::Output, ExitCode::Device, ExitCode::Interrupted})
    EXPECT_NE(help.out.find("\n  " + std::to_string(int(code)) + " ", statusAt), std::string::npos)
        << "exit code " << int(code) << " is not listed";
  for (const char* variable : {"XDG_CACHE_HOME", "LBMSHAPE_NO_PIPELINE_CACHE", "LBMSHAPE_VALIDATION",
                               "LBMSHAPE_PROGRESS_MS", "LBMSHAPE_DEVICE_TRACE"})
    EXPECT_NE(help.out.find(std::string("\n  ") + variable + " ", help.out.find("Environment:")), std::string::npos)
        << variable;
}

}  // namespace
}  // namespace lbmshape
