// SPDX-License-Identifier: Apache-2.0
// Parses a `Stencil { Ref n Comp x Pass x ... }` block into a StencilState.
#include "state/StencilParser.h"

#include <span>
#include <string>

#include "state/ValueSyntax.h"

namespace varc::shaderlab {
namespace {

constexpr std::string_view kCompareFunctions[] = {
    "Never", "Less", "Equal", "LEqual", "Greater", "NotEqual", "GEqual", "Always", "Disabled"};
constexpr std::string_view kOperations[] = {"Keep",    "Zero",   "Replace",  "IncrSat",
                                            "DecrSat", "Invert", "IncrWrap", "DecrWrap"};
constexpr int kMaxByte = 255;

// One face entry family: `Comp`, `CompFront`, `CompBack` all set StencilFace::comp.
struct FaceField {
    std::string_view name;
    StateValue StencilFace::*field;
    std::span<const std::string_view> names;
};

constexpr FaceField kFaceFields[] = {
    {"Comp", &StencilFace::comp, kCompareFunctions},
    {"Pass", &StencilFace::pass, kOperations},
    {"Fail", &StencilFace::fail, kOperations},
    {"ZFail", &StencilFace::zFail, kOperations},
};

enum class Faces { Both, Front, Back };

// Splits "CompFront" into {Comp field, Front}; nullptr when |key| is no face entry.
const FaceField* findFaceField(std::string_view key, Faces& faces) {
    for (const FaceField& entry : kFaceFields) {
        if (key.size() < entry.name.size() ||
            !equalsIgnoreAsciiCase(key.substr(0, entry.name.size()), entry.name)) {
            continue;
        }
        std::string_view suffix = key.substr(entry.name.size());
        if (suffix.empty())
            faces = Faces::Both;
        else if (equalsIgnoreAsciiCase(suffix, "Front"))
            faces = Faces::Front;
        else if (equalsIgnoreAsciiCase(suffix, "Back"))
            faces = Faces::Back;
        else
            continue;
        return &entry;
    }
    return nullptr;
}

}  // namespace

bool StencilParser::parse(StencilState& stencil) {
    Token open;
    if (!mCursor.expectSymbol('{', "after Stencil", &open)) return false;
    while (true) {
        BlockStep step = mCursor.blockStep(open);
        if (step == BlockStep::End) return true;
        if (step == BlockStep::Failed) return false;
        if (!parseEntry(stencil)) return false;
    }
}

bool StencilParser::parseEntry(StencilState& stencil) {
    Token key;
    if (!mCursor.expect(TokenKind::Identifier, "a Stencil command or '}'", key)) return false;
    if (key.isKeyword("Ref")) return parseByteValue("Ref", stencil.ref);
    if (key.isKeyword("ReadMask")) return parseByteValue("ReadMask", stencil.readMask);
    if (key.isKeyword("WriteMask")) return parseByteValue("WriteMask", stencil.writeMask);
    return parseFaceEntry(key, stencil);
}

bool StencilParser::parseByteValue(std::string_view name, StateValue& out) {
    const Token& token = mCursor.peek();
    if (token.is(TokenKind::Number) && name == "Ref") return parseReference(out);
    if (token.is(TokenKind::Number)) {
        std::optional<int> value = integerOf(token);
        if (!value || *value < 0 || *value > kMaxByte) {
            return mCursor.fail(token.location, "invalid Stencil " + std::string(name) + " value " +
                                                    token.describe() +
                                                    "; expected an integer from 0 to 255");
        }
    }
    return parseStateValue(mCursor, "Stencil " + std::string(name), {}, true, out);
}

// Unity accepts a reference above 255; the GPU compares only the stencil buffer's 8 bits, so
// the value in effect is its low byte. varc keeps that byte and warns (`Ref 256` is 0).
bool StencilParser::parseReference(StateValue& out) {
    Token token = mCursor.next();
    std::optional<int> value = integerOf(token);
    if (!value || *value < 0) {
        return mCursor.fail(token.location, "invalid Stencil Ref value " + token.describe() +
                                                "; expected a non-negative integer");
    }
    if (*value > kMaxByte) {
        int lowByte = *value & kMaxByte;
        mCursor.sink().warning(token.location,
                               "Stencil Ref " + std::to_string(*value) +
                                   " is above 255; the stencil buffer holds 8 bits, so it acts "
                                   "as " + std::to_string(lowByte));
        out = StateValue{std::to_string(lowByte), {}};
        return true;
    }
    out = StateValue{std::string(token.text), {}};
    return true;
}

bool StencilParser::parseFaceEntry(const Token& key, StencilState& stencil) {
    Faces faces = Faces::Both;
    const FaceField* entry = findFaceField(key.text, faces);
    if (!entry) {
        return mCursor.fail(key.location, "unknown Stencil command " + key.describe());
    }
    StateValue value;
    std::string command = "Stencil " + std::string(key.text);
    if (!parseStateValue(mCursor, command, entry->names, true, value)) return false;
    if (faces != Faces::Back) stencil.front.*(entry->field) = value;
    if (faces != Faces::Front) stencil.back.*(entry->field) = value;
    return true;
}

}  // namespace varc::shaderlab
