#include "app/keep_libraries_loaded.hpp"

#include "core/sanitizer_build.hpp"

#ifdef ISOPARM_ASAN
#include <dlfcn.h>
#include <link.h>
#include <string>
#include <vector>
#endif

namespace isoparm::app {

void keep_libraries_loaded_for_leak_reports() {
#ifdef ISOPARM_ASAN
    std::vector<std::string> names;
    ::dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void* out) {
            if (info->dlpi_name && *info->dlpi_name)
                static_cast<std::vector<std::string>*>(out)->emplace_back(info->dlpi_name);
            return 0;
        },
        &names);
    // RTLD_NOLOAD | RTLD_NODELETE on a loaded library marks it never to be unloaded (glibc's
    // dlopen(3)); the handle is deliberately kept.
    for (const std::string& name : names)
        (void)::dlopen(name.c_str(), RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
#endif
}

} // namespace isoparm::app
