// OpenMesh reports problems by printing them (to stderr, and some warnings to
// stdout, which lbmshape keeps for --json results). From the first use of
// this class on, OpenMesh's messages go into a buffer instead; while an
// object lives, what OpenMesh prints is collected, so that a reader can put
// the relevant message into its error, and the rest goes to the verbose log.
//
// OpenMesh's readers and writers are process-wide singletons that keep state
// between calls, so an object also lets only one thread use them at a time.
#pragma once

#include <mutex>
#include <string>

namespace lbmshape {

class OpenMeshDiagnostics {
public:
  OpenMeshDiagnostics();
  ~OpenMeshDiagnostics();  // passes what was collected to the verbose log

  OpenMeshDiagnostics(const OpenMeshDiagnostics&) = delete;
  OpenMeshDiagnostics& operator=(const OpenMeshDiagnostics&) = delete;

  // The first message OpenMesh printed so far, trimmed to one line; empty if none.
  std::string firstMessage();

private:
  std::string collected();

  std::unique_lock<std::mutex> lock_;
};

}  // namespace lbmshape
