// The world a VoxelGpuRenderer uploads, as every pass over it binds it (voxel_render, path_trace,
// cascades_picture): bindings 0-5 and 7-9. Binding 6 is the ray caster's image, 11-14 the sun
// visibility arrays (sun_visibility.glsl).
layout(std430, set = 0, binding = 0) readonly buffer Params { VoxelRenderParams params; };
layout(std430, set = 0, binding = 1) readonly buffer Voxels { uint voxels[]; };
layout(std430, set = 0, binding = 2) readonly buffer ChunkSolid { uint chunkSolid[]; };
layout(std430, set = 0, binding = 3) readonly buffer TextureInfos { VoxelTextureInfo textureInfo[]; };
layout(std430, set = 0, binding = 4) readonly buffer Texels { vec4 texels[]; };
layout(std430, set = 0, binding = 5) readonly buffer SrgbTable { float srgbTable[]; };
layout(std430, set = 0, binding = 7) readonly buffer BrickMasks { uvec2 brickMasks[]; };
layout(std430, set = 0, binding = 8) readonly buffer BrickReach { uint brickReach[]; };
layout(std430, set = 0, binding = 9) readonly buffer Materials { VoxelMaterial materials[]; };
