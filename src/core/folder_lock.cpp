#include "lbmshape/core/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/log.hpp"

namespace lbmshape {

FolderLock::FolderLock(const std::filesystem::path& folder)
{
  fd_ = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) throw OutputError("cannot open the folder " + folder.string() + ": " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK)
      throw OutputError(folder.string() +
                        " is being written by another lbmshape; wait for it, or choose another folder");
    // A file system without locks (some network mounts) only loses the
    // guard against a second writer; the morph itself can go on.
    log::verbose("cannot lock the folder " + folder.string() + " (" + std::strerror(error) +
                 "): nothing stops a second lbmshape writing into it");
  }
}

FolderLock::~FolderLock()
{
  if (fd_ >= 0) ::close(fd_);  // closing releases the lock
}

}  // namespace lbmshape
