// Counts in messages: "1 thread", "2 threads".
#pragma once

#include <string>

namespace app {

inline std::string counted(long long n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}
inline std::string counted(long long n, const std::string& one) { return counted(n, one, one + "s"); }

}  // namespace app
