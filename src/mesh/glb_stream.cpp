#include "mesh/glb_stream.hpp"

#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "mesh/glb_container.hpp"

namespace lbmshape {
namespace {

void writeWord(std::ostream& out, uint32_t value) { out.write(reinterpret_cast<const char*>(&value), 4); }

constexpr size_t headerBytes = 12, chunkHeaderBytes = 8;
constexpr uint32_t glbMagic = 0x46546C67, jsonChunk = 0x4E4F534A, binaryChunk = 0x004E4942;

size_t paddedToFour(size_t bytes) { return (bytes + 3) / 4 * 4; }

}  // namespace

GlbStream::GlbStream(std::filesystem::path target, size_t jsonRoom)
    : file_(std::move(target)), out_(file_.open()), jsonRoom_(paddedToFour(jsonRoom))
{
  // The header, the JSON chunk's header and its room, the binary chunk's
  // header: all written again by finish().
  out_ << std::string(headerBytes + chunkHeaderBytes + jsonRoom_ + chunkHeaderBytes, ' ');
  requireGood();
}

void GlbStream::requireGood()
{
  if (!out_)
    throw OutputError("cannot write " + file_.target().string() + ": writing the file failed (is the disk full?)");
}

void GlbStream::append(const std::vector<unsigned char>& bytes)
{
  // A .glb states its length in 32 bits.
  if (headerBytes + 2 * chunkHeaderBytes + jsonRoom_ + paddedToFour(binaryBytes_ + bytes.size()) > UINT32_MAX)
    throw OutputError("cannot write " + file_.target().string() +
                      ": a .glb holds at most 4 GiB; give fewer frames, a coarser grid or --no-animation");
  out_.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  binaryBytes_ += bytes.size();
  requireGood();
}

void GlbStream::finish(const std::string& json)
{
  const size_t binaryChunkBytes = paddedToFour(binaryBytes_);
  out_ << std::string(binaryChunkBytes - binaryBytes_, '\0');
  if (json.size() > jsonRoom_) {
    // Longer than the room left for it: the file again, its binary chunk
    // copied from the first (never so far: the room is half again the
    // longest JSON measured a frame).
    out_.close();
    AtomicFile again(file_.target());
    std::ofstream copy = again.open();
    std::ifstream first(file_.temporaryPath(), std::ios::binary);
    first.seekg(std::streamoff(headerBytes + 2 * chunkHeaderBytes + jsonRoom_));
    std::string binary(binaryBytes_, '\0');  // the rare path: in memory
    first.read(binary.data(), std::streamsize(binary.size()));
    writeGlb(copy, json, binary);
    copy.close();
    if (!first || !copy)
      throw OutputError("cannot write " + file_.target().string() + ": writing the file failed (is the disk full?)");
    again.commit();
    first.close();
    std::error_code ignored;  // the AtomicFile removes it at the latest
    std::filesystem::remove(file_.temporaryPath(), ignored);
    return;
  }
  const size_t total =
      headerBytes + chunkHeaderBytes + jsonRoom_ + (binaryBytes_ > 0 ? chunkHeaderBytes + binaryChunkBytes : 0);
  out_.seekp(0);
  writeWord(out_, glbMagic);
  writeWord(out_, 2);
  writeWord(out_, uint32_t(total));
  writeWord(out_, uint32_t(jsonRoom_));
  writeWord(out_, jsonChunk);
  out_ << json << std::string(jsonRoom_ - json.size(), ' ');
  if (binaryBytes_ > 0) {
    writeWord(out_, uint32_t(binaryChunkBytes));
    writeWord(out_, binaryChunk);
  }
  out_.close();
  requireGood();
  // Without a binary chunk, its header's room is cut off.
  if (binaryBytes_ == 0) std::filesystem::resize_file(file_.temporaryPath(), total);
  file_.commit();
}

}  // namespace lbmshape
