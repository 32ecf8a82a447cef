// A number as a message shows it.
#pragma once

#include <charconv>
#include <cstdio>
#include <string>

namespace lbmshape {

// The shortest text that reads back as exactly `value`: what the user typed
// comes back as typed (1.0000001, not the 1 of six significant digits),
// and 1e300 stays short (std::to_string writes its 301 digits).
inline std::string numberText(double value)
{
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

// A measured value, in a message or on a picture: three significant digits
// (0.0115, 1.23e+04), where the shortest exact text would run to seventeen.
inline std::string threeSignificantDigits(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

}  // namespace lbmshape
