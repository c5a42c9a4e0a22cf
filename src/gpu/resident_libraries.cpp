// RTLD_NODELETE on every loaded shared object (see resident_libraries.h).
#include "gpu/resident_libraries.h"

#include <dlfcn.h>
#include <link.h>

#include <string>
#include <vector>

namespace luxel::gpu {

void keepLoadedLibrariesResident() {
    // Names first, dlopen after: dlopen inside dl_iterate_phdr's callback could wait on the lock
    // the iteration holds.
    std::vector<std::string> names;
    dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void* out) {
            if (info->dlpi_name != nullptr && info->dlpi_name[0] != '\0') {
                static_cast<std::vector<std::string>*>(out)->emplace_back(info->dlpi_name);
            }
            return 0;
        },
        &names);
    for (const std::string& name : names) {
        // RTLD_NOLOAD only finds an object already loaded; the handle is kept on purpose, since
        // the object now stays for the life of the process anyway.
        dlopen(name.c_str(), RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
    }
}

}  // namespace luxel::gpu
