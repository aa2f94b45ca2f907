#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Writes the lightmap validation scenes (docs/SCENES.md "Lightmaps"): each of Unity's four mixed
# lighting modes, with and without the main light's shadows (SHADOWS_SCREEN) and vertex lights
# (VERTEXLIGHT_ON), over a grid of objects holding every lightmap combination (baked, realtime,
# directional) with and without light probes, so that together the scenes select every
# multi_compile_fwdbase variant of the shaders drawn.
#   tests/scenes/seeds/lightmaps-*.json:   seed 001 (GLSL) and seed 004 (BetterDiffuse), as written
#   tests/scenes/forward/lightmaps-*.json: varc/SimpleDiffuse and varc/GlslVertexLights (which
#                                          skip the lightmap keywords): their base variants
#                                          without LIGHTPROBE_SH, in two scenes
# Usage: scripts/lightmap-scenes.py (from the repository root); rewrites those files.
import json
import os

MODES = ["baked_indirect", "subtractive", "shadowmask", "distance_shadowmask"]
# (baked, directional, realtime): every combination a ForwardBase pass tells apart.
LIGHTMAPS = [(True, False, False), (True, True, False), (True, False, True), (True, True, True),
             (False, False, True), (False, True, True), (False, False, False)]


def lightmap(baked, directional, realtime, index):
    if not baked and not realtime:
        return None
    out = {}
    if baked:
        out["baked"] = [0.2 + 0.1 * (index % 3), 0.25, 0.3]
        out["scale_offset"] = [0.5, 0.5, 0.25 * (index % 2), 0.5]
    if realtime:
        out["realtime"] = [0.1, 0.15, 0.3]
        out["realtime_scale_offset"] = [1, 1, 0, 0]
    if directional:
        out["directional"] = [0.3, 1, -0.2, 0.9]
    out["shadowmask"] = [1, 0.5, 0, 0]
    return out


def grid_objects(shaders):
    """shaders: list of (shader, reference, colour); two rows (probes on, off) per shader."""
    objects = []
    rows = 2 * len(shaders)
    for s, (shader, reference, colour) in enumerate(shaders):
        for probes in (True, False):
            row = 2 * s + (0 if probes else 1)
            for column, (baked, directional, realtime) in enumerate(LIGHTMAPS):
                obj = {
                    "name": f"{reference}-{column}-{'sh' if probes else 'nosh'}",
                    "mesh": "sphere",
                    "position": [1.1 * (column - 3), 1.1 * ((rows - 1) / 2 - row), 0],
                    "material": {"shader": shader, "reference": reference,
                                 "properties": {"_Color": colour}},
                }
                lm = lightmap(baked, directional, realtime, column)
                if lm:
                    obj["lightmap"] = lm
                if probes != (lm is None):  # only where it differs from the default
                    obj["light_probes"] = probes
                objects.append(obj)
    return objects


def scene(shaders, mode, shadows, vertex_lights):
    rows = 2 * len(shaders)
    lights = [{"type": "directional", "color": [1, 0.96, 0.9], "intensity": 0.9,
               "rotation": [40, -25, 0], "shadows": "hard" if shadows else "none"},
              # Not important: into the SH, so LIGHTPROBE_SH (ShadeSH9) and the flat ambient differ.
              {"type": "directional", "color": [1, 0.5, 0.3], "intensity": 0.7,
               "rotation": [-30, 70, 0], "render_mode": "not_important"}]
    if vertex_lights:
        lights.append({"type": "point", "color": [0.3, 0.6, 1], "intensity": 1.5,
                       "position": [0.5, 1.5, -3], "range": 40, "render_mode": "not_important"})
    return {
        "camera": {"position": [0, 0, -10], "target": [0, 0, 0], "fov_y": 8 + 6.5 * rows,
                   "near": 1, "far": 30, "width": 224, "height": 32 * rows + 32,
                   "background": [0.05, 0.07, 0.1]},
        "ambient": {"color": [0.08, 0.07, 0.1]},
        "lighting": {"mixed_mode": mode},
        "quality": {"shadow_distance": 20},
        "objects": grid_objects(shaders),
        "lights": lights,
    }


def write(folder, shaders, configs):
    for mode, shadows, vertex_lights in configs:
        name = (f"lightmaps-{mode.replace('_', '-')}-{'shadow' if shadows else 'noshadow'}"
                f"-{'vertex' if vertex_lights else 'novertex'}.json")
        with open(os.path.join(folder, name), "w") as out:
            json.dump(scene(shaders, mode, shadows, vertex_lights), out, indent=1)
            out.write("\n")


write("tests/scenes/seeds", [
    ("GLSL per-pixel lighting with vertex lights", "seed001", [0.9, 0.5, 0.4, 1]),
    ("BetterDiffuse", "seed004", [0.4, 0.7, 0.9, 1]),
], [(mode, shadows, vertex) for mode in MODES for shadows in (False, True)
    for vertex in (False, True)])
write("tests/scenes/forward", [
    ("varc/SimpleDiffuse", "varc-simple-diffuse", [0.8, 0.6, 0.4, 1]),
    ("varc/GlslVertexLights", "varc-glsl-vertex-lights", [0.5, 0.8, 0.5, 1]),
], [("shadowmask", True, True), ("baked_indirect", False, True)])
