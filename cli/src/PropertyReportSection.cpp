// SPDX-License-Identifier: Apache-2.0
// The "Property checks" section of the validate report: verdicts per shader, failing cases.
#include "PropertyReportSection.h"

#include <filesystem>
#include <ostream>
#include <string>

#include "varc/core/FileRead.h"
#include "varc/core/HtmlText.h"

namespace varc::cli {

namespace {

// A PNG is at most a few hundred KB here (64 x 64 renders); more is not an image the run wrote.
constexpr size_t kMaxImageBytes = size_t{16} << 20;

std::string failureAnchor(size_t shader, size_t relation) {
    return "prop-" + std::to_string(shader) + "-" + std::to_string(relation);
}

const char* verdictClass(properties::Verdict verdict) {
    switch (verdict) {
        case properties::Verdict::Pass:
            return "pass";
        case properties::Verdict::Fail:
            return "fail";
        case properties::Verdict::NotApplicable:
            break;
    }
    return "other";
}

void writeVerdictCell(std::ostream& out, const properties::RelationOutcome& outcome, size_t shader,
                      size_t relation) {
    out << "<td class=\"" << verdictClass(outcome.verdict) << "\"";
    if (!outcome.detail.empty())
        out << " title=\"" << htmlEscape(outcome.detail) << "\"";
    else if (outcome.verdict == properties::Verdict::NotApplicable)
        out << " title=\"the shader takes none of the lights this relation needs\"";
    out << ">";
    const char* name = properties::verdictName(outcome.verdict);
    if (outcome.verdict == properties::Verdict::Fail)
        out << "<a href=\"#" << failureAnchor(shader, relation) << "\">" << name << "</a>";
    else
        out << name;
    out << "</td>";
}

void writeTable(std::ostream& out, const std::vector<properties::ShaderReport>& reports) {
    out << "<table class=\"properties\"><tr><th>shader</th><th>model</th>";
    for (const std::string& name : properties::relationNames())
        out << "<th>" << htmlEscape(name) << "</th>";
    out << "<th>lit variants drawn</th><th>renders</th></tr>\n";
    for (size_t s = 0; s < reports.size(); ++s) {
        const properties::ShaderReport& report = reports[s];
        const bool passed = report.passed();
        out << "<tr data-shader=\"" << htmlEscape(report.shader) << "\" data-result=\""
            << (passed ? "pass" : "FAIL")
            << "\"><td title=\"lights drawn: " << htmlEscape(report.lights) << "\">"
            << htmlEscape(report.shader);
        if (!report.error.empty())
            out << " <span class=\"fail\">ERROR</span> " << htmlEscape(report.error);
        out << "</td><td";
        if (!report.modelReason.empty())
            out << " title=\"" << htmlEscape(report.modelReason) << "\"";
        out << ">" << properties::modelName(report.model) << "</td>";
        for (size_t r = 0; r < report.relations.size(); ++r)
            writeVerdictCell(out, report.relations[r], s, r);
        out << "<td class=\"num\">" << report.litVariantsDrawn() << "/" << report.litVariants
            << "</td><td class=\"num\">" << report.renders << "</td></tr>\n";
    }
    out << "</table>\n";
}

const char* imageCaption(size_t index) {
    static const char* const kCaptions[] = {"actual", "expected", "diff"};
    return index < 3 ? kCaptions[index] : "image";
}

void writeCaseImages(std::ostream& out, const std::string& alt,
                     const properties::FailedCase& failed) {
    if (failed.images.empty()) {
        out << "<p class=\"message\">images not written (see the run's output)</p>\n";
        return;
    }
    out << "<div class=\"images\">\n";
    for (size_t i = 0; i < failed.images.size(); ++i) {
        const std::string& path = failed.images[i];
        Result<std::string> png = readFile(path, kMaxImageBytes);
        if (!png) {
            out << "<p class=\"message\">" << htmlEscape(png.error().detail) << "</p>\n";
            continue;
        }
        out << "<figure><img alt=\"" << htmlEscape(alt + " " + imageCaption(i))
            << "\" src=\"data:image/png;base64," << base64Encode(*png) << "\"><figcaption>"
            << imageCaption(i) << ": <code>"
            << htmlEscape(std::filesystem::path(path).filename().string())
            << "</code></figcaption></figure>\n";
    }
    out << "</div>\n";
}

void writeFailure(std::ostream& out, const properties::ShaderReport& report,
                  const properties::RelationOutcome& outcome, const std::string& anchor) {
    out << "<div class=\"scene\" id=\"" << anchor << "\" data-shader=\""
        << htmlEscape(report.shader) << "\" data-relation=\"" << htmlEscape(outcome.relation)
        << "\"><h3>" << htmlEscape(report.shader) << ": " << htmlEscape(outcome.relation)
        << " <span class=\"fail\">FAIL</span></h3>\n";
    if (outcome.cases.empty())
        out << "<p class=\"message\">" << htmlEscape(outcome.detail) << "</p>\n";
    for (const properties::FailedCase& failed : outcome.cases) {
        out << "<p>case <code>" << htmlEscape(failed.label) << "</code>: <span class=\"message\">"
            << htmlEscape(failed.finding) << "</span></p>\n<p>variants drawn:";
        for (const std::string& variant : failed.variants)
            out << " <code>" << htmlEscape(variant) << "</code>";
        out << "</p>\n";
        writeCaseImages(out, report.shader + " " + outcome.relation + " " + failed.label, failed);
    }
    out << "</div>\n";
}

}  // namespace

void writePropertySection(std::ostream& out, const std::vector<properties::ShaderReport>& reports) {
    if (reports.empty()) return;
    size_t passed = 0;
    for (const properties::ShaderReport& report : reports) passed += report.passed();
    out << "<h2 id=\"property-checks\">Property checks</h2>\n<p>" << passed << "/" << reports.size()
        << " lit shaders hold every relation (docs/PROPERTIES.md). n/a: the shader takes no "
           "light the relation needs, or its model excludes it (hover for the reason).</p>\n";
    writeTable(out, reports);
    for (size_t s = 0; s < reports.size(); ++s) {
        for (size_t r = 0; r < reports[s].relations.size(); ++r) {
            const properties::RelationOutcome& outcome = reports[s].relations[r];
            if (outcome.verdict == properties::Verdict::Fail)
                writeFailure(out, reports[s], outcome, failureAnchor(s, r));
        }
    }
}

}  // namespace varc::cli
