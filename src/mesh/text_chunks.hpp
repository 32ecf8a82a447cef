// Splitting a text file into pieces of whole lines, one per task, so that
// threads can parse it in parallel.
#pragma once

#include <string_view>
#include <vector>

namespace lbmshape {

// Consecutive pieces that together are exactly `text`, each ending after a
// '\n' (but the last), each about `target` bytes or more. A small text is
// one piece: threads pay off only for large files.
std::vector<std::string_view> splitIntoLineChunks(std::string_view text, size_t target = size_t(1) << 20);

}  // namespace lbmshape
