#include "lbmshape/core/process_settings.hpp"

#include <cstdlib>
#include <optional>
#include <string>

#include <gtest/gtest.h>

namespace {

// GLIBC_TUNABLES set to `value` (unset for nullopt) for one scope, then
// put back as it was.
class TunablesFor {
public:
  explicit TunablesFor(const std::optional<std::string>& value)
  {
    if (const char* old = std::getenv("GLIBC_TUNABLES")) old_ = old;
    if (value)
      setenv("GLIBC_TUNABLES", value->c_str(), 1);
    else
      unsetenv("GLIBC_TUNABLES");
  }
  ~TunablesFor()
  {
    if (old_)
      setenv("GLIBC_TUNABLES", old_->c_str(), 1);
    else
      unsetenv("GLIBC_TUNABLES");
  }

private:
  std::optional<std::string> old_;
};

bool asksWith(const std::optional<std::string>& tunables)
{
  TunablesFor scope(tunables);
  return lbmshape::mallocAsksForHugePages();
}

}  // namespace

TEST(ProcessSettings, HugePagesAreAskedForOnlyByANonZeroHugetlbTunable)
{
  EXPECT_FALSE(asksWith(std::nullopt));
  EXPECT_FALSE(asksWith(""));
  EXPECT_TRUE(asksWith("glibc.malloc.hugetlb=1"));
  EXPECT_TRUE(asksWith("glibc.malloc.hugetlb=2"));
  EXPECT_FALSE(asksWith("glibc.malloc.hugetlb=0"));
  EXPECT_FALSE(asksWith("glibc.malloc.hugetlb="));
  EXPECT_TRUE(asksWith("glibc.malloc.check=0:glibc.malloc.hugetlb=1"));
  EXPECT_FALSE(asksWith("glibc.malloc.check=0"));
  // The last of a repeated name counts, as glibc reads it.
  EXPECT_FALSE(asksWith("glibc.malloc.hugetlb=1:glibc.malloc.hugetlb=0"));
  EXPECT_TRUE(asksWith("glibc.malloc.hugetlb=0:glibc.malloc.hugetlb=1"));
  // Another tunable whose name merely ends the same is not it.
  EXPECT_FALSE(asksWith("x.glibc.malloc.hugetlb=1"));
}
