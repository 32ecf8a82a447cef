#include "support/scratch_folder.hpp"

#include <algorithm>
#include <random>
#include <stdexcept>

#include <unistd.h>

namespace lbmshape::testing {

ScratchFolder::ScratchFolder()
{
  std::random_device entropy;
  for (int attempt = 0; attempt < 100 && path_.empty(); ++attempt) {
    auto candidate = std::filesystem::temp_directory_path() /
                     ("lbmshape-test-" + std::to_string(::getpid()) + "-" + std::to_string(entropy()));
    if (std::filesystem::create_directory(candidate)) path_ = candidate;
  }
  if (path_.empty()) throw std::runtime_error("cannot create a scratch folder");
}

ScratchFolder::~ScratchFolder()
{
  std::error_code ec;
  std::filesystem::permissions(path_, std::filesystem::perms::owner_all, std::filesystem::perm_options::add, ec);
  std::filesystem::remove_all(path_, ec);
}

std::vector<std::string> ScratchFolder::entries() const
{
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(path_))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace lbmshape::testing
