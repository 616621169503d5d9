#include "rdsf/dataset/sample_set_merge.hpp"

#include <fstream>
#include <iterator>

#include "rdsf/core/error.hpp"
#include "rdsf/dataset/feature_vector_file.hpp"
#include "rdsf/dataset/sample_set.hpp"

namespace rdsf {

namespace {

std::vector<unsigned char> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot be opened (crop missing from its sample set?)");
  return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

MergeResult merge_sample_sets(const std::vector<std::string>& input_dirs, SampleSetWriter& out,
                              const std::function<bool(const SampleRecord&)>& keep) {
  const FeatureSpec& spec = out.manifest().feature_spec;
  std::vector<SampleSet> inputs;
  for (const std::string& dir : input_dirs) {
    SampleSet set = SampleSet::open_read(dir);
    if (set.feature_spec() != spec) {
      fail(dir, "feature spec " + set.feature_spec().hash() + " (" + set.feature_spec().canonical() +
                    ") differs from the output's " + spec.hash() + " (" + spec.canonical() + "); not merged");
    }
    const std::string crops_differ =
        crop_provenance_mismatch(set.manifest().crops, "its crops", out.manifest().crops, "the output's");
    if (!crops_differ.empty()) fail(dir, "crops were cut differently: " + crops_differ + "; not merged");
    const RecordedParameters& options = set.manifest().analyser_options;
    if (!options.empty() && !out.manifest().analyser_options.empty() && options != out.manifest().analyser_options) {
      fail(dir, "its candidates were found with other analyser options than the output's; not merged");
    }
    inputs.push_back(std::move(set));
  }
  MergeResult result;
  result.inputs = static_cast<std::int64_t>(inputs.size());
  const cv::Size window(spec.window_width_px, spec.window_height_px);
  std::vector<float> vector(static_cast<std::size_t>(spec.dimension()));
  for (const SampleSet& set : inputs) {
    std::unique_ptr<FeatureVectorFile> vectors;
    for (std::size_t i = 0; i < set.records().size(); ++i) {
      const SampleRecord& record = set.records()[i];
      if (keep && !keep(record)) continue;
      if (out.is_duplicate(record)) {
        ++result.duplicates;
        continue;
      }
      if (record.has_crop) {
        EncodedCrop crop;
        crop.depth_png = read_bytes(set.depth_crop_path(i));
        if (record.has_colour) crop.colour_png = read_bytes(set.colour_crop_path(i));
        crop.hash = record.crop_hash;
        crop.size = window;
        out.append_encoded(record, crop);
      } else {
        if (!vectors) {
          vectors = std::make_unique<FeatureVectorFile>(FeatureVectorFile::path_in(set.dir(), spec.hash()),
                                                        spec.dimension());
        }
        vectors->read(record.id, vector.data());
        out.append_vector(record, vector.data());
      }
      ++result.added;
    }
  }
  return result;
}

}  // namespace rdsf
