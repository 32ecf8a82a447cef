#include "lbmshape/mesh/openmesh_diagnostics.hpp"

#include <iostream>
#include <sstream>

#include <OpenMesh/Core/System/omstream.hh>

#include "lbmshape/core/log.hpp"

namespace lbmshape {
namespace {

std::mutex openMeshMutex;

// Connected once and never released: OpenMesh's streams are statics of its
// own library that keep a reference to their targets until the very end of
// the process (and connecting or disconnecting a target leaks a little each
// time, so it is done once only).
std::ostringstream& sink()
{
  static std::ostringstream* stream = [] {
    auto* s = new std::ostringstream;
    omerr().disconnect(std::cerr);
    omout().disconnect(std::cout);
    omerr().connect(*s);
    omout().connect(*s);
    omlog().disable();  // it only narrates ("write file")
    return s;
  }();
  return *stream;
}

std::string trimmed(const std::string& s)
{
  const char* space = " \t\r\n";
  size_t first = s.find_first_not_of(space);
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(space) - first + 1);
}

}  // namespace

OpenMeshDiagnostics::OpenMeshDiagnostics() : lock_(openMeshMutex)
{
  collected();     // flushes what anyone else made OpenMesh print ...
  sink().str({});  // ... and forgets it: this object reports its own
}

OpenMeshDiagnostics::~OpenMeshDiagnostics()
{
  std::istringstream lines(collected());
  sink().str({});
  for (std::string line; std::getline(lines, line);)
    if (!trimmed(line).empty()) log::verbose("OpenMesh: " + trimmed(line));
}

std::string OpenMeshDiagnostics::collected()
{
  // OpenMesh's streams pass text on only when flushed, and not every
  // message ends with std::endl.
  std::ostringstream& s = sink();
  omerr().flush();
  omout().flush();
  return s.str();
}

std::string OpenMeshDiagnostics::firstMessage()
{
  std::istringstream lines(collected());
  for (std::string line; std::getline(lines, line);)
    if (!trimmed(line).empty()) return trimmed(line);
  return {};
}

}  // namespace lbmshape
