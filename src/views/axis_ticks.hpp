#pragma once
// Where the ticks of an axis go and how they are labelled, for every view: the plots'
// "nice" ticks (multiples of 1, 2 or 5 times a power of ten) and the wall views' metre
// lines (multiples of a spacing that keeps them apart on the page).

#include <string>
#include <vector>

namespace crux {

// Ticks at multiples of a step of 1, 2 or 5 times a power of ten, the smallest such step
// that covers [min, max] with at most `target` intervals; low and high are the multiples
// of the step just outside [min, max]. An empty range is widened to one around its value.
struct Ticks {
  double low = 0, high = 1, step = 1;
  std::vector<double> values;  // low, low + step, ..., high, each computed as k * step
};
Ticks nice_ticks(double min, double max, int target = 5);

// A tick's label, with the decimals its step needs, the same for every tick of an axis.
// From magnitude (the largest |value| of the axis) 100000 up, values are written in
// thousands (k), millions (M) or billions (G): 200000 with step 200000 and magnitude 1e6
// is "0.2M". Zero is "0", never "-0".
std::string tick_label(double value, double step, double magnitude);

// Metres between the lines of a wall's metre grid drawn at `pixels_per_metre`: 0.5 m,
// doubled while neighbouring lines would be closer than 30 pixels.
double metre_tick_spacing(double pixels_per_metre);

// The multiples of `spacing` in [low, high], each computed as k * spacing.
std::vector<double> metre_ticks(double low, double high, double spacing);

// A metre line's label: one decimal, and "0.0", never "-0.0".
std::string metre_tick_label(double metres);

}  // namespace crux
