#include "mesh/obj_positions.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <string_view>

namespace lbmshape {
namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

std::string_view nextToken(std::string_view& rest)
{
  size_t start = 0;
  while (start < rest.size() && isSpace(rest[start])) ++start;
  size_t end = start;
  while (end < rest.size() && !isSpace(rest[end])) ++end;
  std::string_view token = rest.substr(start, end - start);
  rest.remove_prefix(end);
  return token;
}

// A coordinate as OpenMesh's float parsing would accept it, read as double.
std::optional<double> coordinate(std::string_view token)
{
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);  // from_chars does not take a sign
  double value = 0;
  auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size()) return std::nullopt;
  // Beyond float range OpenMesh's reader fails on the line and drops it.
  if (!std::isfinite(value) || std::abs(value) > double(std::numeric_limits<float>::max())) return std::nullopt;
  return value;
}

std::string shortened(std::string_view line)
{
  constexpr size_t limit = 60;
  return line.size() <= limit ? std::string(line) : std::string(line.substr(0, limit)) + "...";
}

}  // namespace

ObjPositions readObjPositions(const std::filesystem::path& path)
{
  ObjPositions result;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (size_t number = 1; std::getline(in, line); ++number) {
    std::string_view rest = line;
    if (nextToken(rest) != "v") continue;
    glm::dvec3 p;
    bool ok = true;
    for (int k = 0; k < 3 && ok; ++k) {
      auto value = coordinate(nextToken(rest));
      ok = value.has_value();
      if (ok) p[k] = *value;
    }
    if (!ok) {
      std::string_view text = line;
      while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
      result.problem = "line " + std::to_string(number) + ": '" + shortened(text) +
                       "' is not a vertex with three finite coordinates";
      return result;
    }
    result.positions.push_back(p);
  }
  return result;
}

}  // namespace lbmshape
