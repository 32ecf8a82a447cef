// Typed errors. Every failure the user can cause or meet has a kind, and each
// kind has its own process exit code, so batch scripts can tell a typo in the
// command line from a broken mesh from a missing GPU.
#pragma once

#include <stdexcept>
#include <string>

namespace lbmshape {

enum class ExitCode : int {
  Ok = 0,
  Usage = 2,          // bad command line or parameters (checked before any GPU work)
  Input = 3,          // unreadable or invalid input file
  Output = 4,         // cannot write the result
  Device = 5,         // Vulkan device failure or numerical blow-up
  Interrupted = 130,  // Ctrl-C: the shell's convention, 128 + SIGINT (143 for SIGTERM, 129 for SIGHUP)
};

class Error : public std::runtime_error {
public:
  Error(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

private:
  ExitCode code_;
};

struct UsageError : Error {
  explicit UsageError(const std::string& m) : Error(ExitCode::Usage, m) {}
};
struct InputError : Error {
  explicit InputError(const std::string& m) : Error(ExitCode::Input, m) {}
};
struct OutputError : Error {
  explicit OutputError(const std::string& m) : Error(ExitCode::Output, m) {}
};
struct DeviceError : Error {
  explicit DeviceError(const std::string& m) : Error(ExitCode::Device, m) {}
};
// The user pressed Ctrl-C, or the process was asked to stop (SIGTERM,
// SIGHUP), or a program that links the library asked (signal 0,
// interrupt::requestStop); what was complete is kept, nothing partial. The
// exit code is 128 + the signal's number, as the shell reports a process it
// killed (130, Ctrl-C's, for the program's own request).
struct Interrupted : Error {
  explicit Interrupted(const std::string& m, int signal = 2 /* SIGINT */)
      : Error(static_cast<ExitCode>(128 + (signal ? signal : 2)), m), signal_(signal)
  {}
  int signal() const { return signal_; }

private:
  int signal_;
};
// A result that is not a number, or a scheme driven outside its stable range.
struct NumericalError : Error {
  explicit NumericalError(const std::string& m) : Error(ExitCode::Device, m) {}
};

}  // namespace lbmshape
