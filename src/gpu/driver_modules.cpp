#include "lbmshape/gpu/driver_modules.hpp"

#include <dlfcn.h>
#include <link.h>

#include "lbmshape/core/address_sanitizer.hpp"

namespace lbmshape::gpu {

void keepDriverModulesLoadedForLeakReports()
{
  if (!builtWithAddressSanitizer) return;
  // RTLD_NOLOAD only marks modules already loaded; a second dlopen with
  // RTLD_NODELETE makes the loader's later dlclose leave them mapped.
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void*) {
        if (info->dlpi_name && *info->dlpi_name) dlopen(info->dlpi_name, RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
        return 0;
      },
      nullptr);
}

}  // namespace lbmshape::gpu
