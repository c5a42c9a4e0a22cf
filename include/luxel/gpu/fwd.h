// Forward declarations of the GPU runtime types, for headers that take a context.
#pragma once

namespace luxel::gpu {
class Context;
struct PassTiming;
}  // namespace luxel::gpu
