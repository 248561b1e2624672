#pragma once
// REPORT.md's section on compaction (docs/controllers.md): every Bayindir and Soysal experiment's
// model errors with compaction on (the default, the rest of the report) and off, what changed in
// the simulation (member spacing, growth against the model's capture radius, the fraction of LEAVE
// attempts that get out), a paragraph written from those numbers, and the paper's claims whose
// verdict differs between the two.
#include <string>
#include <vector>

#include "reproduce/claims.hpp"
#include "reproduce/compaction_effect.hpp"

namespace swarmagg {

// `claims_off` are check_claims of the same figures with the compaction-off runs in place of
// the Bayindir and Soysal ones (same order as `claims_on`). `off_folder`: where the
// compaction-off runs and plots are, relative to the report.
std::string compaction_section(const std::vector<CompactionEffect>& effects,
                               const std::vector<ClaimCheck>& claims_on,
                               const std::vector<ClaimCheck>& claims_off,
                               const std::string& off_folder);

}  // namespace swarmagg
