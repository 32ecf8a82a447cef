// A .glb file written as its binary chunk grows: room for the JSON chunk is
// left at the start, the buffer's bytes are appended as they come, and the
// JSON goes into its room at the end, padded with spaces (JSON's own
// whitespace). A morph's animation (GltfAnimation) streams its frames this
// way, so that it holds none of them in memory and only the JSON is left to
// write after the last frame.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lbmshape/core/atomic_file.hpp"

namespace lbmshape {

class GlbStream {
public:
  // Written atomically (AtomicFile): nothing is under the target's name until
  // finish(); OutputError as AtomicFile reports it.
  GlbStream(std::filesystem::path target, size_t jsonRoom);

  void append(const std::vector<unsigned char>& bytes);
  size_t binaryBytes() const { return binaryBytes_; }

  // The JSON chunk (its buffer 0 of binaryBytes(), or no buffer when 0) into
  // its room, or, when it is longer than the room, the file again with room
  // enough; then commits. Throws OutputError when the file cannot be written.
  void finish(const std::string& json);

private:
  [[noreturn]] void failed() const;  // OutputError naming the target
  void requireGood();
  size_t headBytes() const;  // where the binary chunk's bytes begin

  AtomicFile file_;
  std::ofstream out_;
  size_t jsonRoom_;
  size_t binaryBytes_ = 0;
};

}  // namespace lbmshape
