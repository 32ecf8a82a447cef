#include "lbmshape/core/mapped_file.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "lbmshape/core/error.hpp"

namespace lbmshape {
namespace {

[[noreturn]] void refuse(const std::filesystem::path& path, const std::string& why)
{
  throw InputError("cannot read " + path.string() + ": " + why);
}

std::string kindOf(mode_t mode)
{
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  return "not a regular file";
}

// An open descriptor of a regular file, closed when it goes out of scope.
class RegularFile {
public:
  explicit RegularFile(const std::filesystem::path& path)
  {
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a
    // writer; it is refused below by its type instead.
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd_ < 0) {
      const int error = errno;
      if (error == ENOENT || error == ENOTDIR) refuse(path, "no such file");
      if (error == EACCES) refuse(path, "the file cannot be opened (check its permissions)");
      refuse(path, std::string("the file cannot be opened (") + std::strerror(error) + ")");
    }
    struct stat status {};
    if (::fstat(fd_, &status) != 0) refuse(path, std::string("cannot inspect the file (") + std::strerror(errno) + ")");
    if (!S_ISREG(status.st_mode)) {
      const std::string kind = kindOf(status.st_mode);
      refuse(path, (kind == "a folder" ? "it is a folder, not a file" : "it is " + kind + ", not a file"));
    }
    size_ = size_t(status.st_size);
  }
  ~RegularFile()
  {
    if (fd_ >= 0) ::close(fd_);
  }
  RegularFile(const RegularFile&) = delete;
  RegularFile& operator=(const RegularFile&) = delete;

  int descriptor() const { return fd_; }
  size_t size() const { return size_; }

private:
  int fd_ = -1;
  size_t size_ = 0;
};

}  // namespace

size_t requireReadableRegularFile(const std::filesystem::path& path) { return RegularFile(path).size(); }

MappedFile::MappedFile(const std::filesystem::path& path)
{
  RegularFile file(path);
  if (file.size() == 0) return;  // mmap refuses a length of 0; an empty view serves
  void* mapped = ::mmap(nullptr, file.size(), PROT_READ, MAP_PRIVATE, file.descriptor(), 0);
  if (mapped == MAP_FAILED) {
    const int error = errno;
    if (error == ENOMEM) throw std::bad_alloc();
    refuse(path, std::string("the file cannot be mapped into memory (") + std::strerror(error) + ")");
  }
  // The readers go through the file front to back (each thread its own
  // part), so the kernel may read ahead. (A file truncated by someone else
  // while it is mapped would end the process with SIGBUS: lbmshape's inputs
  // are not written while it reads them.)
  ::madvise(mapped, file.size(), MADV_SEQUENTIAL);
  ::madvise(mapped, file.size(), MADV_WILLNEED);
  data_ = static_cast<const char*>(mapped);
  size_ = file.size();
}

MappedFile::~MappedFile()
{
  if (data_) ::munmap(const_cast<char*>(data_), size_);
}

}  // namespace lbmshape
