// CLI11's messages for a command line it cannot parse, in lbmshape's words:
// "--res: '1e2' is not a whole number" for "Could not convert: --res = 1e2",
// "unknown option '--frobnicate'" for "The following argument was not
// expected: --frobnicate", "missing argument 'b'" for "b is required".
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace lbmshape::cli {

// `app`: the application parsed; its subcommand given, if any, has the
// options whose types the message names. Messages of other kinds are kept.
std::string plainParseError(const CLI::App& app, const CLI::ParseError& e);

}  // namespace lbmshape::cli
