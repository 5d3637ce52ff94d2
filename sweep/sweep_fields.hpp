// The random fields of a sweep file (README.md, "landslide sweep"; issue 16):
//   "random_fields": [{"path": "stages.1.set.friction_angle",
//                      "distribution": "truncated-normal", "cov": 0.15,
//                      "lower": 10, "upper": 30, "scale_of_fluctuation": [20, 2]}],
//   "samples": 100, "seed": 2026
// Each member of the axes' product is run `samples` times. In sample s the
// number at each field's path becomes the mean of a random field
// ({"random_field": {...}}, scenarios/README.md "Random fields") whose seed
// is field_seed(seed, s, k): the same for every combination of the axes, so
// axis values are compared on the same soils (common random numbers).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sweep {

struct FieldAxis {
  std::string path;          // to a cohesion or friction_angle number of the base scene
  nlohmann::json parameters;  // distribution, cov, [lower, upper], scale_of_fluctuation
};

struct SweepFields {
  std::vector<FieldAxis> fields;  // empty: a sweep of the axes alone
  int samples = 1;                // 1 when there are no fields
  std::uint64_t seed = 0;
};

// Reads random_fields, samples and seed of the sweep document `doc` (file
// `f`); the paths are checked against `base`. Throws SweepError.
SweepFields read_sweep_fields(const nlohmann::json& doc, const std::string& f,
                              const nlohmann::json& base, const std::string& base_name);

// The seed of field k in sample s: SplitMix64 (Steele, Lea & Flood 2014,
// OOPSLA) of the sweep's seed and (s, k), cut to 53 bits so that JSON tools
// keep it exactly.
std::uint64_t field_seed(std::uint64_t seed, int sample, std::size_t field);

// Replaces each field's number in `scene` with its random field for sample
// `sample`; returns the seeds used, one per field.
std::vector<std::uint64_t> put_fields(nlohmann::json& scene, const SweepFields& f, int sample);

}  // namespace sweep
