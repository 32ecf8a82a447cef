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

// The length of the well-formed UTF-8 sequence at the start of `text` for a
// character a message may show (not a control, a space other than ASCII's,
// a soft hyphen, a line or paragraph separator, a bidirectional or
// zero-width format character, a byte order mark); 0 for anything else.
inline size_t printableUtf8Length(std::string_view text)
{
  const auto byte = [&](size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(0);
  const size_t length = lead >= 0xc2 && lead <= 0xdf   ? 2
                        : lead >= 0xe0 && lead <= 0xef ? 3
                        : lead >= 0xf0 && lead <= 0xf4 ? 4
                                                       : 0;
  if (length == 0 || text.size() < length) return 0;
  uint32_t code = lead & (0x7f >> length);
  for (size_t i = 1; i < length; ++i) {
    if ((byte(i) & 0xc0) != 0x80) return 0;
    code = code << 6 | (byte(i) & 0x3f);
  }
  const bool overlong = (length == 3 && code < 0x800) || (length == 4 && code < 0x10000);
  const bool hidden = code <= 0xa0 || code == 0xad || code == 0x1680 || (code >= 0x2000 && code <= 0x200a) ||
                      code == 0x202f || code == 0x205f || code == 0x3000 || (code >= 0x200b && code <= 0x200f) ||
                      (code >= 0x2028 && code <= 0x202e) || (code >= 0x2060 && code <= 0x206f) || code == 0xfeff ||
                      (code >= 0xd800 && code <= 0xdfff);
  return overlong || hidden || code > 0x10ffff ? 0 : length;
}

enum class Letters { Ascii, Utf8 };

// Text from a file (or about it) fit for a one-line message: printable ASCII
// and, with Letters::Utf8, the printable characters of well-formed UTF-8;
// anything else, line ends included, becomes '?'. At most `limit`
// characters, and "..." after that. A file's content is shown in ASCII,
// where a damaged byte (a no-break space in a keyword) must show as one.
inline std::string printable(std::string_view text, size_t limit = 200, Letters letters = Letters::Ascii)
{
  while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
  std::string out;
  size_t characters = 0, i = 0;
  for (; i < text.size() && characters < limit; ++characters) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += char(c);
      ++i;
    } else if (const size_t n = letters == Letters::Utf8 ? printableUtf8Length(text.substr(i)) : 0; n > 0) {
      out += text.substr(i, n);
      i += n;
    } else {
      out += '?';
      ++i;
    }
  }
  return i < text.size() ? out + "..." : out;
}

// A piece of the file for an error message, in quotes: printable, at most
// about 60 characters.
inline std::string quoted(std::string_view text, Letters letters = Letters::Ascii)
{
  std::string out(1, '\'');  // appended, not "'" + ...: GCC 12 warns falsely (-Wrestrict) on that
  out += printable(text, 60, letters);
  out += '\'';
  return out;
}

// A file's name for a message, in its own letters ("données ü.bin", not
// "donn??es ??.bin") where they are printable UTF-8.
inline std::string quotedName(std::string_view name) { return quoted(name, Letters::Utf8); }

}  // namespace lbmshape::text
