#include "lbmshape/core/parameter_names.hpp"

#include <atomic>

namespace lbmshape {

namespace {

struct Names {
  const char* library;
  const char* commandLine;
  const char* python;  // nullptr where the Python module has no such keyword
};

// The one table of which name is which; the flags are those cli/ defines.
Names namesOf(Parameter parameter)
{
  switch (parameter) {
  case Parameter::Resolution: return {"grid.resolution", "--res", "res"};
  case Parameter::Voxel: return {"grid.voxel", "--voxel", "voxel"};
  case Parameter::Margin: return {"grid.marginVoxels", "--margin", "margin"};
  case Parameter::Noise: return {"noise.amplitude", "--noise", "noise"};
  case Parameter::Gamma: return {"gamma", "--gamma", "gamma"};
  case Parameter::Steps: return {"steps", "--steps", "steps"};
  case Parameter::Radius: return {"radius", "--radius", "radius"};
  case Parameter::Relax: return {"relaxRounds", "--relax", "relax"};
  case Parameter::StepsPerFrame: return {"stepsPerFrame", "--steps-per-frame", "steps_per_frame"};
  case Parameter::Frames: return {"frames", "--frames", "frames"};
  case Parameter::Cs: return {"cs", "--cs", "cs"};
  case Parameter::Fps: return {"fps", "--fps", nullptr};
  case Parameter::Tolerance: return {"tolerance", "--tolerance", "tolerance"};
  case Parameter::Format: return {"format", "--format", nullptr};
  case Parameter::Align: return {"align", "--align", "align"};
  case Parameter::Compression: return {"compression", "--compress", nullptr};
  case Parameter::ColourByCurvature: return {"colourByCurvature", "--color curvature", nullptr};
  case Parameter::Animation: return {"animation = false", "--no-animation", nullptr};
  case Parameter::Force: return {"force", "--force", nullptr};
  case Parameter::ReplaceInput: return {"replaceInput", "--force", nullptr};
  case Parameter::Preview: return {"preview", "--preview", nullptr};
  case Parameter::Device: return {"device", "--device", "device"};
  case Parameter::Sdf: return {"distances", "--sdf", "sdf"};
  case Parameter::Extract: return {"surfaces", "--extract", "extract"};
  case Parameter::Size: return {"size", "--size", nullptr};
  case Parameter::View: return {"view", "--view", nullptr};
  case Parameter::Colouring: return {"colouring", "--color", nullptr};
  case Parameter::Count: return {"folderMeshes", "--count", nullptr};
  case Parameter::Columns: return {"columns", "--columns", nullptr};
  case Parameter::Wireframe: return {"wireframe", "--wireframe", nullptr};
  case Parameter::Twicing: return {"twicing", "--twicing", "twicing"};
  }
  return {"?", "?", nullptr};
}

std::atomic<ParameterNaming> currentNaming{ParameterNaming::Library};

}  // namespace

void useParameterNames(ParameterNaming naming) { currentNaming = naming; }
ParameterNaming parameterNaming() { return currentNaming; }

std::string nameOf(Parameter parameter) { return nameOf(parameter, currentNaming); }

std::string nameOf(Parameter parameter, ParameterNaming naming)
{
  const Names names = namesOf(parameter);
  switch (naming) {
  case ParameterNaming::CommandLine: return names.commandLine;
  case ParameterNaming::Python: return names.python ? names.python : names.library;
  case ParameterNaming::Library: break;
  }
  return names.library;
}

bool audienceCanSet(Parameter parameter)
{
  return currentNaming != ParameterNaming::Python || namesOf(parameter).python != nullptr;
}

}  // namespace lbmshape
