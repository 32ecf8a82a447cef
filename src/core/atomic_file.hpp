// Writes a file all at once or not at all. Output goes to a temporary file
// beside the target, and commit() renames it over the target, which is atomic
// on one file system: a crash, a full disk or an exception half way through a
// write never leaves a truncated file under the target's name, and readers of
// the target see either the old content or the new. A second Ctrl-C, which
// ends the process without unwinding, removes the temporary file too
// (temporary_files.hpp). A target that is a symbolic link is written
// through: the file it points to gets the content (the temporary file
// beside that one) and the link stays, as a shell's `>` does; replacing the
// link with a file cut the tie a render farm's or asset store's link had
// made.
#pragma once

#include <filesystem>
#include <string>
#include <fstream>

namespace lbmshape {

// "writing the file failed (...)": why, from the errno a failed write left
// (the disk full, the file-size limit of ulimit -f, a quota, an I/O error),
// for the message that names the file. Called right after the failure.
std::string writeFailure();

class AtomicFile {
public:
  // Creates the (empty) temporary file at once, so that a missing or
  // unwritable folder is reported (OutputError naming the target) before any
  // work is spent on the content.
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();  // removes the temporary file unless committed

  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::filesystem::path& target() const { return target_; }
  // Hidden, in the folder of the file the target names (its links
  // followed), and ending with that file's extension,
  // so that writers which choose the format by file name write the right one.
  const std::filesystem::path& temporaryPath() const { return temporary_; }
  // The temporary file opened for writing from its start, never made again:
  // once the last-resort handler has removed it (temporary_files.hpp), the
  // stream fails instead of leaving a new file behind. Writers use this
  // rather than opening temporaryPath() with a mode that creates files.
  std::ofstream open() const;

  // Flushes the temporary file to disk and renames it to the target
  // (replacing any file there). Throws OutputError naming the target.
  void commit();

private:
  std::filesystem::path target_;       // as given, for messages
  std::filesystem::path destination_;  // what the rename replaces: the target, its links followed
  std::filesystem::path temporary_;
  bool committed_ = false;
  int ticket_ = -1;  // in temporary_files, until committed or removed
};

// Removes from `folder` the temporary files of AtomicFiles whose process is
// gone: one killed by a signal no handler sees (SIGKILL, the kernel's
// out-of-memory killer) leaves its ".<name>.tmp-<tag>-<pid>-<n><ext>",
// which stayed for ever and made the folder "not empty" to the next morph
// into it. The tag names the machine, its boot and its process-id
// namespace: files of live processes, and of other machines or containers
// (a folder shared over the network or a volume), are left; files named
// before the tag are taken for this machine's (a locked morph folder's).
// Returns how many went. Never throws. commit() removes this machine's
// dead writers' files (tagged ones only) from each folder it writes into,
// once a process.
size_t removeDeadWritersTemporaryFiles(const std::filesystem::path& folder);

}  // namespace lbmshape
