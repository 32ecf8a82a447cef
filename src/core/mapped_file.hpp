// A file's bytes, mapped read-only into memory, so that a reader parses it in
// place in one pass, split across threads if it likes, without a copy.
//
// Only regular files are opened: a folder, a FIFO, a socket or a device is
// refused before a single byte is read, so no path can make a reader block
// forever or read without end.
#pragma once

#include <filesystem>
#include <string_view>

namespace lbmshape {

class MappedFile {
public:
  // Throws InputError ("cannot read PATH: ...") when the path is missing, is
  // not a regular file, or cannot be opened or mapped.
  explicit MappedFile(const std::filesystem::path& path);
  ~MappedFile();

  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  // The whole file; empty for an empty file.
  std::string_view bytes() const { return {data_, size_}; }

private:
  const char* data_ = nullptr;
  size_t size_ = 0;
};

// Throws InputError ("cannot read PATH: ...") unless the path names a regular
// file that can be opened for reading; returns its size. Opens without
// blocking, so a FIFO is refused rather than waited on.
size_t requireReadableRegularFile(const std::filesystem::path& path);

}  // namespace lbmshape
