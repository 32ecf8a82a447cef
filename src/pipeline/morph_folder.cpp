#include "lbmshape/pipeline/morph_folder.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "lbmshape/core/atomic_file.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/core/temporary_files.hpp"

namespace lbmshape {

namespace fs = std::filesystem;

MorphFolder::MorphFolder(const fs::path& folder, bool force) : folder_(folder)
{
  std::error_code ec;
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec))
    throw OutputError("cannot write frames to " + folder.string() + ": it is a file, not a folder");
  try {
    make();
  } catch (...) {
    removeEmptyMade();  // the parents made before the folder failed
    throw;
  }
  try {
    lock_.emplace(folder);
  } catch (...) {
    // Another lbmshape holds it, perhaps the one whose mkdir this process's
    // beat: the folder is its now, and stays.
    forgetMade();
    throw;
  }
  try {
    // A killed morph's temporary files are no frames: gone before the
    // folder is judged empty (the folder is this process's now).
    removeDeadWritersTemporaryFiles(folder);
    if (!fs::is_empty(folder, ec) && !force)
      throw OutputError(folder.string() + " is not empty; use " + nameOf(Parameter::Force) +
                        " to write the frames into it anyway");
    AtomicFile probe(folder / "morph.glb");  // throws OutputError if the folder is not writable
  } catch (...) {
    removeEmptyMade();
    throw;
  }
}

void MorphFolder::make()
{
  std::error_code ec;
  const fs::path absolute = fs::absolute(folder_, ec).lexically_normal();
  std::vector<fs::path> missing;  // the folder first, then its missing parents
  for (fs::path p = absolute; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  // Listed before they are made, the folder first: a process that ends
  // without unwinding removes each listed folder that is empty, in turn.
  std::vector<int> tickets;
  for (const fs::path& p : missing) tickets.push_back(temporary_files::remember(p));
  for (size_t i = missing.size(); i-- > 0;) {  // the topmost first
    const fs::path& p = missing[i];
    int error = 0;
    {
      const temporary_files::Creation creation;
      if (::mkdir(p.c_str(), 0777) != 0) error = errno;
    }
    if (error == 0) {
      made_.emplace_back(p, tickets[i]);
      continue;
    }
    temporary_files::forget(tickets[i]);
    if (error == EEXIST && fs::is_directory(p, ec)) continue;  // another process made it just now
    for (size_t k = 0; k < i; ++k) temporary_files::forget(tickets[k]);
    const std::string reason = error == EACCES    ? p.parent_path().string() + " is not writable"
                               : error == ENOTDIR ? p.parent_path().string() + " is not a folder"
                                                  : std::string(std::strerror(error));
    throw OutputError("cannot create the folder " + folder_.string() + ": " + reason);
  }
}

void MorphFolder::forgetMade()
{
  for (const auto& [path, ticket] : made_) temporary_files::forget(ticket);
  made_.clear();
}

void MorphFolder::keep() { forgetMade(); }

void MorphFolder::removeEmptyMade()
{
  std::error_code ec;
  // The morph's own folder first, then up: each only if still empty.
  for (auto made = made_.rbegin(); made != made_.rend(); ++made)
    if (!fs::is_empty(made->first, ec) || !fs::remove(made->first, ec)) break;
  forgetMade();
}

MorphFolder::~MorphFolder() { removeEmptyMade(); }

}  // namespace lbmshape
