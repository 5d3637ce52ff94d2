// The granular studies of bench/accuracy (bench/accuracy_granular.cpp).
#pragma once

#include <string>

namespace bench {

// Prints the Bui column's toe against the experiment on both bases, and a
// column of aspect ratio 1 against its finest run, at several cell sizes
// (--full adds 1.25 mm) and Courant numbers, with each run's wall time.
void granular_studies(const std::string& scenarios, bool full);

// The paper's slope with the FLIP update and with APIC (sim/physics/apic.hpp),
// side by side (part of granular_studies).
void transfer_study(const std::string& scenarios, bool full);

}  // namespace bench
