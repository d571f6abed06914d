# The browser side of the HTML report. include() this from the top-level CMakeLists.txt.
#
#   crux_replay_bundle  custom target: ${CMAKE_BINARY_DIR}/web/replay.bundle.js, bundled by esbuild
#                       from web/replay/*.js (three.js included, one minified IIFE, licence kept)
#   crux_web_assets     static library (src/reports/web_assets.{hpp,cpp}) embedding the bundle and
#                       web/report.css with .incbin: crux::replay_script(), crux::report_style()
#   CRUX_REPLAY_BUNDLE  the bundle's path; CRUX_REPORT_CSS the stylesheet's path
#
# esbuild comes from build/npm/node_modules, installed from web/package-lock.json by
# scripts/setup_web.sh (called by scripts/setup.sh).
set(CRUX_NPM_DIR "${CMAKE_SOURCE_DIR}/build/npm" CACHE PATH
    "Folder holding node_modules installed by scripts/setup_web.sh")
set(_crux_node_modules "${CRUX_NPM_DIR}/node_modules")
set(_crux_lock "${CMAKE_SOURCE_DIR}/web/package-lock.json")
set(_crux_stamp "${_crux_node_modules}/.crux-package-lock.json")

if(NOT EXISTS "${_crux_node_modules}/esbuild/package.json" OR NOT EXISTS "${_crux_node_modules}/three/package.json")
  message(FATAL_ERROR "${_crux_node_modules} lacks esbuild or three: run scripts/setup.sh")
endif()
# Reconfigure when the lock changes, and refuse packages installed from another lock.
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${_crux_lock}")
file(SHA256 "${_crux_lock}" _crux_lock_hash)
if(EXISTS "${_crux_stamp}")
  file(SHA256 "${_crux_stamp}" _crux_stamp_hash)
else()
  set(_crux_stamp_hash "")
endif()
if(NOT _crux_lock_hash STREQUAL _crux_stamp_hash)
  message(FATAL_ERROR "${_crux_node_modules} was not installed from web/package-lock.json: run scripts/setup.sh")
endif()

# esbuild's bin is its native binary once installed, or a node launcher for it: run it as it is.
set(_crux_esbuild "${_crux_node_modules}/.bin/esbuild")

file(GLOB CRUX_REPLAY_SOURCES CONFIGURE_DEPENDS "${CMAKE_SOURCE_DIR}/web/replay/*.js")
set(CRUX_REPLAY_BUNDLE "${CMAKE_BINARY_DIR}/web/replay.bundle.js")
set(CRUX_REPORT_CSS "${CMAKE_SOURCE_DIR}/web/report.css")

# NODE_PATH lets esbuild resolve "three" from build/npm/node_modules, outside web/'s ancestors.
# Legal comments stay inline: three.js's @license block is kept in the bundle.
add_custom_command(
  OUTPUT "${CRUX_REPLAY_BUNDLE}"
  COMMAND "${CMAKE_COMMAND}" -E make_directory "${CMAKE_BINARY_DIR}/web"
  COMMAND "${CMAKE_COMMAND}" -E env "NODE_PATH=${_crux_node_modules}"
          "${_crux_esbuild}" "${CMAKE_SOURCE_DIR}/web/replay/main.js"
          --bundle --minify --format=iife --target=es2020 --charset=ascii
          --legal-comments=inline --log-level=warning "--outfile=${CRUX_REPLAY_BUNDLE}"
  DEPENDS ${CRUX_REPLAY_SOURCES} "${_crux_lock}" "${_crux_stamp}"
  COMMENT "Bundling the replay viewer (esbuild: web/replay -> web/replay.bundle.js)"
  VERBATIM)
add_custom_target(crux_replay_bundle DEPENDS "${CRUX_REPLAY_BUNDLE}")

set(_crux_web_assets_cpp "${CMAKE_SOURCE_DIR}/src/reports/web_assets.cpp")
add_library(crux_web_assets STATIC "${_crux_web_assets_cpp}")
target_include_directories(crux_web_assets PUBLIC "${CMAKE_SOURCE_DIR}/src")
target_compile_features(crux_web_assets PUBLIC cxx_std_20)
target_compile_definitions(crux_web_assets PRIVATE
  "CRUX_REPLAY_BUNDLE_FILE=\"${CRUX_REPLAY_BUNDLE}\""
  "CRUX_REPORT_CSS_FILE=\"${CRUX_REPORT_CSS}\"")
# .incbin is invisible to the compiler's dependency scan: name the embedded files. A unity
# source would compile it under another name that OBJECT_DEPENDS does not reach, so that an
# edited web/replay/*.js left the old bundle in crux: this one file is compiled alone.
set_target_properties(crux_web_assets PROPERTIES UNITY_BUILD OFF)
set_source_files_properties("${_crux_web_assets_cpp}" PROPERTIES
  OBJECT_DEPENDS "${CRUX_REPLAY_BUNDLE};${CRUX_REPORT_CSS}")
add_dependencies(crux_web_assets crux_replay_bundle)
