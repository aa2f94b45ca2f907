// SPDX-License-Identifier: Apache-2.0
// The HTML page of `varc validate --report`: per scene the GPU frame, reference, difference and
// pixel-class mask with its errors and variants; the property checks with their failing cases;
// per pack the variants drawn and their programs.
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "varc/core/Result.h"
#include "varc/properties/PropertyRunner.h"
#include "varc/reader/Pack.h"

namespace varc::cli {

// One PNG shown for a scene: a caption and the encoded bytes.
struct ReportImage {
    std::string caption;  // "GPU", "reference", ...
    std::string png;      // PNG file bytes
};

// What validate learnt about one scene.
struct ReportScene {
    std::string name;       // the scene file's stem
    std::string path;       // the scene file
    std::string status;     // "pass", "FAIL", "ERROR" or "no reference"
    std::string message;    // the comparison's one-line message, the error, or why no reference
    bool compared = false;  // the error figures below are meaningful
    uint32_t draws = 0;
    float maxErrorLsb = 0.0f, meanSignedErrorLsb = 0.0f, meanAbsErrorLsb = 0.0f;
    double seconds = 0.0;
    std::vector<std::string> variants;  // VariantView::describe() of each draw, in draw order
    std::vector<ReportImage> images;
};

// Collects the scenes of one validate run and writes them as one self-contained page: images
// are embedded as data: URLs, styles and the image check script are inline, nothing is fetched.
// Every string from scenes and packs is HTML-escaped. |packs| must outlive the report.
class ValidationReport {
public:
    ValidationReport(const std::vector<reader::Pack>& packs, std::vector<std::string> packPaths)
        : mPacks(packs), mPackPaths(std::move(packPaths)) {}

    void addScene(ReportScene scene) { mScenes.push_back(std::move(scene)); }

    // The property checks of the run (runValidateProperties), one report per shader: the page
    // gets a "Property checks" section (PropertyReportSection.h) after the scenes.
    void addProperties(std::vector<properties::ShaderReport> reports) {
        for (properties::ShaderReport& report : reports) mProperties.push_back(std::move(report));
    }

    // The page. |compared| holds VariantView::describe() of every variant drawn in a scene that
    // matched (as printValidationCoverage takes it). Each scene's variants link to an anchor in
    // their pack's section, which lists the variants drawn with their keywords and the program
    // index of each stage. Once the page has loaded, a script marks the body with
    // data-images-checked, data-images, data-broken-images and data-broken-links (images that
    // did not decode, in-page links with no anchor) for tests/vulkan/check_report.sh.
    std::string html(const std::set<std::string>& compared) const;

    // Writes html(|compared|) to |path| through a temporary file and a rename. Errors:
    // ErrorCode::IoError naming |path|.
    Status write(const std::string& path, const std::set<std::string>& compared) const;

private:
    const std::vector<reader::Pack>& mPacks;
    std::vector<std::string> mPackPaths;
    std::vector<ReportScene> mScenes;
    std::vector<properties::ShaderReport> mProperties;
};

}  // namespace varc::cli
