#include "rdsf/dataset/sample_set.hpp"

#include <algorithm>
#include <filesystem>
#include <memory>

#include "rdsf/core/error.hpp"
#include "rdsf/core/ordered_pool.hpp"
#include "rdsf/core/stable_hash.hpp"
#include "rdsf/core/yaml_guard.hpp"
#include "rdsf/dataset/feature_vector_file.hpp"
#include "rdsf/dataset/retraction_log.hpp"
#include "rdsf/dataset/sample_crop.hpp"
#include "rdsf/dataset/sample_tsv.hpp"
#include "rdsf/frame/depth_png.hpp"

namespace rdsf {

namespace fs = std::filesystem;

SampleSet SampleSet::open_read(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) fail(dir, "is not a sample set folder (it does not exist)");
  SampleSet set;
  set.dir_ = dir;
  std::string text;
  set.manifest_ = SampleSetManifest::read((fs::path(dir) / "manifest.yml").string(), &text);
  set.manifest_hash_ = to_hex16(fnv1a64(text));
  SampleTsvContents contents = read_sample_tsv((fs::path(dir) / "samples.tsv").string());
  set.torn_tail_ = contents.torn_tail;
  const RetractionLog retracted = read_retraction_log((fs::path(dir) / "retracted.tsv").string());
  for (SampleRecord& record : contents.records) {
    if (retracted.ids.count(record.id) != 0) {
      ++set.retracted_;
    } else {
      set.records_.push_back(std::move(record));
    }
  }
  return set;
}

std::size_t SampleSet::count(int label) const {
  return static_cast<std::size_t>(
      std::count_if(records_.begin(), records_.end(), [label](const SampleRecord& r) { return r.label == label; }));
}

std::string SampleSet::depth_crop_path(std::size_t index) const {
  return (fs::path(dir_) / (crop_stem(records_.at(index).id) + ".depth.png")).string();
}

std::string SampleSet::colour_crop_path(std::size_t index) const {
  return (fs::path(dir_) / (crop_stem(records_.at(index).id) + ".rgb.png")).string();
}

cv::Mat1w SampleSet::depth_crop(std::size_t index) const {
  const SampleRecord& record = records_.at(index);
  if (!record.has_crop) {
    fail(dir_, "sample " + std::to_string(record.id) + " has no crop (imported as a feature vector)");
  }
  const std::string path = depth_crop_path(index);
  const std::string sample = "sample " + std::to_string(record.id) + ": ";
  cv::Mat1w crop;
  try {
    crop = read_depth_png(path);
  } catch (const Error& e) {  // "<path>: <problem>" -> "<path>: sample N: <problem>"
    const std::string what = e.what();
    // one_line: the PNG reader quotes chunk names, which may hold any byte (found by fuzz/fuzz_depth_crop).
    fail(path, sample + one_line(what.rfind(path + ": ", 0) == 0 ? what.substr(path.size() + 2) : what) +
                   " (rdsf-samples --check lists every problem)");
  }
  const FeatureSpec& spec = manifest_.feature_spec;
  if (crop.cols != spec.window_width_px || crop.rows != spec.window_height_px) {
    fail(path, sample + "crop is " + std::to_string(crop.cols) + "x" + std::to_string(crop.rows) +
                   ", the set's window is " + std::to_string(spec.window_width_px) + "x" +
                   std::to_string(spec.window_height_px));
  }
  if (!record.crop_hash.empty() && depth_crop_hash(crop) != record.crop_hash) {
    fail(path, sample + "crop does not match its hash " + record.crop_hash +
                   " in samples.tsv (replaced by another image?)");
  }
  return crop;
}

cv::Mat3b SampleSet::colour_crop(std::size_t index) const {
  const SampleRecord& record = records_.at(index);
  if (!record.has_colour) return {};
  const FeatureSpec& spec = manifest_.feature_spec;
  return read_colour_png(colour_crop_path(index), cv::Size(spec.window_width_px, spec.window_height_px));
}

cv::Mat1f SampleSet::features(const RdsfExtractor& extractor, const std::vector<std::size_t>& indices,
                              int threads) const {
  return rows_of(extractor.spec(), extractor.dimension(),
                 [&extractor](const cv::Mat1w& crop, float* out) { extractor.compute(crop, out); }, nullptr, indices,
                 threads);
}

cv::Mat1f SampleSet::features(const FeatureSubset& subset, const std::vector<std::size_t>& indices,
                              int threads) const {
  return rows_of(subset.spec(), subset.size(),
                 [&subset](const cv::Mat1w& crop, float* out) { subset.compute(crop, out); }, &subset.features(),
                 indices, threads);
}

cv::Mat1f SampleSet::rows_of(const FeatureSpec& spec, int columns,
                             const std::function<void(const cv::Mat1w&, float*)>& from_crop,
                             const std::vector<int>* pick, const std::vector<std::size_t>& indices,
                             int threads) const {
  std::vector<std::size_t> chosen = indices;
  if (chosen.empty()) {
    chosen.resize(records_.size());
    for (std::size_t i = 0; i < chosen.size(); ++i) chosen[i] = i;
  }
  for (std::size_t index : chosen) {
    if (index >= records_.size()) {
      fail(dir_, "record index " + std::to_string(index) + " is out of range (" + std::to_string(records_.size()) +
                     " samples)");
    }
  }
  const int dimension = spec.dimension();
  cv::Mat1f rows(static_cast<int>(chosen.size()), columns);
  if (chosen.empty()) return rows;

  // Stored vectors of samples without crop, only for the spec they were written with.
  std::unique_ptr<FeatureVectorFile> vectors;
  const bool any_without_crop =
      std::any_of(chosen.begin(), chosen.end(), [this](std::size_t i) { return !records_[i].has_crop; });
  if (any_without_crop) {
    vectors = std::make_unique<FeatureVectorFile>(FeatureVectorFile::path_in(dir_, spec.hash()),
                                                  dimension);
  }

  // Uneven work (a crop to decode, or a stored vector to read): chunks of 64 taken as workers come free.
  parallel_for_chunks(chosen.size(), 64, threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t index = chosen[k];
      const SampleRecord& record = records_[index];
      float* out = rows.ptr<float>(static_cast<int>(k));
      if (record.has_crop) {
        from_crop(depth_crop(index), out);
      } else if (vectors->contains(record.id) && pick == nullptr) {
        vectors->read(record.id, out);
      } else if (vectors->contains(record.id)) {
        std::vector<float> whole(static_cast<std::size_t>(dimension));
        vectors->read(record.id, whole.data());
        for (const int f : *pick) *out++ = whole[static_cast<std::size_t>(f)];
      } else {
        fail(dir_, "sample " + std::to_string(record.id) +
                       " has no crop and no stored feature vector for feature spec " + spec.hash() + " (" +
                       vectors->path() + "); it was imported under spec " + manifest_.feature_spec.hash());
      }
    }
  });
  return rows;
}

}  // namespace rdsf
