// SPDX-License-Identifier: Apache-2.0
// The HTML page of `varc validate --report`.
#include "ValidationReport.h"

#include <cstdio>
#include <map>
#include <optional>
#include <sstream>
#include <vector>

#include "PropertyReportSection.h"
#include "ValidationCoverage.h"
#include "varc/core/AtomicFile.h"
#include "varc/core/HtmlText.h"
#include "varc/core/Stage.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"

namespace varc::cli {

namespace {

constexpr const char* kStyle = R"(
body { font: 14px/1.4 sans-serif; margin: 16px; background: #fafafa; color: #222; }
h1 { font-size: 22px; } h2 { font-size: 18px; margin-top: 28px; } h3 { font-size: 15px; }
table { border-collapse: collapse; margin: 8px 0; }
th, td { border: 1px solid #ccc; padding: 2px 8px; text-align: left; vertical-align: top; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
.pass { color: #186a18; font-weight: bold; } .fail { color: #b00000; font-weight: bold; }
.other { color: #8a5a00; font-weight: bold; }
.scene { background: #fff; border: 1px solid #ddd; padding: 8px 12px; margin: 12px 0; }
.images { display: flex; flex-wrap: wrap; gap: 10px; }
figure { margin: 0; max-width: 260px; } figcaption { font-size: 12px; color: #555; }
figcaption code { word-break: break-all; }
figure img { width: 256px; height: auto; image-rendering: pixelated; border: 1px solid #999; }
code, .message { font-family: monospace; font-size: 12px; }
table.properties th, table.properties td { font-size: 12px; padding: 1px 4px; white-space: nowrap; }
.legend span { display: inline-block; width: 10px; height: 10px; border: 1px solid #999; }
)";

// Marks the body once every image has loaded or failed, for the headless-browser test: the
// number of images, the alt text of each that did not decode (naturalWidth 0) and each in-page
// link whose anchor is missing.
constexpr const char* kCheckScript = R"(
window.addEventListener('load', function () {
  var broken = [], links = [];
  for (var i = 0; i < document.images.length; ++i) {
    var image = document.images[i];
    if (!image.complete || image.naturalWidth === 0) broken.push(image.alt || String(i));
  }
  var anchors = document.querySelectorAll('a[href^="#"]');
  for (var j = 0; j < anchors.length; ++j) {
    var target = anchors[j].getAttribute('href').substring(1);
    if (!document.getElementById(target)) links.push(target);
  }
  document.body.setAttribute('data-images', String(document.images.length));
  document.body.setAttribute('data-broken-images', broken.join('|'));
  document.body.setAttribute('data-broken-links', links.join('|'));
  document.body.setAttribute('data-images-checked', 'yes');
});
)";

// A variant some scene drew: where it is and which scenes drew it.
struct DrawnVariant {
    size_t pack = 0;
    std::string anchor;
    std::optional<reader::VariantView> view;
    std::vector<size_t> scenes;  // indices into the report's scenes
};

using VariantIndex = std::map<std::string, DrawnVariant>;  // by VariantView::describe()

// Each pack variant that a scene drew, with an anchor "v<pack>-<n>" (n counts the pack's
// variants shader by shader, pass by pass); the first pack that has it wins.
VariantIndex indexDrawnVariants(const std::vector<reader::Pack>& packs,
                                const std::vector<ReportScene>& scenes) {
    VariantIndex index;
    for (size_t s = 0; s < scenes.size(); ++s) {
        for (const std::string& name : scenes[s].variants) {
            std::vector<size_t>& drawers = index[name].scenes;
            if (drawers.empty() || drawers.back() != s) drawers.push_back(s);
        }
    }
    for (size_t p = 0; p < packs.size(); ++p) {
        size_t n = 0;
        for (size_t s = 0; s < packs[p].shaderCount(); ++s) {
            const reader::ShaderView shader = packs[p].shader(s);
            for (size_t i = 0; i < shader.passCount(); ++i) {
                std::optional<reader::PassView> pass = shader.pass(i);
                for (size_t v = 0; pass && v < pass->variantCount(); ++v, ++n) {
                    auto found = index.find(pass->variant(v).describe());
                    if (found == index.end() || found->second.view) continue;
                    found->second.pack = p;
                    found->second.anchor = "v" + std::to_string(p) + "-" + std::to_string(n);
                    found->second.view = pass->variant(v);
                }
            }
        }
    }
    return index;
}

std::string formatNumber(const char* format, double value) {
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

const char* statusClass(const std::string& status) {
    if (status == "pass") return "pass";
    if (status == "FAIL" || status == "ERROR") return "fail";
    return "other";
}

std::string sceneAnchor(size_t index) { return "scene-" + std::to_string(index); }

void writeSceneTable(std::ostream& out, const std::vector<ReportScene>& scenes) {
    out << "<table><tr><th>scene</th><th>result</th><th>draws</th><th>variants</th>"
           "<th>max LSB</th><th>mean signed LSB</th><th>time</th></tr>\n";
    for (size_t s = 0; s < scenes.size(); ++s) {
        const ReportScene& scene = scenes[s];
        out << "<tr><td><a href=\"#" << sceneAnchor(s) << "\">" << htmlEscape(scene.name)
            << "</a></td><td class=\"" << statusClass(scene.status) << "\">"
            << htmlEscape(scene.status) << "</td><td class=\"num\">" << scene.draws
            << "</td><td class=\"num\">"
            << std::set<std::string>(scene.variants.begin(), scene.variants.end()).size()
            << "</td><td class=\"num\">"
            << (scene.compared ? formatNumber("%.2f", scene.maxErrorLsb) : "-")
            << "</td><td class=\"num\">"
            << (scene.compared ? formatNumber("%.3f", scene.meanSignedErrorLsb) : "-")
            << "</td><td class=\"num\">" << formatNumber("%.2f s", scene.seconds) << "</td></tr>\n";
    }
    out << "</table>\n";
}

void writeCoverageTable(std::ostream& out, const std::vector<PackCoverage>& coverage) {
    out << "<table><tr><th>pack</th><th>variants compared</th><th>by LightMode</th></tr>\n";
    for (size_t p = 0; p < coverage.size(); ++p) {
        out << "<tr><td><a href=\"#pack-" << p << "\">" << htmlEscape(coverage[p].packName)
            << "</a></td><td class=\"num\">" << coverage[p].all.compared << " of "
            << coverage[p].all.total << "</td><td>" << htmlEscape(lightModeSummary(coverage[p]))
            << "</td></tr>\n";
    }
    out << "</table>\n";
}

void writeSummary(std::ostream& out, const std::vector<ReportScene>& scenes,
                  const std::vector<PackCoverage>& coverage) {
    size_t passed = 0, referenced = 0;
    for (const ReportScene& scene : scenes) {
        passed += scene.status == "pass";
        referenced += scene.status != "no reference";
    }
    out << "<h1>varc validate</h1>\n";
    if (!scenes.empty()) {
        out << "<p>" << passed << "/" << referenced << " scenes match the CPU reference";
        if (referenced < scenes.size())
            out << " (" << scenes.size() - referenced << " more rendered with no reference model)";
        out << ".</p>\n";
        writeSceneTable(out, scenes);
    }
    out << "<h2>Variants compared per pack</h2>\n";
    writeCoverageTable(out, coverage);
}

void writeImages(std::ostream& out, const ReportScene& scene) {
    out << "<div class=\"images\">\n";
    for (const ReportImage& image : scene.images) {
        out << "<figure><img alt=\"" << htmlEscape(scene.name + " " + image.caption)
            << "\" src=\"data:image/png;base64," << base64Encode(image.png) << "\"><figcaption>"
            << htmlEscape(image.caption) << "</figcaption></figure>\n";
    }
    out << "</div>\n";
}

void writeScene(std::ostream& out, const ReportScene& scene, size_t index,
                const VariantIndex& variants) {
    out << "<div class=\"scene\" id=\"" << sceneAnchor(index) << "\"><h2>" << htmlEscape(scene.name)
        << " <span class=\"" << statusClass(scene.status) << "\">" << htmlEscape(scene.status)
        << "</span></h2>\n<p><code>" << htmlEscape(scene.path) << "</code>: " << scene.draws
        << " draws";
    if (scene.compared) {
        out << ", max error " << formatNumber("%.2f", scene.maxErrorLsb) << " LSB, mean signed "
            << formatNumber("%.3f", scene.meanSignedErrorLsb) << " LSB, mean abs "
            << formatNumber("%.3f", scene.meanAbsErrorLsb) << " LSB";
    }
    out << "</p>\n<p class=\"message\">" << htmlEscape(scene.message) << "</p>\n";
    writeImages(out, scene);
    out << "<h3>Variants drawn</h3>\n<ul>\n";
    std::set<std::string> listed;
    for (const std::string& name : scene.variants) {
        if (!listed.insert(name).second) continue;
        auto found = variants.find(name);
        if (found != variants.end() && found->second.view) {
            out << "<li><a href=\"#" << found->second.anchor << "\">" << htmlEscape(name)
                << "</a></li>\n";
        } else {
            out << "<li>" << htmlEscape(name) << "</li>\n";
        }
    }
    out << "</ul></div>\n";
}

std::string programsOf(const reader::VariantView& view) {
    std::string text;
    for (Stage stage : kStages) {
        std::optional<reader::ProgramView> program = view.program(stage);
        if (!program) continue;
        if (!text.empty()) text += ", ";
        text += std::string(stageName(stage)) + " #" + std::to_string(program->index());
    }
    return text;
}

void writeVariantRow(std::ostream& out, const std::string& name, const DrawnVariant& drawn,
                     const std::vector<ReportScene>& scenes, bool compared) {
    std::string keywords;
    for (const std::string& keyword : drawn.view->keywords())
        keywords += (keywords.empty() ? "" : " ") + keyword;
    out << "<tr id=\"" << drawn.anchor << "\"><td>" << htmlEscape(name) << "</td><td><code>"
        << htmlEscape(keywords.empty() ? "(none)" : keywords) << "</code></td><td>"
        << htmlEscape(programsOf(*drawn.view)) << "</td><td>" << (compared ? "yes" : "no")
        << "</td><td>";
    for (size_t s : drawn.scenes) {
        out << "<a href=\"#" << sceneAnchor(s) << "\">" << htmlEscape(scenes[s].name) << "</a> ";
    }
    out << "</td></tr>\n";
}

void writePack(std::ostream& out, size_t pack, const PackCoverage& coverage,
               const VariantIndex& variants, const std::vector<ReportScene>& scenes,
               const std::set<std::string>& compared) {
    out << "<h2 id=\"pack-" << pack << "\">" << htmlEscape(coverage.packName) << "</h2>\n<p>"
        << coverage.all.compared << " of " << coverage.all.total
        << " variants compared with the reference (" << htmlEscape(lightModeSummary(coverage))
        << ").</p>\n<table><tr><th>variant drawn</th><th>keywords</th><th>programs</th>"
           "<th>compared</th><th>scenes</th></tr>\n";
    for (const auto& [name, drawn] : variants) {
        if (drawn.view && drawn.pack == pack)
            writeVariantRow(out, name, drawn, scenes, compared.count(name) > 0);
    }
    out << "</table>\n<details><summary>" << coverage.uncovered.size()
        << " variants not compared</summary><ul>\n";
    for (const std::string& name : coverage.uncovered)
        out << "<li>" << htmlEscape(name) << "</li>\n";
    out << "</ul></details>\n";
}

// The key to the difference and mask images of the scenes.
void writeLegend(std::ostream& out) {
    out << "<p class=\"legend\">Difference: grey = reference luminance / 4, red = too bright, "
           "blue = too dark (32 levels per LSB), failing pixels saturated with full green. Mask: "
           "<span style=\"background:#202020\"></span> background "
           "<span style=\"background:#808080\"></span> interior "
           "<span style=\"background:#f0c828\"></span> edge "
           "<span style=\"background:#28bef0\"></span> shadow interval "
           "<span style=\"background:#ff0000\"></span> mismatch.</p>\n";
}

}  // namespace

std::string ValidationReport::html(const std::set<std::string>& compared) const {
    const std::vector<PackCoverage> coverage =
        computeValidationCoverage(mPacks, mPackPaths, compared);
    const VariantIndex variants = indexDrawnVariants(mPacks, mScenes);
    std::ostringstream out;
    out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
           "<title>varc validate report</title>\n<style>"
        << kStyle << "</style>\n<script>" << kCheckScript << "</script>\n</head><body>\n";
    writeSummary(out, mScenes, coverage);
    if (!mScenes.empty()) writeLegend(out);
    for (size_t s = 0; s < mScenes.size(); ++s) writeScene(out, mScenes[s], s, variants);
    writePropertySection(out, mProperties);
    for (size_t p = 0; p < coverage.size(); ++p)
        writePack(out, p, coverage[p], variants, mScenes, compared);
    out << "</body></html>\n";
    return out.str();
}

Status ValidationReport::write(const std::string& path,
                               const std::set<std::string>& compared) const {
    return writeFileAtomically(path, html(compared));
}

}  // namespace varc::cli
