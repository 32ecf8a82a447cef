#include "lbmshape/mesh/glb_stream.hpp"

#include <cstdint>
#include <string>

#include "lbmshape/core/error.hpp"
#include "lbmshape/mesh/glb_container.hpp"

namespace lbmshape {

GlbStream::GlbStream(std::filesystem::path target, size_t jsonRoom)
    : file_(std::move(target)), out_(file_.open()), jsonRoom_(glbPadded(jsonRoom))
{
  // The head of the file (glbHead), the JSON chunk's room and the binary
  // chunk's header included: all written again by finish().
  out_ << std::string(headBytes(), ' ');
  requireGood();
}

size_t GlbStream::headBytes() const
{
  return glbHead(std::string(), 1).size() + jsonRoom_;  // with the binary chunk's header
}

void GlbStream::failed() const { throw OutputError("cannot write " + file_.target().string() + ": " + writeFailure()); }

void GlbStream::requireGood()
{
  if (!out_) failed();
}

void GlbStream::append(const std::vector<unsigned char>& bytes)
{
  // A .glb states its length in 32 bits.
  if (headBytes() + glbPadded(binaryBytes_ + bytes.size()) > UINT32_MAX)
    throw OutputError("cannot write " + file_.target().string() +
                      ": a .glb holds at most 4 GiB; give fewer frames, a coarser grid or --no-animation");
  out_.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  binaryBytes_ += bytes.size();
  requireGood();
}

void GlbStream::finish(const std::string& json)
{
  const size_t binaryChunkBytes = glbPadded(binaryBytes_);
  out_ << std::string(binaryChunkBytes - binaryBytes_, '\0');
  if (json.size() > jsonRoom_) {
    // Longer than the room left for it: the file again, its binary chunk
    // copied from the first (never so far: the room is half again the
    // longest JSON measured a frame).
    out_.close();
    AtomicFile again(file_.target());
    std::ofstream copy = again.open();
    std::ifstream first(file_.temporaryPath(), std::ios::binary);
    first.seekg(std::streamoff(headBytes()));
    std::string binary(binaryBytes_, '\0');  // the rare path: in memory
    first.read(binary.data(), std::streamsize(binary.size()));
    writeGlb(copy, json, binary);
    copy.close();
    if (!first || !copy) failed();
    again.commit();
    first.close();
    std::error_code ignored;  // the AtomicFile removes it at the latest
    std::filesystem::remove(file_.temporaryPath(), ignored);
    return;
  }
  // The JSON fills its room with spaces, so the head is as long as the
  // room left for it (less the binary chunk's header without binary bytes).
  const std::string head = glbHead(json + std::string(jsonRoom_ - json.size(), ' '), binaryBytes_);
  out_.seekp(0);
  out_ << head;
  out_.close();
  requireGood();
  // Without a binary chunk, its header's room is cut off.
  if (binaryBytes_ == 0) std::filesystem::resize_file(file_.temporaryPath(), head.size());
  file_.commit();
}

}  // namespace lbmshape
