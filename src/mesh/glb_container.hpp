// The GLB container (glTF 2.0, section 4.4): a 12-byte header, a JSON chunk
// and an optional binary chunk, each chunk 4-byte aligned.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>

namespace lbmshape {

// The little-endian word at `at` (the caller has checked that it is there).
uint32_t glbWord(std::string_view bytes, size_t at);

// `bytes` rounded up to the 4-byte alignment of a GLB chunk.
inline size_t glbPadded(size_t bytes) { return (bytes + 3) / 4 * 4; }

// The JSON and binary chunks (the binary one empty when there is none) of
// a GLB whose layout is known to be sound: one lbmshape wrote, or one the
// reader has checked.
struct GlbChunks {
  std::string_view json, binary;
};
GlbChunks glbChunks(std::string_view glb);

// A GLB file of this JSON text and binary chunk (none when empty), padded
// as GLB requires: the JSON with spaces, the binary chunk with zeros.
std::string glbFile(std::string json, std::string binary);
// Everything of such a file before the binary chunk's bytes: the header,
// the JSON chunk (padded with spaces) and, when there are binary bytes, the
// binary chunk's own header (its bytes then padded with zeros to a multiple
// of 4). A file whose JSON is already padded has a head of the same length
// whatever its text: GlbStream writes it last, over room left for it.
std::string glbHead(std::string json, size_t binaryBytes);
// The same written to `out` as it goes, the binary chunk from where it lies
// (a morph's animation holds hundreds of megabytes: no copy of them is made).
void writeGlb(std::ostream& out, std::string json, std::string_view binary);

}  // namespace lbmshape
