// How the library's messages name a job's parameters. One check serves three
// audiences, who know the same parameter by three names: a C++ program sets
// DenoiseOptions::grid.resolution, a shell script gives --res, a notebook
// passes res=. Each front end says once, at start-up, whose names its users
// know (the command line and the Python module do); a program linking the
// library gets the names of its option structs without doing anything.
#pragma once

#include <string>

namespace lbmshape {

enum class Parameter {
  Resolution,
  Voxel,
  Margin,
  Noise,
  Gamma,
  Steps,
  Radius,
  Relax,
  StepsPerFrame,
  Frames,
  Cs,
  Fps,
  Tolerance,
  Format,
  Align,
  Compression,
  ColourByCurvature,
  Animation,
  Force,
  ReplaceInput,
  Preview,
  Device,
  Sdf,
  Extract,
  Size,
  View,
  Colouring,
  Count,
  Columns,
  Wireframe,
  Twicing,
};

enum class ParameterNaming {
  Library,      // as the option structs spell them: "grid.resolution"
  CommandLine,  // the flag: "--res"
  Python,       // lbmshape.denoise's keyword where it has one: "res"
};

// Process-wide, for every message from then on. Library until set.
void useParameterNames(ParameterNaming naming);
ParameterNaming parameterNaming();

// The parameter as the current audience names it.
std::string nameOf(Parameter parameter);
std::string nameOf(Parameter parameter, ParameterNaming naming);

// Whether the current audience can set it at all (the Python module takes
// fewer parameters than the command line): a hint names only those.
bool audienceCanSet(Parameter parameter);

}  // namespace lbmshape
