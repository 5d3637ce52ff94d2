#pragma once
// "Nice" axis ticks: steps of 1, 2 or 5 x 10^k.
#include <string>
#include <vector>

namespace render {

class Font;

struct Ticks {
  double step = 1;
  int decimals = 0;  // digits after the point that show the step exactly
  std::vector<double> values;
  std::vector<std::string> labels;
};

// Smallest 1/2/5 x 10^k step giving at most max_ticks intervals over span.
double nice_step(double span, int max_ticks);
// Multiples of the nice step inside [lo, hi] (ends included when they fall
// on a multiple). Throws InvalidArgument unless lo < hi, both finite.
Ticks nice_ticks(double lo, double hi, int max_ticks);
// Pixel column/row of a 1 px tick at edge position p of a box spanning
// [lo, hi): ticks at the box's ends go onto its frame lines (lo - 1 and hi),
// so 0 and the frame coincide.
int tick_pixel(double p, int lo, int hi);
// Width in px of the widest of t's labels at font size px.
int widest_label(Font& font, const Ticks& t, int px);
// Fixed-point label; never prints "-0".
std::string format_tick(double v, int decimals);

}  // namespace render
