// The library's messages name a parameter as the caller knows it: the option
// struct's field for a C++ program, the flag on the command line, the keyword
// in Python (core/parameter_names.hpp).
#include <string>

#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/pipeline/denoise.hpp"
#include "lbmshape/pipeline/morph.hpp"

namespace lbmshape {
namespace {

// Switches the process-wide naming for one test and back.
class NamingFor {
public:
  explicit NamingFor(ParameterNaming naming) : previous_(parameterNaming()) { useParameterNames(naming); }
  ~NamingFor() { useParameterNames(previous_); }

private:
  ParameterNaming previous_;
};

template <typename Check>
std::string usageMessage(Check check)
{
  try {
    check();
  } catch (const UsageError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no UsageError";
  return "";
}

TEST(ParameterNames, EachAudienceHasItsOwnName)
{
  EXPECT_EQ(nameOf(Parameter::Resolution, ParameterNaming::Library), "grid.resolution");
  EXPECT_EQ(nameOf(Parameter::Resolution, ParameterNaming::CommandLine), "--res");
  EXPECT_EQ(nameOf(Parameter::Resolution, ParameterNaming::Python), "res");
  EXPECT_EQ(nameOf(Parameter::StepsPerFrame, ParameterNaming::CommandLine), "--steps-per-frame");
  EXPECT_EQ(nameOf(Parameter::Margin, ParameterNaming::Python), "margin");
  // The Python module has no keyword for the colours: its struct name stands.
  EXPECT_EQ(nameOf(Parameter::ColourByCurvature, ParameterNaming::Python), "colourByCurvature");
  // --force is two fields: a denoise's replaceInput, a morph's force.
  EXPECT_EQ(nameOf(Parameter::ReplaceInput, ParameterNaming::Library), "replaceInput");
  EXPECT_EQ(nameOf(Parameter::ReplaceInput, ParameterNaming::CommandLine), "--force");
}

TEST(ParameterNames, HintsNameOnlyWhatTheAudienceCanSet)
{
  EXPECT_TRUE(audienceCanSet(Parameter::Fps)) << "a C++ caller sets every field";
  NamingFor python(ParameterNaming::Python);
  EXPECT_FALSE(audienceCanSet(Parameter::Fps)) << "lbmshape.morph makes no animation, so has no fps keyword";
  EXPECT_TRUE(audienceCanSet(Parameter::Resolution));
  EXPECT_TRUE(audienceCanSet(Parameter::Voxel));
}

TEST(ParameterNames, ALibraryCallerIsToldTheOptionNotTheFlag)
{
  ASSERT_EQ(parameterNaming(), ParameterNaming::Library) << "what a program linking the library gets";
  DenoiseOptions denoise;
  denoise.gamma = -1.0;
  std::string message = usageMessage([&] { checkDenoiseOptions(denoise); });
  EXPECT_EQ(message.rfind("gamma must be", 0), 0u) << message;
  EXPECT_EQ(message.find("--"), std::string::npos) << message;

  denoise = DenoiseOptions();
  denoise.grid.resolution = 4;
  message = usageMessage([&] { checkDenoiseOptions(denoise); });
  EXPECT_EQ(message, "grid.resolution 4 is too coarse for a margin of 4 voxels; use at least 12");

  MorphOptions morph;
  morph.steps = 10;
  morph.stepsPerFrame = 2;
  message = usageMessage([&] { checkMorphOptions(morph); });
  EXPECT_EQ(message, "give stepsPerFrame or steps, not both");

  morph = MorphOptions();
  morph.format = "xyz";
  message = usageMessage([&] { checkMorphOptions(morph); });
  EXPECT_EQ(message.rfind("format xyz is not a mesh format", 0), 0u) << message;
}

TEST(ParameterNames, TheCommandLineIsToldTheFlagAndPythonTheKeyword)
{
  DenoiseOptions o;
  o.grid.resolution = 4;
  {
    NamingFor commandLine(ParameterNaming::CommandLine);
    EXPECT_EQ(usageMessage([&] { checkDenoiseOptions(o); }),
              "--res 4 is too coarse for a margin of 4 voxels; use at least 12");
  }
  {
    NamingFor python(ParameterNaming::Python);
    EXPECT_EQ(usageMessage([&] { checkDenoiseOptions(o); }),
              "res 4 is too coarse for a margin of 4 voxels; use at least 12");
  }
  EXPECT_EQ(usageMessage([&] { checkDenoiseOptions(o); }),
            "grid.resolution 4 is too coarse for a margin of 4 voxels; use at least 12");
}

}  // namespace
}  // namespace lbmshape
