#pragma once
// Scalar -> colour. Continuous maps are 256-entry tables looked up the way
// matplotlib does (index = floor(t * 256), clamped), so colours match its
// figures; the categorical map cycles a 10-colour palette by integer id.
#include <array>
#include <string>
#include <vector>

#include "render/image.hpp"

namespace render {

namespace detail {
extern const float kViridis[256][3];
}

class ColourMap {
 public:
  // "viridis" (default), "jet", or "categorical" (alias "tab10").
  // Throws InvalidArgument listing the known names.
  static ColourMap by_name(const std::string& name);
  static ColourMap viridis();
  static ColourMap jet();
  static ColourMap categorical();
  static std::vector<std::string> names();

  const std::string& name() const { return name_; }
  bool is_categorical() const { return categorical_; }

  // Continuous maps: value clamped to [lo, hi]. Categorical: value rounded
  // to the nearest integer, palette index = id mod 10 (lo/hi ignored).
  // NaN maps to nan_colour().
  Rgba map(double value, double lo, double hi) const;
  // Position t in [0, 1] (clamped) of a continuous map.
  Rgba at(double t) const;
  Rgba nan_colour() const { return Rgba{128, 128, 128, 255}; }
  // Raw table (256 entries; the categorical map repeats its 10 colours).
  const std::array<Rgba, 256>& table() const { return table_; }

 private:
  ColourMap() = default;
  std::string name_;
  bool categorical_ = false;
  std::array<Rgba, 256> table_{};
};

// Throws InvalidArgument unless lo < hi and both are finite.
void validate_range(double lo, double hi);

}  // namespace render
