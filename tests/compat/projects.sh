#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The corpus projects (issue #28): every Unity project folder in ../shared/compat/projects (read in
# place; its shaders come from ../shared/compat/<folder> and .../surface/<folder>) through
# `varc variants --json --project` and `varc build --project`. The figures are the section
# "## The corpus projects" of docs/PROJECTS.md, which this test writes (--update) and checks.
# It fails when:
#   * varc crashes or hangs on a project (exit status other than 0 or 1, or the time limit),
#   * a project's build (with --skip-failing-shaders, as a Unity player build leaves a failing
#     shader out) leaves out or fails in a shader that docs/COMPATIBILITY.md does not list as
#     refused (a shader that builds alone must build in its project), or
#   * the section is no longer true.
# Usage: projects.sh VARC COMPAT_DIR PROJECTS_DOC COMPAT_DOC WORK_DIR [--update]
set -u
varc=$1 compat=$2 doc=$3 compatDoc=$4 work=$5 update=${6:-}
rm -rf "$work" && mkdir -p "$work"
status=0
results="$work/results.jsonl"
: >"$results"

for folder in "$compat"/projects/*/; do
    name=$(basename "$folder")
    roots=()
    for root in "$compat/$name" "$compat/surface/$name"; do
        [ -d "$root" ] && roots+=(--project-shaders "$root")
    done
    timeout 300 "$varc" variants --json --project "$folder" "${roots[@]}" \
        >"$work/$name.json" 2>"$work/$name.variants.err"
    vstatus=$?
    timeout 1200 "$varc" build -j 2 --skip-failing-shaders --project "$folder" "${roots[@]}" \
        -o "$work/$name.svpack" \
        >"$work/$name.build.out" 2>"$work/$name.build.err"
    bstatus=$?
    if [ "$vstatus" -gt 1 ] || [ "$bstatus" -gt 1 ]; then
        echo "FAIL: $name: varc exited with $vstatus (variants) / $bstatus (build): crash or hang"
        tail -5 "$work/$name.build.err"
        status=1
    fi
    python3 - "$name" "$vstatus" "$bstatus" "$work" "$compat" >>"$results" <<'PY'
import json, re, sys
name, vstatus, bstatus, work, compat = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4], sys.argv[5]
row = {"name": name, "variants_status": vstatus, "build_status": bstatus}
if vstatus == 0:
    data = json.load(open(f"{work}/{name}.json"))
    row["project"] = data["project"]
    stages = {"declared": 0, "materials": 0, "settings": 0, "rules": 0}
    passes = 0
    for shader in data["shaders"]:
        for p in shader["passes"]:
            passes += 1
            for key in stages:
                stages[key] += p["stages"][key]
    row.update(passes=passes, stages=stages)
def relative(path):
    return path[len(compat) + 1:] if path.startswith(compat + "/") else path
if bstatus == 0:
    m = re.search(r"^Built (\d+) variants", open(f"{work}/{name}.build.out").read(), re.M)
    row["built"] = int(m.group(1)) if m else None
    m = re.search(r"shaders? left out of the pack \([^)]*\): (.*)$",
                  open(f"{work}/{name}.build.err").read(), re.M)
    row["left_out"] = sorted(relative(f) for f in m.group(1).split(", ")) if m else []
else:
    # The shader files the first errors are in, relative to the corpus folder.
    files = []
    for line in open(f"{work}/{name}.build.err"):
        m = re.match(r"^(\S+?):\d+(?::\d+)?: error: ", line)
        if m and m.group(1).startswith(compat + "/"):
            files.append(m.group(1)[len(compat) + 1:])
    row["errors_in"] = sorted(set(files))
print(json.dumps(row))
PY
done

python3 - "$results" "$compatDoc" "$work/section.md" <<'PY' || status=1
import json, re, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
compat_doc = open(sys.argv[2]).read()
# Refused corpus files, and the reasons COMPATIBILITY.md gives (which name the include file an
# error is in, e.g. "refused: Toon_VertFrag.cginc:44: ...").
refused_rows = re.findall(r"^\| `([^`]*)` \|[^\n]*\| refused: ([^\n]*)\|$", compat_doc, re.M)
refused = {path for path, _ in refused_rows}
reasons = " ".join(reason for _, reason in refused_rows)
def explained(f):
    return f in refused or (f.split("/")[-1] + ":") in reasons
ok = True
out = []
out.append("## The corpus projects\n")
out.append("Written by the test `compat.projects` (tests/compat/projects.sh) and checked by it; after an")
out.append("intended change: `bash tests/compat/projects.sh build/varc ../shared/compat docs/PROJECTS.md")
out.append("docs/COMPATIBILITY.md build/projects --update`. Each project folder of")
out.append("`../shared/compat/projects/` with `--project-shaders` naming its shaders in `../shared/compat/`;")
out.append("counts are summed over the passes of the shaders in the build.\n")
out.append("| project | shaders (in build) | materials | passes | declared | after materials | after settings | after rules | build |")
out.append("|---|---:|---:|---:|---:|---:|---:|---:|---|")
for row in rows:
    if row["variants_status"] != 0:
        out.append(f"| `{row['name']}` | | | | | | | | varc variants failed |")
        continue
    p, s = row["project"], row["stages"]
    if row["build_status"] == 0:
        build = f"built {row['built']} variants"
        unexplained = [f for f in row["left_out"] if not explained(f)]
        if unexplained:
            print(f"FAIL: {row['name']}: the build left out shaders COMPATIBILITY.md does not "
                  f"list as refused: {unexplained}")
            ok = False
        if row["left_out"]:
            build += "; left out " + ", ".join(f"`{f.split('/')[-1]}`" for f in row["left_out"])
            build += " (refused alone too)"
    else:
        files = row.get("errors_in", [])
        unexplained = [f for f in files if not explained(f)]
        if not files or unexplained:
            print(f"FAIL: {row['name']}: the build failed in shaders COMPATIBILITY.md does not list "
                  f"as refused: {unexplained or 'no shader named'}")
            ok = False
        build = "refused: " + ", ".join(f"`{f.split('/')[-1]}`" for f in files) + " (refused alone too)"
    out.append(f"| `{row['name']}` | {p['shaders']} ({p['in_build']}) | {p['materials']} | {row['passes']} "
               f"| {s['declared']} | {s['materials']} | {s['settings']} | {s['rules']} | {build} |")
open(sys.argv[3], "w").write("\n".join(out) + "\n")
sys.exit(0 if ok else 1)
PY

heading='^## The corpus projects'
docHead() { awk -v h="$heading" '$0 ~ h { exit } { print }' "$doc"; }
docTail() { awk -v h="$heading" '$0 ~ h { keep = 1 } keep' "$doc"; }
if [ "$update" = --update ]; then
    { docHead; cat "$work/section.md"; } >"$work/doc.md"
    cp "$work/doc.md" "$doc"
    echo "projects: $doc updated"
    exit $status
fi
if ! diff -u <(docTail) "$work/section.md"; then
    echo "FAIL: the section \"The corpus projects\" of $doc is not true any more (above);"
    echo "rerun with --update after an intended change"
    status=1
fi
echo "projects: $(wc -l <"$results") projects checked"
exit $status
