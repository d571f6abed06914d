#include "reports/web_assets.hpp"

#include <cstddef>

// The files are pulled in by the assembler (.incbin); their paths come from the build
// (cmake/WebAssets.cmake), which also recompiles this file when either changes.
#if !defined(CRUX_REPLAY_BUNDLE_FILE) || !defined(CRUX_REPORT_CSS_FILE)
#error "CRUX_REPLAY_BUNDLE_FILE and CRUX_REPORT_CSS_FILE must name the files to embed"
#endif

// Each blob is bracketed by a begin and an end symbol, hidden so that position-independent
// code reaches them directly. A NUL follows each (not counted) for debuggers' sake.
asm(".pushsection .rodata\n"
    ".balign 16\n"
    ".globl crux_web_replay_script_begin\n"
    ".hidden crux_web_replay_script_begin\n"
    "crux_web_replay_script_begin:\n"
    ".incbin \"" CRUX_REPLAY_BUNDLE_FILE
    "\"\n"
    ".globl crux_web_replay_script_end\n"
    ".hidden crux_web_replay_script_end\n"
    "crux_web_replay_script_end:\n"
    ".byte 0\n"
    ".balign 16\n"
    ".globl crux_web_report_style_begin\n"
    ".hidden crux_web_report_style_begin\n"
    "crux_web_report_style_begin:\n"
    ".incbin \"" CRUX_REPORT_CSS_FILE
    "\"\n"
    ".globl crux_web_report_style_end\n"
    ".hidden crux_web_report_style_end\n"
    "crux_web_report_style_end:\n"
    ".byte 0\n"
    ".popsection\n");

extern "C" {
__attribute__((visibility("hidden"))) extern const char crux_web_replay_script_begin[];
__attribute__((visibility("hidden"))) extern const char crux_web_replay_script_end[];
__attribute__((visibility("hidden"))) extern const char crux_web_report_style_begin[];
__attribute__((visibility("hidden"))) extern const char crux_web_report_style_end[];
}

namespace crux {

std::string_view replay_script() {
  return {crux_web_replay_script_begin,
          static_cast<std::size_t>(crux_web_replay_script_end - crux_web_replay_script_begin)};
}

std::string_view report_style() {
  return {crux_web_report_style_begin,
          static_cast<std::size_t>(crux_web_report_style_end - crux_web_report_style_begin)};
}

}  // namespace crux
