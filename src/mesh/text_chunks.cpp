#include "lbmshape/mesh/text_chunks.hpp"

namespace lbmshape {

std::vector<std::string_view> splitIntoLineChunks(std::string_view text, size_t target)
{
  std::vector<std::string_view> chunks;
  while (!text.empty()) {
    size_t end = text.size();
    if (text.size() > 2 * target) {
      const size_t newline = text.find('\n', target);
      if (newline != std::string_view::npos) end = newline + 1;
    }
    chunks.push_back(text.substr(0, end));
    text.remove_prefix(end);
  }
  return chunks;
}

}  // namespace lbmshape
