#include "miner/samples_run.hpp"

#include <iostream>
#include <map>

#include "cli/cli.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_check.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/dataset/thesis_text.hpp"

namespace rdsf {

namespace {

void describe(const SampleSet& set) {
  std::map<std::string, std::size_t> by_origin;
  std::size_t without_crop = 0, with_colour = 0;
  for (const SampleRecord& r : set.records()) {
    ++by_origin[r.origin];
    without_crop += r.has_crop ? 0 : 1;
    with_colour += r.has_colour ? 1 : 0;
  }
  std::cout << "sample set " << set.dir() << "\n"
            << "  samples " << set.records().size() << ": " << set.count(1) << " person, " << set.count(0)
            << " not\n";
  for (const auto& [origin, count] : by_origin) std::cout << "  origin " << origin << ": " << count << "\n";
  std::cout << "  with colour crop " << with_colour << ", without crop (imported vectors) " << without_crop << "\n"
            << "  feature spec " << set.feature_spec().hash() << " (" << set.feature_spec().canonical() << ")\n"
            << "  camera " << set.manifest().camera.describe() << "\n"
            << "  created " << set.manifest().created << " by " << set.manifest().created_by << "\n"
            << "  manifest hash " << set.manifest_hash() << "\n";
  if (set.retracted_count() > 0) std::cout << "  retracted " << set.retracted_count() << "\n";
  if (set.torn_tail()) std::cout << "  note: the index ends in a row torn by a killed writer (ignored)\n";
}

}  // namespace

int run_samples(const SamplesOptions& o) {
  if (!o.import_file.empty() && !o.export_file.empty()) {
    throw cli::UsageError("give either --import or --export, not both");
  }
  if (o.check || o.repair) {
    if (o.check && o.repair) throw cli::UsageError("give either --check or --repair, not both");
    if (!o.import_file.empty() || !o.export_file.empty()) throw cli::UsageError("--check and --repair go alone");
    if (o.repair) {
      const std::vector<std::string> changes = repair_sample_set(o.set);
      for (const std::string& change : changes) std::cout << o.set << "/" << change << "\n";
      std::cerr << "rdsf-samples: " << o.set << ": " << changes.size() << " changes\n";
      return 0;
    }
    const std::vector<SetProblem> problems = check_sample_set(o.set);
    std::size_t fixable = 0;
    for (const SetProblem& p : problems) {
      std::cout << o.set << "/" << p.where << ": " << p.what << " ["
                << (p.fix.empty() ? "cannot be repaired" : "--repair: " + p.fix) << "]\n";
      fixable += p.fix.empty() ? 0 : 1;
    }
    std::cerr << "rdsf-samples: " << o.set << ": " << problems.size() << " problems, " << fixable
              << " repairable\n";
    return problems.empty() ? 0 : 1;
  }
  if (!o.import_file.empty()) {
    check_thesis_text(o.import_file, FeatureSpec{}.dimension());  // a bad file creates no set
    SampleSetWriter writer =
        SampleSetWriter::open_or_create(o.set, FeatureSpec{}, CameraModel::kinect_v1(), "rdsf-samples --import");
    const ThesisImportResult result = import_thesis_text(o.import_file, writer, /*already_checked=*/true);
    std::cerr << "rdsf-samples: " << o.import_file << ": " << result.lines << " samples, imported " << result.imported
              << ", duplicates skipped " << result.duplicates << "; " << o.set << " holds "
              << writer.records().size() << " samples\n";
    return 0;
  }
  const SampleSet set = SampleSet::open_read(o.set);
  if (!o.export_file.empty()) {
    const std::int64_t lines = export_thesis_text(set, RdsfExtractor(set.feature_spec()), o.export_file, o.force);
    std::cerr << "rdsf-samples: wrote " << lines << " samples to " << o.export_file << "\n";
    return 0;
  }
  describe(set);
  return 0;
}

}  // namespace rdsf
