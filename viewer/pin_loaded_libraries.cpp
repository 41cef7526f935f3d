#include "viewer/pin_loaded_libraries.h"

#include <dlfcn.h>
#include <link.h>

#include <string>
#include <vector>

namespace upf::viewer {

void pin_loaded_libraries() {
  // Names first: dlopen is not called while dl_iterate_phdr holds the loader's list.
  std::vector<std::string> names;
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* out) {
        if (info->dlpi_name != nullptr && info->dlpi_name[0] != '\0')
          static_cast<std::vector<std::string>*>(out)->emplace_back(info->dlpi_name);
        return 0;
      },
      &names);
  // RTLD_NOLOAD finds a loaded library without loading anything; RTLD_NODELETE marks it never
  // to be unmapped. Our dlclose drops only the reference this dlopen took.
  for (const std::string& name : names)
    if (void* handle = dlopen(name.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE))
      dlclose(handle);
}

}  // namespace upf::viewer
