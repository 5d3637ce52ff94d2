#include "output/amount_text.hpp"

#include <cstdio>

namespace app {

std::string count_text(double n) {
  char text[32];
  std::snprintf(text, sizeof text, n < 1e7 ? "%.0f" : "%.3g", n);
  return text;
}

std::string duration_text(double s) {
  char text[32];
  if (s < 120) std::snprintf(text, sizeof text, "%.0f s", s);
  else if (s < 7200) std::snprintf(text, sizeof text, "%.0f min", s / 60);
  else if (s < 172800) std::snprintf(text, sizeof text, "%.1f h", s / 3600);
  else std::snprintf(text, sizeof text, "%.3g days", s / 86400);
  return text;
}

std::string bytes_text(double b) {
  char text[32];
  const char* units[] = {"B", "kB", "MB", "GB", "TB"};
  int u = 0;
  while (b >= 1000 && u < 4) b /= 1000, ++u;
  std::snprintf(text, sizeof text, u == 0 ? "%.0f %s" : "%.3g %s", b, units[u]);
  return text;
}

}  // namespace app
