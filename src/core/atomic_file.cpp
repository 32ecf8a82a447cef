#include "lbmshape/core/atomic_file.hpp"

#include <atomic>
#include <set>
#include <mutex>
#include <fstream>
#include <cstdio>
#include <charconv>
#include <cerrno>
#include <cstring>
#include <limits>
#include <regex>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <signal.h>
#include <unistd.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/temporary_files.hpp"

namespace lbmshape {

std::string writeFailure()
{
  const int error = errno;
  switch (error) {
  case ENOSPC: return "writing the file failed: the disk is full";
  case EFBIG: return "writing the file failed: it would pass the file-size limit (ulimit -f)";
  case EDQUOT: return "writing the file failed: the disk quota is used up";
  case EIO: return "writing the file failed: an input/output error";
  default: return "writing the file failed (is the disk full?)";
  }
}
namespace {

std::string failure(const std::filesystem::path& target, const std::string& why)
{
  return "cannot write " + target.string() + ": " + why;
}

// Opens `path` read-only and forces its data to disk. Without this a crash
// soon after the rename can leave an empty file under the new name on file
// systems that order metadata before data (ext4 with delalloc, XFS).
// Returns 0 or the errno of the failure.
int syncToDisk(const std::filesystem::path& path, int flags)
{
  int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) return errno;
  int error = ::fsync(fd) == 0 || errno == EINVAL ? 0 : errno;  // EINVAL: this file system has nothing to sync
  ::close(fd);
  return error;
}

// Where this process's id means this process, as temporary files carry it:
// 16 hex digits of a hash of the host's name, its boot's id and the inode
// of the process-id namespace. Two machines sharing a folder over the
// network, two containers with one host name (pods whose names share a
// prefix, --uts=host) or a machine after a reboot each have their own, and
// none takes another's live writer for dead.
const std::string& writerTag()
{
  static const std::string tag = [] {
    std::string identity;
    char name[256] = {};
    if (::gethostname(name, sizeof name - 1) == 0) identity += name;
    std::ifstream boot("/proc/sys/kernel/random/boot_id");
    std::string bootId;
    std::getline(boot, bootId);
    identity += "/" + bootId;
    struct stat space {};
    if (::stat("/proc/self/ns/pid", &space) == 0) identity += "/" + std::to_string(space.st_ino);
    uint64_t hash = 14695981039346656037ull;  // FNV-1a
    for (const char c : identity) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    return std::string(hex);
  }();
  return tag;
}

// The folder a file lies in ("." for a bare name).
std::filesystem::path folderOf(const std::filesystem::path& file)
{
  return file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
}

// The file `path` names once its symbolic links are followed (a link that
// points nowhere names the file it would point to; a relative link is read
// from its own folder). A loop of links is left to the writing to report.
std::filesystem::path followedLinks(std::filesystem::path path)
{
  std::error_code ec;
  for (int hop = 0; hop < 40 && std::filesystem::is_symlink(path, ec); ++hop) {
    const std::filesystem::path next = std::filesystem::read_symlink(path, ec);
    if (ec) break;
    path = next.is_absolute() ? next : path.parent_path() / next;
  }
  return path;
}

std::string kindOfFile(std::filesystem::file_type type)
{
  switch (type) {
  case std::filesystem::file_type::directory: return "a folder";
  case std::filesystem::file_type::character:
  case std::filesystem::file_type::block: return "a device";
  case std::filesystem::file_type::fifo: return "a named pipe";
  case std::filesystem::file_type::socket: return "a socket";
  default: return "not a file";
  }
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target))
{
  if (target_.filename().empty() || target_.filename() == "." || target_.filename() == "..")
    throw OutputError(failure(target_, "the path names a folder, not a file"));
  std::error_code ec;
  if (std::filesystem::is_directory(target_, ec)) throw OutputError(failure(target_, "it is a folder"));
  destination_ = followedLinks(target_);
  // The new file is renamed over the old: a device, a pipe or a socket
  // there would be replaced by a plain file (as root, /dev/null itself).
  if (const auto type = std::filesystem::status(destination_, ec).type();
      !ec && type != std::filesystem::file_type::regular && type != std::filesystem::file_type::not_found)
    throw OutputError(failure(target_, (destination_ == target_ ? "it" : destination_.string()) + " is " +
                                           kindOfFile(type) + ", not a regular file"));
  const std::filesystem::path folder = folderOf(destination_);
  if (!std::filesystem::is_directory(folder, ec))
    throw OutputError(failure(target_, std::filesystem::exists(folder, ec)
                                           ? folder.string() + " is not a folder"
                                           : "the folder " + folder.string() + " does not exist"));

  // Several writers (threads, or processes writing frames into one folder)
  // may work at once: the process id and a counter keep their names apart,
  // and O_EXCL makes sure no one else's file is ever taken over.
  static std::atomic<unsigned> counter{0};
  const std::string stem = destination_.stem().string(), extension = destination_.extension().string();
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::filesystem::path candidate = folder / ("." + stem + ".tmp-" + writerTag() + "-" + std::to_string(::getpid()) +
                                                "-" + std::to_string(counter++) + extension);
    // Listed before it is made (a second Ctrl-C or an abort ends the process
    // without unwinding): listed only after, a signal in between left it.
    // A name that is taken (a dead process's leftover) is taken off again.
    const temporary_files::Creation creation;
    const int ticket = temporary_files::remember(candidate);
    int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      temporary_ = std::move(candidate);
      ticket_ = ticket;
      return;
    }
    const int error = errno;
    temporary_files::forget(ticket);
    if (error != EEXIST) throw OutputError(failure(target_, std::strerror(error)));
  }
  throw OutputError(failure(target_, "no free temporary file name in " + folder.string()));
}

std::ofstream AtomicFile::open() const
{
  // in | out is fopen's "r+": the file must exist. It is empty until written
  // (the constructor made it so), so nothing needs truncating.
  return std::ofstream(temporary_, std::ios::binary | std::ios::in | std::ios::out);
}

AtomicFile::~AtomicFile()
{
  if (committed_ || temporary_.empty()) return;
  std::error_code ec;
  std::filesystem::remove(temporary_, ec);  // nothing more to do if it is already gone
  temporary_files::forget(ticket_);
}

namespace {

// Removes the temporary files in `folder` whose writer is gone: those with
// this process's tag (writerTag) whose process id names no process, and
// with `untaggedToo` those named before the tag was written, as a locked
// morph folder may. Never throws: a name, an id or an entry it cannot read
// is passed over.
size_t removeDead(const std::filesystem::path& folder, bool untaggedToo) noexcept
{
  try {
    // ".<stem>.tmp-<tag>-<pid>-<n><ext>", or without the tag.
    static const std::regex temporaryName(R"(^\..*\.tmp-(?:([A-Za-z0-9_]+)-)?([0-9]+)-[0-9]+(\.[^.]*)?$)");
    size_t removed = 0;
    std::error_code ec;
    for (std::filesystem::directory_iterator entry(folder, ec), end; !ec && entry != end; entry.increment(ec)) {
      std::smatch match;
      const std::string name = entry->path().filename().string();
      if (!name.starts_with(".") || name.find(".tmp-") == std::string::npos) continue;
      if (!std::regex_match(name, match, temporaryName) || !entry->is_regular_file(ec)) continue;
      if (match[1].matched ? match[1].str() != writerTag() : !untaggedToo) continue;
      const std::string digits = match[2].str();
      uint64_t pid = 0;
      if (std::from_chars(digits.data(), digits.data() + digits.size(), pid).ec != std::errc()) continue;
      // kill(pid, 0) sends nothing: ESRCH says no process has the id.
      if (pid == 0 || pid > uint64_t(std::numeric_limits<pid_t>::max()) || ::kill(pid_t(pid), 0) == 0 || errno != ESRCH)
        continue;
      std::error_code removal;
      if (std::filesystem::remove(entry->path(), removal)) ++removed;
    }
    return removed;
  } catch (...) {
    return 0;  // (std::regex or an allocation): the leftovers stay, as they did
  }
}

}  // namespace

size_t removeDeadWritersTemporaryFiles(const std::filesystem::path& folder) { return removeDead(folder, true); }

void AtomicFile::commit()
{
  if (committed_) return;
  if (int error = syncToDisk(temporary_, O_RDONLY)) throw OutputError(failure(target_, std::strerror(error)));
  std::error_code ec;
  std::filesystem::rename(temporary_, destination_, ec);
  if (ec) throw OutputError(failure(target_, ec.message()));
  committed_ = true;
  temporary_files::forget(ticket_);
  // What writers on this machine left in the folder when they were killed
  // without unwinding (SIGKILL, the out-of-memory killer) goes now: once a
  // folder in a process, not once a file (a morph's frames would read the
  // folder once each).
  {
    static std::mutex cleaned;
    static std::set<std::string> folders;
    std::unique_lock lock(cleaned);
    if (folders.insert(folderOf(destination_).string()).second) {
      lock.unlock();
      removeDead(folderOf(destination_), false);
    }
  }
  // The rename itself reaches the disk with the folder's own metadata; if
  // that cannot be forced the file is still complete, only perhaps not yet
  // durable, so this is not an error.
  syncToDisk(folderOf(destination_), O_RDONLY | O_DIRECTORY);
}

}  // namespace lbmshape
