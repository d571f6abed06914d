#pragma once
// The browser side of the HTML report, embedded in the binary at build time
// (cmake/WebAssets.cmake): the replay viewer bundled by esbuild from web/replay/*.js
// (three.js included, one minified IIFE) and the report's stylesheet web/report.css.
// Both are ASCII text that contains neither "</script" nor "</style", so they can be
// inlined as they are into <script> and <style> elements.

#include <string_view>

namespace crux {

// replay.bundle.js: reads <script type="application/json" id="crux-replay-data"> and
// builds the 3D replay inside <div id="crux-replay"></div> when the page loads.
std::string_view replay_script();

// web/report.css: styles for the whole report page.
std::string_view report_style();

}  // namespace crux
