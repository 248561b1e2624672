#pragma once
// `swarmagg merge DIR... --out DIR`: combines the output folders of a sweep's shards (or of
// one unsharded sweep) into tidy files, each written atomically:
//   sweep_timeseries.csv   the parameter columns, then the timeseries.csv columns, with
//                          `replicate` the sweep's replicate index;
//   sweep_partitions.csv   the same for partitions.csv (Soysal worlds only);
//   sweep_summary.csv      final-value statistics per point and observable (sweep_summary.hpp);
//   sweep.json             the sweep's manifest.
// Rows follow the run index (points in grid order, then replicates), never the shard that
// ran them, so the result is byte-identical however the sweep was divided. Every run must
// be complete in one of the folders; the folders must hold the same sweep.
#include <filesystem>
#include <vector>

namespace swarmagg {

struct MergeReport {
  int points = 0;
  int runs = 0;
  std::vector<std::filesystem::path> files;
  // The earlier merge's files this one outdated: its plots (of another summary) and
  // partitions (when this merge has none).
  std::vector<std::filesystem::path> removed;
  bool plots_removed = false;  // among them, sweep plots
};

// Unless `force` (merge --force), `out` must hold no run (world.resolved.yaml) and no other
// sweep's manifest: their files would be mixed with this merge's. Other files may stay (the
// shards' folders, a cluster's logs). The sweep plots of an earlier merge in `out` whose
// summary differs from this one's are removed: `swarmagg plot` draws them anew.
MergeReport merge_sweep(const std::vector<std::filesystem::path>& folders,
                        const std::filesystem::path& out, bool force = false);

}  // namespace swarmagg
