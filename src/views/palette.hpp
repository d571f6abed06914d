#pragma once
// The colours of crux's figures, named, in one place, and what the shared ones stand
// for: the limbs, the grid's anchor, the finishing height and the inks of text. Named
// colours come from Okabe and Ito's palette, which colour-blind readers tell apart.

#include <array>
#include <string_view>

#include "body/limb.hpp"

namespace crux {

// Okabe-Ito colours.
inline constexpr const char* kOkabeItoOrange = "#e69f00";
inline constexpr const char* kOkabeItoBlue = "#0072b2";
inline constexpr const char* kOkabeItoBluishGreen = "#009e73";
inline constexpr const char* kOkabeItoVermillion = "#d55e00";
inline constexpr const char* kOkabeItoReddishPurple = "#cc79a7";

// Inks of text and of the marks drawn like text.
inline constexpr const char* kTitleColour = "#111111";
inline constexpr const char* kTextColour = "#333333";  // axis titles, legends, labels
inline constexpr const char* kDarkGrey = "#444444";    // tick labels, reference and finish lines
inline constexpr const char* kSubtitleColour = "#555555";

// Frames, and the light lines behind the data. Each kind of figure has kept its own
// shade, so that the figures' bytes stay as they were.
inline constexpr const char* kPlotFrameColour = "#888888";  // plots, colour bars, Fig. 2b's maps
inline constexpr const char* kViewFrameColour = "#999999";  // the wall and body views
inline constexpr const char* kPlotGridLineColour = "#e6e6e6";
inline constexpr const char* kWallMetreLineColour = "#e8e8e8";
inline constexpr const char* kBodyMetreLineColour = "#ececec";

// The anchor P_i of the moving grid (Fig. 2a), in the wall view and in Fig. 2b alike.
inline constexpr const char* kAnchorColour = "#1a9641";

// How a line is stroked; colours and dashes are literals, so strokes can be constants.
struct Stroke {
  std::string_view colour = kTextColour;
  double width = 1.5;
  std::string_view dash;  // an SVG stroke-dasharray, e.g. "6 4"; empty for a solid line
};

// The static model's contact forces, in the body view and the replay.
inline constexpr const char* kForceColour = "#222222";

// The finishing height, in the wall and body views and their legends.
inline constexpr Stroke kFinishStroke{kDarkGrey, 1.2, "6 4"};

struct LimbStyle {
  const char* code;
  const char* name;
  const char* colour;
};
// In limb order.
inline constexpr std::array<LimbStyle, kLimbCount> kLimbStyles{{
    {"RH", "right hand", kOkabeItoVermillion},
    {"LH", "left hand", kOkabeItoBlue},
    {"RF", "right foot", kOkabeItoOrange},
    {"LF", "left foot", kOkabeItoReddishPurple},
}};

}  // namespace crux
