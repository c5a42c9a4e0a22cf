// A minimal SPIR-V reader: only the instructions that say how a compute shader's interface is laid
// out (SPIR-V 1.6 specification, sections 2.3 "Physical Layout" and 3 "Binary Form").
#include "gpu/spirv_reflect.h"

#include <algorithm>
#include <map>
#include <string>

namespace luxel::gpu {

namespace {

// Opcodes and enumerants used below (SPIR-V specification, section 3).
enum : std::uint32_t {
    kMagic = 0x07230203,
    kOpExecutionMode = 16,
    kOpTypeRuntimeArray = 29,
    kOpTypeStruct = 30,
    kOpTypePointer = 32,
    kOpConstant = 43,
    kOpConstantComposite = 44,
    kOpVariable = 59,
    kOpDecorate = 71,
    kOpMemberDecorate = 72,
    kOpExecutionModeId = 331,
    kModeLocalSize = 17,
    kModeLocalSizeId = 38,
    kDecorationArrayStride = 6,
    kDecorationBuiltIn = 11,
    kDecorationBinding = 33,
    kDecorationDescriptorSet = 34,
    kDecorationOffset = 35,
    kBuiltInWorkgroupSize = 25,
    kStoragePushConstant = 9,
    kStorageStorageBuffer = 12,
    kStorageUniform = 2,  // buffer blocks in SPIR-V before 1.3
};

}  // namespace

struct SpirvReflection::Tables {
    std::map<std::uint32_t, std::vector<std::uint32_t>> structMembers;  // id -> member types
    std::map<std::uint32_t, std::map<std::uint32_t, std::uint32_t>>
        offsets;                                                 // id -> member -> offset
    std::map<std::uint32_t, std::uint32_t> runtimeArrayElement;  // id -> element type
    std::map<std::uint32_t, std::uint32_t> arrayStride;
    std::map<std::uint32_t, std::uint32_t> pointee;  // pointer type id -> pointee type id
    std::map<std::uint32_t, std::uint32_t> binding, descriptorSet;
    std::map<std::uint32_t, std::uint32_t> bufferVariables;  // variable id -> pointer type id
    std::uint32_t pushVariableType = 0;

    SpirvStruct layoutOf(std::uint32_t structId) const {
        SpirvStruct s;
        const auto it = offsets.find(structId);
        const std::size_t members =
            structMembers.count(structId) ? structMembers.at(structId).size() : 0;
        for (std::uint32_t m = 0; m < members; ++m) {
            const bool known = it != offsets.end() && it->second.count(m);
            s.offsets.push_back(known ? it->second.at(m) : ~0u);
        }
        return s;
    }
};

Result<SpirvReflection> reflectSpirv(std::span<const std::uint32_t> words) {
    if (words.size() < 5 || words[0] != kMagic) return Error("not SPIR-V (bad magic number)");
    auto tables = std::make_shared<SpirvReflection::Tables>();
    SpirvReflection out;
    std::map<std::uint32_t, std::uint32_t> constants;
    std::map<std::uint32_t, std::vector<std::uint32_t>> composites;
    std::uint32_t builtinWorkgroupSize = 0;
    std::array<std::uint32_t, 3> localSizeIds{0, 0, 0};
    bool localSizeById = false;

    for (std::size_t at = 5; at < words.size();) {
        const std::uint32_t count = words[at] >> 16, op = words[at] & 0xffffu;
        if (count == 0 || at + count > words.size()) {
            return Error("malformed SPIR-V: instruction at word " + std::to_string(at) +
                         " runs past the end");
        }
        const std::span<const std::uint32_t> a = words.subspan(at + 1, count - 1);
        at += count;
        switch (op) {
            case kOpExecutionMode:
                if (a.size() >= 5 && a[1] == kModeLocalSize) {
                    out.workgroupSize = {a[2], a[3], a[4]};
                }
                break;
            case kOpExecutionModeId:
                if (a.size() >= 5 && a[1] == kModeLocalSizeId) {
                    localSizeIds = {a[2], a[3], a[4]};
                    localSizeById = true;
                }
                break;
            case kOpTypeStruct:
                if (!a.empty()) tables->structMembers[a[0]].assign(a.begin() + 1, a.end());
                break;
            case kOpTypeRuntimeArray:
                if (a.size() >= 2) tables->runtimeArrayElement[a[0]] = a[1];
                break;
            case kOpTypePointer:
                if (a.size() >= 3) tables->pointee[a[0]] = a[2];
                break;
            case kOpConstant:
                if (a.size() >= 3) constants[a[1]] = a[2];
                break;
            case kOpConstantComposite:
                if (a.size() >= 2) composites[a[1]].assign(a.begin() + 2, a.end());
                break;
            case kOpVariable:
                if (a.size() >= 3 && a[2] == kStoragePushConstant) {
                    tables->pushVariableType = a[0];
                } else if (a.size() >= 3 &&
                           (a[2] == kStorageStorageBuffer || a[2] == kStorageUniform)) {
                    tables->bufferVariables[a[1]] = a[0];
                }
                break;
            case kOpDecorate:
                if (a.size() >= 3 && a[1] == kDecorationBinding) tables->binding[a[0]] = a[2];
                if (a.size() >= 3 && a[1] == kDecorationDescriptorSet) {
                    tables->descriptorSet[a[0]] = a[2];
                }
                if (a.size() >= 3 && a[1] == kDecorationArrayStride) {
                    tables->arrayStride[a[0]] = a[2];
                }
                if (a.size() >= 3 && a[1] == kDecorationBuiltIn && a[2] == kBuiltInWorkgroupSize) {
                    builtinWorkgroupSize = a[0];
                }
                break;
            case kOpMemberDecorate:
                if (a.size() >= 4 && a[2] == kDecorationOffset) tables->offsets[a[0]][a[1]] = a[3];
                break;
            default:
                break;
        }
    }

    // The WorkgroupSize built-in overrides the execution mode (SPIR-V 2.16.2, "BuiltIn").
    auto resolve = [&](std::span<const std::uint32_t> ids) -> Result<std::array<std::uint32_t, 3>> {
        std::array<std::uint32_t, 3> size{};
        for (int i = 0; i < 3; ++i) {
            const auto c = constants.find(ids[static_cast<std::size_t>(i)]);
            if (c == constants.end()) return Error("workgroup size is not a plain constant");
            size[static_cast<std::size_t>(i)] = c->second;
        }
        return size;
    };
    if (builtinWorkgroupSize != 0 && composites.count(builtinWorkgroupSize) &&
        composites[builtinWorkgroupSize].size() == 3) {
        auto size = resolve(composites[builtinWorkgroupSize]);
        if (!size) return size.error();
        out.workgroupSize = *size;
    } else if (localSizeById) {
        auto size = resolve(localSizeIds);
        if (!size) return size.error();
        out.workgroupSize = *size;
    }

    if (tables->pushVariableType != 0) {
        const auto block = tables->pointee.find(tables->pushVariableType);
        if (block != tables->pointee.end() && tables->structMembers.count(block->second)) {
            const auto& members = tables->structMembers.at(block->second);
            // `uniform Push { Params params; }`: report Params; a block of scalars reports itself.
            const std::uint32_t inner =
                members.size() == 1 && tables->structMembers.count(members[0]) ? members[0]
                                                                               : block->second;
            out.pushConstants = tables->layoutOf(inner);
            out.hasPushConstants = true;
        }
    }
    out.tables = std::move(tables);
    return out;
}

std::vector<std::uint32_t> SpirvReflection::bufferBindings() const {
    std::vector<std::uint32_t> bindings;
    for (const auto& [variable, type] : tables->bufferVariables) {
        (void)type;
        const auto set = tables->descriptorSet.find(variable);
        const auto b = tables->binding.find(variable);
        if (b != tables->binding.end() &&
            (set == tables->descriptorSet.end() || set->second == 0)) {
            bindings.push_back(b->second);
        }
    }
    std::sort(bindings.begin(), bindings.end());
    return bindings;
}

Result<SpirvStruct> SpirvReflection::bufferElement(std::uint32_t binding) const {
    for (const auto& [variable, pointerType] : tables->bufferVariables) {
        const auto b = tables->binding.find(variable);
        const auto set = tables->descriptorSet.find(variable);
        if (b == tables->binding.end() || b->second != binding ||
            (set != tables->descriptorSet.end() && set->second != 0)) {
            continue;
        }
        const auto block = tables->pointee.find(pointerType);
        if (block == tables->pointee.end() || !tables->structMembers.count(block->second)) {
            return Error("binding " + std::to_string(binding) + " is not a buffer block");
        }
        const auto& members = tables->structMembers.at(block->second);
        const auto array = members.empty() ? tables->runtimeArrayElement.end()
                                           : tables->runtimeArrayElement.find(members.back());
        if (array == tables->runtimeArrayElement.end()) {
            // `buffer B { Params params; }`: one struct, no array.
            if (members.size() == 1 && tables->structMembers.count(members[0])) {
                return tables->layoutOf(members[0]);
            }
            return Error("binding " + std::to_string(binding) +
                         " holds neither a runtime array nor a single struct");
        }
        if (!tables->structMembers.count(array->second)) {
            return Error("binding " + std::to_string(binding) +
                         " is an array of scalars or vectors, not of a struct");
        }
        SpirvStruct s = tables->layoutOf(array->second);
        const auto stride = tables->arrayStride.find(members.back());
        s.arrayStride = stride == tables->arrayStride.end() ? 0 : stride->second;
        return s;
    }
    return Error("the shader has no storage buffer at binding " + std::to_string(binding));
}

}  // namespace luxel::gpu
