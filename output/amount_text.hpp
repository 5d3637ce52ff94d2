// Amounts in messages, as the estimate prints them: counts, durations and
// sizes. Here rather than in app/ because a sweep (sweep/, below app/) prints
// its own estimate in the same words as a run's.
#pragma once

#include <string>

namespace app {

// "17496" below ten million, "2.91e+07" from there.
std::string count_text(double n);
// "30 s" below 2 min, "12 min" below 2 h, "3.5 h" below 2 days, then "4.2 days".
std::string duration_text(double seconds);
// "45.2 MB": decimal units, three digits.
std::string bytes_text(double bytes);

}  // namespace app
