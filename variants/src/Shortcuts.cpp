// SPDX-License-Identifier: Apache-2.0
// The built-in shortcut table (sets in Unity's enumeration order, validity rules) and options.
#include "varc/variants/Shortcuts.h"

#include <algorithm>

#include "varc/variants/RuntimeKeywords.h"

namespace varc::variants {

namespace {

using Sets = std::vector<std::vector<std::string>>;
using Names = std::vector<std::string>;

// Unity's fwdadd light-type set, in the manual's (and the observed listing's) order.
Names lightTypes() {
    return {"POINT", "DIRECTIONAL", "SPOT", "POINT_COOKIE", "DIRECTIONAL_COOKIE"};
}

ValidityRule needsAnyOf(std::string keyword, Names anyOf) {
    return {std::move(keyword), std::move(anyOf), {}, {}};
}

ValidityRule excludes(std::string keyword, Names none) {
    return {std::move(keyword), {}, std::move(none), {}};
}

// Unity 5.5's shadowed light passes (docs/KEYWORDS.md §4): soft set slowest, shadow kind,
// light type fastest; every shadow keyword needs a light type that can carry it. This order
// reproduces the observed 13-variant listing exactly.
Shortcut shadowedLightShortcut(std::string name) {
    Sets sets = {{"", "SHADOWS_SOFT"},
                 {"", "SHADOWS_DEPTH", "SHADOWS_SCREEN", "SHADOWS_CUBE"},
                 lightTypes()};
    std::vector<ValidityRule> rules = {
        needsAnyOf("SHADOWS_DEPTH", {"SPOT"}),
        needsAnyOf("SHADOWS_SCREEN", {"DIRECTIONAL", "DIRECTIONAL_COOKIE"}),
        needsAnyOf("SHADOWS_CUBE", {"POINT", "POINT_COOKIE"}),
        needsAnyOf("SHADOWS_SOFT", {"SHADOWS_DEPTH", "SHADOWS_CUBE"}),
    };
    return {std::move(name), std::move(sets), std::move(rules), "docs/KEYWORDS.md §4"};
}

// fwdbase / fwdbasealpha (§1.3, INFERRED): DIRECTIONAL always on, then on/off sets. The set
// order makes VERTEXLIGHT_ON vary slowest, SHADOWS_SCREEN next and LIGHTPROBE_SH fastest, which
// is the observed 8-variant listing of §1.2.
Shortcut forwardBaseShortcut(std::string name, bool withShadows) {
    Sets sets = {{"DIRECTIONAL"},
                 {"", "VERTEXLIGHT_ON"},
                 {"", "LIGHTMAP_ON"},
                 {"", "DIRLIGHTMAP_COMBINED"},
                 {"", "DYNAMICLIGHTMAP_ON"}};
    if (withShadows) {
        sets.push_back({"", "SHADOWS_SCREEN"});
        sets.push_back({"", "SHADOWS_SHADOWMASK"});
    }
    sets.push_back({"", "LIGHTMAP_SHADOW_MIXING"});
    sets.push_back({"", "LIGHTPROBE_SH"});
    Names mixingNeeds =
        withShadows ? Names{"LIGHTMAP_ON", "SHADOWS_SHADOWMASK"} : Names{"LIGHTMAP_ON"};
    std::vector<ValidityRule> rules = {
        excludes("VERTEXLIGHT_ON", {"LIGHTMAP_ON"}),
        needsAnyOf("DIRLIGHTMAP_COMBINED", {"LIGHTMAP_ON", "DYNAMICLIGHTMAP_ON"}),
        needsAnyOf("LIGHTMAP_SHADOW_MIXING", std::move(mixingNeeds)),
    };
    return {std::move(name), std::move(sets), std::move(rules), "docs/KEYWORDS.md §4"};
}

Shortcut plainShortcut(std::string name, Sets sets, std::string source) {
    return {std::move(name), std::move(sets), {}, std::move(source)};
}

std::vector<Shortcut> makeShortcuts() {
    std::vector<Shortcut> table;
    table.push_back(plainShortcut("fwdadd", {lightTypes()}, "docs/KEYWORDS.md §4"));
    table.push_back(shadowedLightShortcut("fwdadd_fullshadows"));
    table.push_back(shadowedLightShortcut("lightpass"));
    table.push_back(forwardBaseShortcut("fwdbase", true));
    table.push_back(forwardBaseShortcut("fwdbasealpha", false));
    // Absent from Unity's manual, used by shaders that compile in Unity: the base pass only ever
    // draws the main directional light, whose shadows fwdbase already covers (docs/KEYWORDS.md §4).
    table.push_back(forwardBaseShortcut("fwdbase_fullshadows", true));
    Shortcut prepass = plainShortcut("prepassfinal",
                                     {{"", "LIGHTMAP_ON"},
                                      {"", "DIRLIGHTMAP_COMBINED"},
                                      {"", "DYNAMICLIGHTMAP_ON"},
                                      {"", kHdrKeyword},
                                      {"", "SHADOWS_SHADOWMASK"},
                                      {"", "LIGHTPROBE_SH"}},
                                     "docs/KEYWORDS.md §4");
    prepass.rules.push_back(
        needsAnyOf("DIRLIGHTMAP_COMBINED", {"LIGHTMAP_ON", "DYNAMICLIGHTMAP_ON"}));
    table.push_back(std::move(prepass));
    table.push_back(
        plainShortcut("shadowcaster", {{"SHADOWS_DEPTH", "SHADOWS_CUBE"}}, "docs/KEYWORDS.md §4"));
    table.push_back(plainShortcut("shadowcollector",
                                  {{"", "SHADOWS_SPLIT_SPHERES"}, {"", "SHADOWS_SINGLE_CASCADE"}},
                                  "docs/KEYWORDS.md §4"));
    table.push_back(
        plainShortcut("fog", {{"", "FOG_LINEAR", "FOG_EXP", "FOG_EXP2"}}, "docs/KEYWORDS.md §4"));
    table.push_back(plainShortcut("instancing", {{"", kInstancingKeyword}}, "docs/KEYWORDS.md §4"));
    table.push_back(plainShortcut("particles", {{"", "SOFTPARTICLES_ON"}}, "docs/KEYWORDS.md §4"));
    for (Shortcut& shortcut : table) {
        for (ValidityRule& rule : shortcut.rules) rule.origin = shortcut.directive();
    }
    return table;
}

bool isRemoved(const std::string& keyword, const std::vector<const ShortcutOption*>& options) {
    return std::any_of(options.begin(), options.end(), [&](const ShortcutOption* option) {
        const Names& removes = option->removes;
        return std::find(removes.begin(), removes.end(), keyword) != removes.end();
    });
}

}  // namespace

const std::vector<Shortcut>& builtinShortcuts() {
    static const std::vector<Shortcut> table = makeShortcuts();
    return table;
}

const Shortcut* findShortcut(std::string_view name) {
    for (const Shortcut& shortcut : builtinShortcuts()) {
        if (shortcut.name == name) return &shortcut;
    }
    return nullptr;
}

const std::vector<ShortcutOption>& shortcutOptions() {
    static const std::vector<ShortcutOption> options = {
        {"nolightmap", {"LIGHTMAP_ON"}},
        {"nodirlightmap", {"DIRLIGHTMAP_COMBINED"}},
        {"nodynlightmap", {"DYNAMICLIGHTMAP_ON"}},
        {"novertexlight", {"VERTEXLIGHT_ON"}},
        {"novertexlights", {"VERTEXLIGHT_ON"}},
        {"noshadow", {"SHADOWS_SCREEN", "SHADOWS_DEPTH", "SHADOWS_CUBE", "SHADOWS_SOFT"}},
        {"noshadowmask", {"SHADOWS_SHADOWMASK"}},
    };
    return options;
}

const ShortcutOption* findShortcutOption(std::string_view name) {
    for (const ShortcutOption& option : shortcutOptions()) {
        if (option.name == name) return &option;
    }
    return nullptr;
}

ShortcutExpansion expandShortcut(const Shortcut& shortcut,
                                 const std::vector<const ShortcutOption*>& options,
                                 SourceLocation location) {
    ShortcutExpansion expansion;
    for (const Names& set : shortcut.sets) {
        KeywordSetDecl decl;
        decl.directive = shortcut.directive();
        decl.location = location;
        for (const std::string& keyword : set) {
            if (keyword.empty() || !isRemoved(keyword, options)) decl.keywords.push_back(keyword);
        }
        bool varies = std::any_of(decl.keywords.begin(), decl.keywords.end(),
                                  [](const std::string& keyword) { return !keyword.empty(); });
        if (varies) expansion.sets.push_back(std::move(decl));
    }
    expansion.rules = shortcut.rules;
    return expansion;
}

}  // namespace varc::variants
