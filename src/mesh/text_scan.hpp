// Pieces the text-format readers (OBJ, PLY, OFF, STL) share: whitespace,
// tokens, numbers parsed without locale or allocation, and a line quoted
// safely in an error message.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace lbmshape::text {

inline bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
inline bool isSpace(char c) { return isBlank(c) || c == '\n'; }

// Text without the UTF-8 byte order mark some editors put first.
inline std::string_view withoutByteOrderMark(std::string_view text)
{
  return text.starts_with("\xEF\xBB\xBF") ? text.substr(3) : text;
}

// The next whitespace-separated token of `rest` (empty at the end), which
// `rest` then no longer holds.
inline std::string_view nextToken(std::string_view& rest)
{
  size_t start = 0;
  while (start < rest.size() && isSpace(rest[start])) ++start;
  size_t end = start;
  while (end < rest.size() && !isSpace(rest[end])) ++end;
  const std::string_view token = rest.substr(start, end - start);
  rest.remove_prefix(end);
  return token;
}

// `rest` without leading blanks (spaces and tabs, not line ends).
inline std::string_view skipBlanks(std::string_view rest)
{
  size_t start = 0;
  while (start < rest.size() && isBlank(rest[start])) ++start;
  return rest.substr(start);
}

// The line at the start of `rest` (without its '\n' or "\r\n"), which `rest`
// then no longer holds.
inline std::string_view nextLine(std::string_view& rest)
{
  const size_t end = rest.find('\n');
  std::string_view line = rest.substr(0, end);
  rest.remove_prefix(end == std::string_view::npos ? rest.size() : end + 1);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

// Coordinates must be finite and representable as float: every format
// lbmshape writes except OBJ stores float, and the lattice works in float.
inline constexpr double largestCoordinate = double(std::numeric_limits<float>::max());

// What a reader says of a vertex whose coordinates are not all coordinates.
inline constexpr const char* notAVertex =
    "not a vertex with three finite coordinates (numbers of magnitude at most 3.4e38, single precision's largest)";

// A whole token as a finite coordinate ("1", "-2.5e3", "+.5"), or nothing:
// "nan", "inf", "1e39", "1,5" and "abc" are not coordinates.
inline std::optional<double> coordinate(std::string_view token)
{
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);  // from_chars takes no plus sign
  double value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size()) return std::nullopt;
  if (!std::isfinite(value) || std::abs(value) > largestCoordinate) return std::nullopt;
  return value;
}

// A whole token as a decimal integer, or nothing (also when out of range).
inline std::optional<int64_t> integer(std::string_view token)
{
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  int64_t value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size() || token.empty()) return std::nullopt;
  return value;
}

// Text from a file (or about it) fit for a one-line message: printable ASCII
// only (anything else, line ends included, becomes '?'), at most `limit`
// characters and "..." after that.
inline std::string printable(std::string_view text, size_t limit = 200)
{
  while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
  std::string out;
  for (size_t i = 0; i < text.size() && i < limit; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    out += c >= 0x20 && c < 0x7f ? char(c) : '?';
  }
  return text.size() > limit ? out + "..." : out;
}

// A piece of the file for an error message, in quotes: printable, at most
// about 60 characters.
inline std::string quoted(std::string_view text)
{
  std::string out(1, '\'');  // appended, not "'" + ...: GCC 12 warns falsely (-Wrestrict) on that
  out += printable(text, 60);
  out += '\'';
  return out;
}

}  // namespace lbmshape::text
