#include "gpu/driver_modules.hpp"

#include <dlfcn.h>
#include <link.h>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LBMSHAPE_LEAK_CHECKED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define LBMSHAPE_LEAK_CHECKED 1
#endif

namespace lbmshape::gpu {

void keepDriverModulesLoadedForLeakReports()
{
#ifdef LBMSHAPE_LEAK_CHECKED
  // RTLD_NOLOAD only marks modules already loaded; a second dlopen with
  // RTLD_NODELETE makes the loader's later dlclose leave them mapped.
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void*) {
        if (info->dlpi_name && *info->dlpi_name) dlopen(info->dlpi_name, RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
        return 0;
      },
      nullptr);
#endif
}

}  // namespace lbmshape::gpu
