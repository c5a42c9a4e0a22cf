// Keeps the Vulkan loader, layers and drivers loaded once a probe has loaded them.
#pragma once

namespace luxel::gpu {

// Marks every shared library loaded so far as never to be unloaded (RTLD_NODELETE). Called after
// a Vulkan instance has enumerated its devices, when the loader has loaded the drivers. Drivers
// keep blocks from one-time initialisation in their globals (Mesa's lavapipe: 128 bytes under a
// pthread_once) and do not free them when the loader unloads them at vkDestroyInstance; unloaded,
// those blocks were unreachable, so LeakSanitizer reported a leak on every run that probed
// Vulkan, with a stack it could not even name. Resident, they stay reachable, as in any process
// that keeps its instance, and the next context does not load the driver again.
void keepLoadedLibrariesResident();

}  // namespace luxel::gpu
