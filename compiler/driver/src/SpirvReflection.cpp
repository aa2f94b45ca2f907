// SPDX-License-Identifier: Apache-2.0
// Reflection of a compiled stage program from its SPIR-V: blocks, resources, stage interface.
#include "varc/driver/SpirvReflection.h"

#include <algorithm>
#include <map>
#include <tuple>

#include "SpirvModule.h"
#include "varc/core/AsciiCase.h"

namespace varc::driver {

using namespace spv_consts;

namespace {

// HLSL spelling of a scalar, vector or matrix type: "float", "float4", "float4x4", "uint2".
std::string typeName(const SpirvModule& module, uint32_t typeId) {
    const SpirvType* type = module.type(typeId);
    if (!type) return "?";
    switch (type->op) {
        case OpTypeBool:
            return "bool";
        case OpTypeFloat:
            return type->operands.at(0) == 64   ? "double"
                   : type->operands.at(0) == 16 ? "half"
                                                : "float";
        case OpTypeInt:
            return type->operands.size() > 1 && type->operands[1] ? "int" : "uint";
        case OpTypeVector:
            return typeName(module, type->operands.at(0)) + std::to_string(type->operands.at(1));
        case OpTypeMatrix: {
            const SpirvType* column = module.type(type->operands.at(0));
            uint32_t rows = column && column->operands.size() > 1 ? column->operands[1] : 0;
            std::string scalar = column ? typeName(module, column->operands.at(0)) : "?";
            return scalar + std::to_string(type->operands.at(1)) + "x" + std::to_string(rows);
        }
        case OpTypeArray:
        case OpTypeRuntimeArray:
            return typeName(module, type->operands.at(0));
        case OpTypeStruct:
            return module.name(typeId).empty() ? "struct" : module.name(typeId);
        default:
            return "?";
    }
}

// Element count of an array type (0 = runtime-sized), or 0 when |typeId| is no array.
uint32_t arrayLength(const SpirvModule& module, uint32_t typeId) {
    const SpirvType* type = module.type(typeId);
    if (!type || type->op != OpTypeArray) return 0;
    return module.constant(type->operands.at(1)).value_or(0);
}

uint32_t scalarSize(const SpirvModule& module, uint32_t typeId) {
    const SpirvType* type = module.type(typeId);
    if (!type) return 0;
    if (type->op == OpTypeFloat || type->op == OpTypeInt) return type->operands.at(0) / 8;
    if (type->op == OpTypeBool) return 4;
    if (type->op == OpTypeVector)
        return scalarSize(module, type->operands.at(0)) * type->operands.at(1);
    return 0;
}

// Byte size of a block member of |typeId| with |decorations| (offset-based layouts).
uint32_t memberSize(const SpirvModule& module, uint32_t typeId, const Decorations& decorations);

uint32_t structSize(const SpirvModule& module, uint32_t structId) {
    const SpirvType* type = module.type(structId);
    uint32_t size = 0;
    for (uint32_t i = 0; type && i < type->operands.size(); ++i) {
        const Decorations& member = module.memberDecorations(structId, i);
        size = std::max(size, member.get(Offset) + memberSize(module, type->operands[i], member));
    }
    return size;
}

uint32_t memberSize(const SpirvModule& module, uint32_t typeId, const Decorations& decorations) {
    const SpirvType* type = module.type(typeId);
    if (!type) return 0;
    if (type->op == OpTypeArray) {
        uint32_t stride = module.decorations(typeId).get(ArrayStride);
        return arrayLength(module, typeId) * stride;
    }
    if (type->op == OpTypeMatrix) {
        const SpirvType* column = module.type(type->operands.at(0));
        uint32_t rows = column ? column->operands.at(1) : 0;
        uint32_t vectors = decorations.has(RowMajor) ? rows : type->operands.at(1);
        return vectors * decorations.get(MatrixStride);
    }
    if (type->op == OpTypeStruct) return structSize(module, typeId);
    return scalarSize(module, typeId);
}

std::vector<pack::BlockMember> blockMembers(const SpirvModule& module, uint32_t structId) {
    std::vector<pack::BlockMember> members;
    const SpirvType* type = module.type(structId);
    for (uint32_t i = 0; type && i < type->operands.size(); ++i) {
        const Decorations& decorations = module.memberDecorations(structId, i);
        uint32_t memberType = type->operands[i];
        members.push_back({module.memberName(structId, i), decorations.get(Offset),
                           memberSize(module, memberType, decorations),
                           typeName(module, memberType), arrayLength(module, memberType),
                           decorations.has(RowMajor)});
    }
    return members;
}

std::string blockName(const SpirvModule& module, uint32_t structId, uint32_t variableId) {
    std::string name = module.name(structId);
    return name.empty() ? module.name(variableId) : name;
}

// Strips array wrappers; sets |count| to the outermost length (1 when not an array).
uint32_t elementType(const SpirvModule& module, uint32_t typeId, uint32_t& count) {
    count = 1;
    const SpirvType* type = module.type(typeId);
    if (type && (type->op == OpTypeArray || type->op == OpTypeRuntimeArray)) {
        count = type->op == OpTypeArray ? arrayLength(module, typeId) : 0;
        return type->operands.at(0);
    }
    return typeId;
}

pack::ResourceDim imageDim(const SpirvType& image) {
    uint32_t dim = image.operands.at(1);
    bool arrayed = image.operands.at(3) != 0;
    switch (dim) {
        case 0:
            return arrayed ? pack::ResourceDim::Dim1DArray : pack::ResourceDim::Dim1D;
        case 1:
            return arrayed ? pack::ResourceDim::Dim2DArray : pack::ResourceDim::Dim2D;
        case 2:
            return pack::ResourceDim::Dim3D;
        case 3:
            return arrayed ? pack::ResourceDim::CubeArray : pack::ResourceDim::Cube;
        case 5:
            return pack::ResourceDim::Buffer;
        default:
            return pack::ResourceDim::None;
    }
}

// A UniformConstant variable's descriptor, or nullopt for types that are not descriptors.
std::optional<pack::ResourceBinding> resourceOf(const SpirvModule& module,
                                                const SpirvVariable& variable) {
    pack::ResourceBinding resource;
    uint32_t typeId = elementType(module, module.pointee(variable.pointerType), resource.arraySize);
    const SpirvType* type = module.type(typeId);
    if (!type) return std::nullopt;
    resource.name = module.name(variable.id);
    resource.dim = pack::ResourceDim::None;
    const Decorations& decorations = module.decorations(variable.id);
    resource.set = decorations.get(DescriptorSet);
    resource.binding = decorations.get(Binding);
    if (type->op == OpTypeSampler) {
        resource.kind = pack::ResourceKind::Sampler;
    } else if (type->op == OpTypeSampledImage || type->op == OpTypeImage) {
        const SpirvType* image = type->op == OpTypeImage ? type : module.type(type->operands.at(0));
        if (!image || image->operands.size() < 6) return std::nullopt;
        resource.dim = imageDim(*image);
        resource.multisampled = image->operands.at(4) != 0;
        bool storage = image->operands.at(5) == 2;
        bool buffer = resource.dim == pack::ResourceDim::Buffer;
        resource.kind = type->op == OpTypeSampledImage ? pack::ResourceKind::CombinedImageSampler
                        : buffer  ? (storage ? pack::ResourceKind::StorageTexelBuffer
                                             : pack::ResourceKind::UniformTexelBuffer)
                        : storage ? pack::ResourceKind::StorageImage
                                  : pack::ResourceKind::SampledImage;
    } else {
        return std::nullopt;
    }
    return resource;
}

std::map<uint32_t, std::string> semanticsByLocation(const SpirvModule& module) {
    std::map<uint32_t, std::string> semantics;
    for (const SpirvVariable& variable : module.variables()) {
        if (variable.storageClass != Input) continue;
        const Decorations& decorations = module.decorations(variable.id);
        auto semantic = decorations.strings.find(UserSemantic);
        if (decorations.has(Location) && semantic != decorations.strings.end()) {
            semantics[decorations.get(Location)] = toAsciiUpper(semantic->second);
        }
    }
    return semantics;
}

void addBlock(const SpirvModule& module, const SpirvVariable& variable,
              pack::ProgramReflection& reflection) {
    uint32_t structId = module.pointee(variable.pointerType);
    uint32_t count = 1;
    uint32_t element = elementType(module, structId, count);
    const Decorations& typeDecorations = module.decorations(element);
    const Decorations& decorations = module.decorations(variable.id);
    bool storage = variable.storageClass == StorageBuffer || typeDecorations.has(BufferBlock);
    if (storage) {
        pack::ResourceBinding resource{blockName(module, element, variable.id),
                                       pack::ResourceKind::StorageBuffer,
                                       pack::ResourceDim::None,
                                       decorations.get(DescriptorSet),
                                       decorations.get(Binding),
                                       count,
                                       false};
        reflection.resources.push_back(resource);
        return;
    }
    uint32_t size = (structSize(module, element) + 15u) & ~15u;
    reflection.uniformBlocks.push_back({blockName(module, element, variable.id),
                                        decorations.get(DescriptorSet), decorations.get(Binding),
                                        size, blockMembers(module, element)});
}

void addInterface(const SpirvModule& module, const SpirvVariable& variable,
                  const std::map<uint32_t, std::string>& semantics, bool isVertexStage,
                  pack::ProgramReflection& reflection) {
    const Decorations& decorations = module.decorations(variable.id);
    if (decorations.has(BuiltIn) || !decorations.has(Location)) return;
    uint32_t location = decorations.get(Location);
    std::string type = typeName(module, module.pointee(variable.pointerType));
    pack::StageVariable stageVariable{module.name(variable.id), location, type};
    if (variable.storageClass == Output) {
        reflection.outputs.push_back(stageVariable);
        return;
    }
    reflection.inputs.push_back(stageVariable);
    if (isVertexStage) {
        auto semantic = semantics.find(location);
        reflection.vertexInputs.push_back({stageVariable.name,
                                           semantic == semantics.end() ? "" : semantic->second,
                                           location, type});
    }
}

void sortReflection(pack::ProgramReflection& reflection) {
    auto byBinding = [](const auto& a, const auto& b) {
        return std::tie(a.set, a.binding, a.name) < std::tie(b.set, b.binding, b.name);
    };
    auto byLocation = [](const auto& a, const auto& b) {
        return std::tie(a.location, a.name) < std::tie(b.location, b.name);
    };
    std::sort(reflection.uniformBlocks.begin(), reflection.uniformBlocks.end(), byBinding);
    std::sort(reflection.resources.begin(), reflection.resources.end(), byBinding);
    std::sort(reflection.vertexInputs.begin(), reflection.vertexInputs.end(), byLocation);
    std::sort(reflection.inputs.begin(), reflection.inputs.end(), byLocation);
    std::sort(reflection.outputs.begin(), reflection.outputs.end(), byLocation);
}

}  // namespace

std::optional<SemanticsByLocation> hlslSemantics(std::span<const uint32_t> withSemantics) {
    auto original = SpirvModule::parse(withSemantics);
    if (!original) return std::nullopt;
    return semanticsByLocation(*original);
}

std::optional<pack::ProgramReflection> reflectSpirv(std::span<const uint32_t> optimized,
                                                    std::span<const uint32_t> withSemantics,
                                                    bool isVertexStage) {
    auto semantics = hlslSemantics(withSemantics);
    if (!semantics) return std::nullopt;
    return reflectSpirv(optimized, *semantics, isVertexStage);
}

std::optional<pack::ProgramReflection> reflectSpirv(std::span<const uint32_t> optimized,
                                                    const SemanticsByLocation& semantics,
                                                    bool isVertexStage) {
    auto module = SpirvModule::parse(optimized);
    if (!module) return std::nullopt;
    pack::ProgramReflection reflection;
    for (const SpirvVariable& variable : module->variables()) {
        switch (variable.storageClass) {
            case Uniform:
            case StorageBuffer:
                addBlock(*module, variable, reflection);
                break;
            case UniformConstant:
                if (auto resource = resourceOf(*module, variable))
                    reflection.resources.push_back(*resource);
                break;
            case PushConstant: {
                uint32_t structId = module->pointee(variable.pointerType);
                reflection.pushConstants.push_back({blockName(*module, structId, variable.id),
                                                    structSize(*module, structId),
                                                    blockMembers(*module, structId)});
                break;
            }
            case Input:
            case Output:
                addInterface(*module, variable, semantics, isVertexStage, reflection);
                break;
            default:
                break;
        }
    }
    sortReflection(reflection);
    return reflection;
}

}  // namespace varc::driver
