#include "dataset/sample_set_writer.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <utility>

#include <fcntl.h>
#include <unistd.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "dataset/feature_vector_file.hpp"
#include "dataset/retraction_log.hpp"
#include "dataset/sample_tsv.hpp"

namespace rdsf {

namespace fs = std::filesystem;

struct SampleSetWriter::State {
  std::string dir;
  SampleSetManifest manifest;
  SampleSetLock lock;
  std::vector<SampleRecord> records;
  std::int64_t next_id = 1;
  int tsv_fd = -1;
  int vectors_fd = -1;
  int retracted_fd = -1;
  bool recovered_torn_row = false;
  bool broken = false;  ///< a write failed: the set must be reopened (which repairs it)
  std::unordered_set<std::string> place_keys;
  std::unordered_set<std::string> hash_keys;

  State(std::string d, SampleSetLock l) : dir(std::move(d)), lock(std::move(l)) {}
  ~State() {
    if (tsv_fd >= 0) ::close(tsv_fd);
    if (vectors_fd >= 0) ::close(vectors_fd);
    if (retracted_fd >= 0) ::close(retracted_fd);
  }
  State(const State&) = delete;
  State& operator=(const State&) = delete;

  std::string path(const std::string& name) const { return (fs::path(dir) / name).string(); }
  std::string tsv_path() const { return path("samples.tsv"); }
  std::string retracted_path() const { return path("retracted.tsv"); }
  std::string vectors_path() const { return FeatureVectorFile::path_in(dir, manifest.feature_spec.hash()); }
};

namespace {

std::string place_key(const SampleRecord& r) {
  const cv::Rect& b = r.strict_box;
  return std::to_string(r.label) + '\x1f' + r.source + '\x1f' + r.frame + '\x1f' + std::to_string(b.x) + ',' +
         std::to_string(b.y) + ',' + std::to_string(b.width) + ',' + std::to_string(b.height);
}

std::string hash_key(const SampleRecord& r) { return std::to_string(r.label) + ':' + r.crop_hash; }

void write_all(int fd, const void* data, std::size_t size, const std::string& path) {
  const char* bytes = static_cast<const char*>(data);
  std::size_t written = 0;
  while (written < size) {
    const ssize_t n = ::write(fd, bytes + written, size - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail(path, std::string("append failed (disk full?): ") + std::strerror(errno));
    written += static_cast<std::size_t>(n);
  }
}

void sync_fd(int fd, const std::string& path) {
  if (::fdatasync(fd) != 0) fail(path, std::string("cannot flush to disk: ") + std::strerror(errno));
}

void truncate_file(const std::string& path, std::uint64_t size) {
  std::error_code ec;
  fs::resize_file(path, size, ec);
  if (ec) fail(path, "cannot cut off the torn end left by a killed writer: " + ec.message());
}

void write_header(const std::string& path, const std::string& header = sample_tsv_header()) {
  AtomicTextFile file(path, /*overwrite=*/true);
  file.stream() << header << '\n';
  file.commit();
}

}  // namespace

SampleSetWriter::SampleSetWriter(std::unique_ptr<State> state) : state_(std::move(state)) {}
SampleSetWriter::SampleSetWriter(SampleSetWriter&&) noexcept = default;
SampleSetWriter& SampleSetWriter::operator=(SampleSetWriter&&) noexcept = default;
SampleSetWriter::~SampleSetWriter() = default;

SampleSetWriter SampleSetWriter::open_or_create(const std::string& dir, const FeatureSpec& spec,
                                                const CameraModel& camera, const std::string& created_by) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) fail(dir, "cannot create the sample set folder: " + ec.message());
  SampleSetLock lock(dir);
  const fs::path root(dir);
  if (!fs::exists(root / "manifest.yml", ec)) {
    // A new set. Leftovers of an interrupted creation are allowed; anything else means a wrong folder.
    for (const fs::directory_entry& entry : fs::directory_iterator(root, ec)) {
      const std::string name = entry.path().filename().string();
      const bool leftover = name == "lock" || name == "manifest.yml.partial" || name == "samples.tsv.partial" ||
                            (name == "samples.tsv" && entry.file_size(ec) <= sample_tsv_header().size() + 1) ||
                            (name == "crops" && entry.is_directory() && fs::is_empty(entry.path(), ec));
      if (!leftover) {
        fail(dir, "folder exists and is not a sample set (no manifest.yml, but it holds '" + name +
                      "'); give a new or empty folder");
      }
    }
    if (ec) fail(dir, "cannot list the folder: " + ec.message());
    fs::create_directories(root / "crops", ec);
    if (ec) fail((root / "crops").string(), "cannot create: " + ec.message());
    write_header((root / "samples.tsv").string());
    SampleSetManifest manifest;
    manifest.feature_spec = spec;
    manifest.camera = camera;
    manifest.created = utc_now_iso8601();
    manifest.created_by = created_by;
    manifest.write((root / "manifest.yml").string());  // last: a set exists once its manifest does
  }
  SampleSetWriter writer = open_locked(dir, std::move(lock));
  const FeatureSpec& have = writer.manifest().feature_spec;
  if (have != spec) {
    fail(dir, "sample set has feature spec " + have.hash() + " (" + have.canonical() + "), not the requested " +
                  spec.hash() + " (" + spec.canonical() + "); use another set");
  }
  return writer;
}

SampleSetWriter SampleSetWriter::open_existing(const std::string& dir) {
  std::error_code ec;
  if (!fs::exists(fs::path(dir) / "manifest.yml", ec)) fail(dir, "is not a sample set (no manifest.yml)");
  return open_locked(dir, SampleSetLock(dir));
}

SampleSetWriter SampleSetWriter::open_locked(const std::string& dir, SampleSetLock lock) {
  auto state = std::make_unique<State>(dir, std::move(lock));
  State& s = *state;
  s.manifest = SampleSetManifest::read(s.path("manifest.yml"));
  SampleTsvContents contents = read_sample_tsv(s.tsv_path());
  if (contents.complete_bytes == 0) {
    write_header(s.tsv_path());
  } else if (contents.torn_tail) {
    truncate_file(s.tsv_path(), contents.complete_bytes);
  }
  s.recovered_torn_row = contents.torn_tail;
  s.next_id = contents.records.empty() ? 1 : contents.records.back().id + 1;
  const RetractionLog retracted = read_retraction_log(s.retracted_path());
  if (retracted.exists && retracted.complete_bytes == 0) {
    write_header(s.retracted_path(), retraction_log_header());
  } else if (retracted.torn_tail) {
    truncate_file(s.retracted_path(), retracted.complete_bytes);
  }
  for (SampleRecord& record : contents.records) {
    if (retracted.ids.count(record.id) == 0) s.records.push_back(std::move(record));
  }
  for (const SampleRecord& r : s.records) {
    s.place_keys.insert(place_key(r));
    if (!r.crop_hash.empty()) s.hash_keys.insert(hash_key(r));
  }

  // Remove what a killed writer left of the sample in flight: temporary files, crops without a row.
  std::error_code ec;
  const fs::path crops = fs::path(dir) / "crops";
  fs::create_directories(crops, ec);
  if (ec) fail(crops.string(), "cannot create: " + ec.message());
  for (const fs::directory_entry& entry : fs::directory_iterator(crops, ec)) {
    const std::string name = entry.path().filename().string();
    bool orphan = name.size() > 4 && name.compare(name.size() - 4, 4, ".tmp") == 0;
    std::size_t digits = 0;
    while (digits < name.size() && name[digits] >= '0' && name[digits] <= '9') ++digits;
    if (digits > 0 && digits < 19 && std::stoll(name.substr(0, digits)) >= s.next_id) orphan = true;
    if (orphan) fs::remove(entry.path(), ec);
  }
  const std::string vectors_path = s.vectors_path();
  if (fs::exists(vectors_path, ec)) {
    const FeatureVectorFile vectors(vectors_path, s.manifest.feature_spec.dimension());
    const std::uint64_t keep = vectors.first_offset_from(s.next_id);
    if (keep != fs::file_size(vectors_path, ec)) truncate_file(vectors_path, keep);
  }

  s.tsv_fd = ::open(s.tsv_path().c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (s.tsv_fd < 0) fail(s.tsv_path(), std::string("cannot be opened for appending: ") + std::strerror(errno));
  return SampleSetWriter(std::move(state));
}

SampleRecord SampleSetWriter::prepare(SampleRecord record) const {
  if (!state_) throw Error("sample set writer: used after close()");
  if (state_->broken) fail(state_->dir, "an earlier append failed; reopen the set (which repairs it)");
  if (record.label != 0 && record.label != 1) {
    fail(state_->dir, "label " + std::to_string(record.label) + " is neither 1 (person) nor 0 (not)");
  }
  record.id = state_->next_id;
  if (record.time.empty()) record.time = utc_now_iso8601();
  return record;
}

void SampleSetWriter::append_row(const SampleRecord& record, bool sync_now) {
  State& s = *state_;
  const std::string line = format_sample_row(record) + '\n';
  try {
    write_all(s.tsv_fd, line.data(), line.size(), s.tsv_path());
    if (sync_now) sync_fd(s.tsv_fd, s.tsv_path());
  } catch (...) {
    s.broken = true;
    throw;
  }
  s.records.push_back(record);
  s.place_keys.insert(place_key(record));
  if (!record.crop_hash.empty()) s.hash_keys.insert(hash_key(record));
  s.next_id = record.id + 1;
}

SampleRecord SampleSetWriter::append(SampleRecord record, const cv::Mat1w& depth_crop, const cv::Mat3b& colour_crop) {
  return append_encoded(std::move(record), EncodedCrop::encode(depth_crop, colour_crop));
}

void SampleSetWriter::sync() {
  if (!state_) throw Error("sample set writer: used after close()");
  sync_fd(state_->tsv_fd, state_->tsv_path());
}

SampleRecord SampleSetWriter::append_encoded(SampleRecord record, const EncodedCrop& crop, bool sync_now) {
  record = prepare(std::move(record));
  State& s = *state_;
  const FeatureSpec& spec = s.manifest.feature_spec;
  if (crop.size != cv::Size(spec.window_width_px, spec.window_height_px) || crop.depth_png.empty()) {
    fail(s.dir, "crop of " + std::to_string(crop.size.width) + "x" + std::to_string(crop.size.height) +
                    " does not match the set's window " + std::to_string(spec.window_width_px) + "x" +
                    std::to_string(spec.window_height_px));
  }
  record.has_crop = true;
  record.has_colour = !crop.colour_png.empty();
  record.crop_hash = crop.hash;
  const std::string stem = s.path(crop_stem(record.id));
  write_bytes_atomically(stem + ".depth.png", crop.depth_png);
  if (record.has_colour) write_bytes_atomically(stem + ".rgb.png", crop.colour_png);
  append_row(record, sync_now);
  return record;
}

SampleRecord SampleSetWriter::append_vector(SampleRecord record, const float* features) {
  record = prepare(std::move(record));
  State& s = *state_;
  record.has_crop = false;
  record.has_colour = false;
  record.crop_hash.clear();
  const std::string path = s.vectors_path();
  if (s.vectors_fd < 0) {
    s.vectors_fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
    if (s.vectors_fd < 0) fail(path, std::string("cannot be opened for appending: ") + std::strerror(errno));
  }
  const std::int64_t id = record.id;
  std::vector<char> bytes(8 + 4 * static_cast<std::size_t>(dimension()));
  std::memcpy(bytes.data(), &id, 8);
  std::memcpy(bytes.data() + 8, features, bytes.size() - 8);
  try {
    write_all(s.vectors_fd, bytes.data(), bytes.size(), path);
    sync_fd(s.vectors_fd, path);
  } catch (...) {
    s.broken = true;
    throw;
  }
  append_row(record, true);
  return record;
}

void SampleSetWriter::retract(std::int64_t id) {
  if (!state_) throw Error("sample set writer: used after close()");
  State& s = *state_;
  if (s.broken) fail(s.dir, "an earlier append failed; reopen the set (which repairs it)");
  const auto found = std::find_if(s.records.rbegin(), s.records.rend(),
                                  [id](const SampleRecord& r) { return r.id == id; });
  if (found == s.records.rend()) {
    fail(s.dir, "cannot retract sample " + std::to_string(id) + ": the set holds no such sample");
  }
  const std::string path = s.retracted_path();
  if (s.retracted_fd < 0) {
    std::error_code ec;
    if (!fs::exists(path, ec)) write_header(path, retraction_log_header());
    s.retracted_fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (s.retracted_fd < 0) fail(path, std::string("cannot be opened for appending: ") + std::strerror(errno));
  }
  const std::string line = std::to_string(id) + '\t' + utc_now_iso8601() + '\n';
  try {
    write_all(s.retracted_fd, line.data(), line.size(), path);
    sync_fd(s.retracted_fd, path);
  } catch (...) {
    s.broken = true;
    throw;
  }
  s.place_keys.erase(place_key(*found));
  if (!found->crop_hash.empty()) s.hash_keys.erase(hash_key(*found));
  s.records.erase(std::next(found).base());
}

bool SampleSetWriter::is_duplicate(const SampleRecord& record) const {
  if (state_->place_keys.count(place_key(record)) != 0) return true;
  return !record.crop_hash.empty() && state_->hash_keys.count(hash_key(record)) != 0;
}

const std::vector<SampleRecord>& SampleSetWriter::records() const { return state_->records; }
const SampleSetManifest& SampleSetWriter::manifest() const { return state_->manifest; }
const std::string& SampleSetWriter::dir() const { return state_->dir; }
int SampleSetWriter::dimension() const { return state_->manifest.feature_spec.dimension(); }
bool SampleSetWriter::recovered_torn_row() const { return state_->recovered_torn_row; }
bool SampleSetWriter::took_over_stale_lock() const { return state_->lock.took_over_stale(); }
std::string SampleSetWriter::stale_holder() const { return state_->lock.stale_holder(); }
void SampleSetWriter::close() { state_.reset(); }

}  // namespace rdsf
