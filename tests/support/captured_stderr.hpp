// What the logger writes to std::cerr while a CapturedStderr lives, for
// tests of the messages themselves.
#pragma once

#include <iostream>
#include <sstream>
#include <string>

namespace lbmshape::testing {

class CapturedStderr {
public:
  CapturedStderr() : previous_(std::cerr.rdbuf(text_.rdbuf())) {}
  ~CapturedStderr() { std::cerr.rdbuf(previous_); }
  CapturedStderr(const CapturedStderr&) = delete;
  CapturedStderr& operator=(const CapturedStderr&) = delete;
  std::string text() const { return text_.str(); }

private:
  std::ostringstream text_;
  std::streambuf* previous_;
};

}  // namespace lbmshape::testing
