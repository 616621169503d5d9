#include "rdsf/dataset/sample_set_writer.hpp"

#include <algorithm>
#include <filesystem>
#include <unordered_map>
#include <utility>

#include "rdsf/core/durable_io.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/utc_time.hpp"
#include "rdsf/dataset/feature_vector_file.hpp"
#include "rdsf/dataset/retraction_log.hpp"
#include "rdsf/dataset/sample_set_check.hpp"
#include "rdsf/dataset/sample_tsv.hpp"

namespace rdsf {

namespace fs = std::filesystem;

struct SampleSetWriter::State {
  std::string dir;
  SampleSetManifest manifest;
  SampleSetLock lock;
  std::vector<SampleRecord> records;
  std::int64_t next_id = 1;
  AppendFile tsv;
  AppendFile vectors;
  AppendFile retracted;
  std::vector<std::string> unsynced_crops;  ///< crops of rows appended with sync = false
  std::size_t unsynced_rows = 0;            ///< rows appended with sync = false since the last sync()
  bool recovered_torn_row = false;
  std::vector<std::string> repairs;
  bool broken = false;  ///< a write failed: the set must be reopened (which repairs it)
  std::unordered_map<std::string, std::int64_t> place_keys;  ///< place -> id
  std::unordered_set<std::string> hash_keys;

  State(std::string d, SampleSetLock l) : dir(std::move(d)), lock(std::move(l)) {}
  State(const State&) = delete;
  State& operator=(const State&) = delete;

  std::string path(const std::string& name) const { return (fs::path(dir) / name).string(); }
  std::string tsv_path() const { return path("samples.tsv"); }
  std::string retracted_path() const { return path("retracted.tsv"); }
  std::string vectors_path() const { return FeatureVectorFile::path_in(dir, manifest.feature_spec.hash()); }
};

namespace {

/// A batch of at least this many crops is flushed with one syncfs() instead of one fdatasync() each.
constexpr std::size_t kSyncfsFromCrops = 4;

std::string place_key(const SampleRecord& r) {
  const cv::Rect& b = r.strict_box;
  return std::to_string(r.label) + '\x1f' + r.source + '\x1f' + r.frame + '\x1f' + std::to_string(b.x) + ',' +
         std::to_string(b.y) + ',' + std::to_string(b.width) + ',' + std::to_string(b.height);
}

std::string hash_key(const SampleRecord& r) { return std::to_string(r.label) + ':' + r.crop_hash; }

/// A reason as one tab- and newline-free field of retracted.tsv.
std::string one_field(std::string text) {
  for (char& c : text) {
    if (c == '\t' || c == '\n' || c == '\r') c = ' ';
  }
  return text;
}

void write_header(const std::string& path, const std::string& header = sample_tsv_header()) {
  write_file_durably(path, header + "\n");
}

}  // namespace

SampleSetWriter::SampleSetWriter(std::unique_ptr<State> state) : state_(std::move(state)) {}
SampleSetWriter::SampleSetWriter(SampleSetWriter&&) noexcept = default;
SampleSetWriter& SampleSetWriter::operator=(SampleSetWriter&&) noexcept = default;
SampleSetWriter::~SampleSetWriter() = default;

SampleSetWriter SampleSetWriter::open_or_create(const std::string& dir, const FeatureSpec& spec,
                                                const CameraModel& camera, const std::string& created_by,
                                                const CropProvenance& crops,
                                                const RecordedParameters& analyser_options) {
  std::error_code ec;
  create_folders_durably(dir);
  SampleSetLock lock(dir);
  const fs::path root(dir);
  if (!fs::exists(root / "manifest.yml", ec)) {
    // A new set. Leftovers of an interrupted creation are allowed; anything else means a wrong folder.
    for (const fs::directory_entry& entry : fs::directory_iterator(root, ec)) {
      const std::string name = entry.path().filename().string();
      const bool leftover = name == "lock" || name == "manifest.yml.partial" || name == "samples.tsv.tmp" ||
                            name == "samples.tsv.partial" ||
                            (name == "samples.tsv" && entry.file_size(ec) <= sample_tsv_header().size() + 1) ||
                            (name == "crops" && entry.is_directory() && fs::is_empty(entry.path(), ec));
      if (!leftover) {
        fail(dir, "folder exists and is not a sample set (no manifest.yml, but it holds '" + name +
                      "'); give a new or empty folder");
      }
    }
    if (ec) fail(dir, "cannot list the folder: " + ec.message());
    create_folders_durably((root / "crops").string());
    write_header((root / "samples.tsv").string());
    SampleSetManifest manifest;
    manifest.feature_spec = spec;
    manifest.camera = camera;
    manifest.crops = crops;
    manifest.analyser_options = analyser_options;
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
  const std::string crops_differ =
      crop_provenance_mismatch(writer.manifest().crops, "the set's crops", crops, "the new crops");
  if (!crops_differ.empty()) fail(dir, "sample set's crops were cut differently: " + crops_differ + "; use another set");
  const RecordedParameters& had = writer.manifest().analyser_options;
  const std::optional<std::size_t> i = first_difference(had, analyser_options);
  if (!had.empty() && !analyser_options.empty() && i) {
    const std::string which = *i < had.size() && *i < analyser_options.size()
                                  ? " (" + had[*i].first + " " + had[*i].second + ", now " + analyser_options[*i].second + ")"
                                  : "";
    fail(dir, "sample set's candidates were found with other options" + which +
                  "; give the set's options or use another set");
  }
  return writer;
}

SampleSetWriter SampleSetWriter::open_existing(const std::string& dir) {
  std::error_code ec;
  if (!fs::exists(fs::path(dir) / "manifest.yml", ec)) fail(dir, "is not a sample set (no manifest.yml)");
  return open_locked(dir, SampleSetLock(dir));
}

void SampleSetWriter::write_crop_unsynced(const std::string& path, const std::vector<unsigned char>& bytes) {
  write_new_file_unsynced(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  state_->unsynced_crops.push_back(path);
}

SampleSetWriter SampleSetWriter::open_locked(const std::string& dir, SampleSetLock lock) {
  auto state = std::make_unique<State>(dir, std::move(lock));
  State& s = *state;
  s.manifest = SampleSetManifest::read(s.path("manifest.yml"));
  SampleTsvContents contents = read_sample_tsv(s.tsv_path());
  if (contents.complete_bytes == 0) {
    write_header(s.tsv_path());
  } else if (contents.torn_tail) {
    cut_file_durably(s.tsv_path(), contents.complete_bytes);
    s.repairs.push_back("samples.tsv: cut off a sample row torn by an interrupted writer (never reported as saved)");
  }
  s.recovered_torn_row = contents.torn_tail;
  s.next_id = contents.records.empty() ? 1 : contents.records.back().id + 1;
  const RetractionLog retracted = read_retraction_log(s.retracted_path());
  if (retracted.exists && retracted.complete_bytes == 0) {
    write_header(s.retracted_path(), retraction_log_header());
  } else if (retracted.torn_tail) {
    cut_file_durably(s.retracted_path(), retracted.complete_bytes);
    s.repairs.push_back("retracted.tsv: cut off a torn last row (never reported as done)");
  }
  for (SampleRecord& record : contents.records) {
    if (retracted.ids.count(record.id) == 0) s.records.push_back(std::move(record));
  }
  for (const SampleRecord& r : s.records) {
    s.place_keys[place_key(r)] = r.id;
    if (!r.crop_hash.empty()) s.hash_keys.insert(hash_key(r));
  }

  // Remove what an interrupted writer left of the sample in flight: temporary files, crops without a row.
  std::error_code ec;
  const fs::path crops = fs::path(dir) / "crops";
  create_folders_durably(crops.string());
  std::vector<fs::path> orphans;
  for (const fs::directory_entry& entry : fs::directory_iterator(crops, ec)) {
    const std::string name = entry.path().filename().string();
    bool orphan = name.size() > 4 && name.compare(name.size() - 4, 4, ".tmp") == 0;
    std::size_t digits = 0;
    while (digits < name.size() && name[digits] >= '0' && name[digits] <= '9') ++digits;
    if (digits > 0 && digits < 19 && std::stoll(name.substr(0, digits)) >= s.next_id) orphan = true;
    if (orphan) orphans.push_back(entry.path());
  }
  if (ec) fail(crops.string(), "cannot list the folder: " + ec.message());
  std::sort(orphans.begin(), orphans.end());
  for (const fs::path& orphan : orphans) {
    remove_file(orphan.string());
    s.repairs.push_back("crops/" + orphan.filename().string() + ": removed (no row: a sample never saved)");
  }
  if (!orphans.empty()) sync_folder(crops.string());
  const std::string vectors_path = s.vectors_path();
  if (fs::exists(vectors_path, ec)) {
    const FeatureVectorFile vectors(vectors_path, s.manifest.feature_spec.dimension());
    const std::uint64_t keep = vectors.first_offset_from(s.next_id);
    if (keep != fs::file_size(vectors_path, ec)) {
      cut_file_durably(vectors_path, keep);
      s.repairs.push_back(fs::path(vectors_path).filename().string() + ": cut off vectors without a row");
    }
  }

  // Rows whose depth crop is unusable (missing or empty for every row; decoded and hashed for the last
  // kCheckedRows) are retracted with the reason: such a row was never reported as saved by this version
  // (crops are on disk before their row), but a disk that lost data or an older version can leave them.
  constexpr std::size_t kCheckedRows = kMaxUnsyncedRows;  // a whole unsynced batch
  s.tsv = AppendFile(s.tsv_path(), /*create=*/false);
  std::vector<std::pair<std::int64_t, std::string>> bad;
  for (std::size_t i = 0; i < s.records.size(); ++i) {
    const SampleRecord& r = s.records[i];
    if (!r.has_crop) continue;
    const std::string problem = depth_crop_problem(s.path(crop_stem(r.id) + ".depth.png"), r, s.manifest.feature_spec,
                                             i + kCheckedRows >= s.records.size());
    if (!problem.empty()) bad.emplace_back(r.id, problem);
  }
  SampleSetWriter writer(std::move(state));
  for (const auto& [id, problem] : bad) {
    writer.retract(id, problem);
    writer.state_->repairs.push_back("sample " + std::to_string(id) + ": retracted (" + problem + ", " +
                                     crop_stem(id) + ".depth.png)");
  }
  return writer;
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
    if (sync_now) sync_crops();
    s.tsv.append(line, sync_now);
  } catch (...) {
    s.broken = true;
    throw;
  }
  s.unsynced_rows = sync_now ? 0 : s.unsynced_rows + 1;  // a synced row flushes the batch before it
  s.records.push_back(record);
  s.place_keys[place_key(record)] = record.id;
  if (!record.crop_hash.empty()) s.hash_keys.insert(hash_key(record));
  s.next_id = record.id + 1;
}

SampleRecord SampleSetWriter::append(SampleRecord record, const cv::Mat1w& depth_crop, const cv::Mat3b& colour_crop) {
  return append_encoded(std::move(record), EncodedCrop::encode(depth_crop, colour_crop));
}

void SampleSetWriter::sync() {
  if (!state_) throw Error("sample set writer: used after close()");
  try {
    sync_crops();
    state_->tsv.sync();
  } catch (...) {
    state_->broken = true;
    throw;
  }
  state_->unsynced_rows = 0;
}

std::size_t SampleSetWriter::unsynced_rows() const { return state_ ? state_->unsynced_rows : 0; }

void SampleSetWriter::sync_crops() {
  State& s = *state_;
  if (s.unsynced_crops.empty()) return;
  if (s.unsynced_crops.size() >= kSyncfsFromCrops) {
    sync_file_system(s.path("crops"));  // one flush for the batch: data and names
  } else {
    for (const std::string& path : s.unsynced_crops) sync_file(path);
    sync_folder(s.path("crops"));
  }
  s.unsynced_crops.clear();
}

SampleRecord SampleSetWriter::append_encoded(SampleRecord record, const EncodedCrop& crop, bool sync_now) {
  if (!sync_now && state_ && state_->unsynced_rows >= kMaxUnsyncedRows) sync();  // a batch stays checkable
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
  try {
    if (sync_now) {
      // On disk, name included, before the row that refers to it.
      write_file_durably(stem + ".depth.png", crop.depth_png);
      if (record.has_colour) write_file_durably(stem + ".rgb.png", crop.colour_png);
    } else {
      // Batched (the miner): written under their own names now (a crop without a row is removed at
      // open), synced by sync() before the rows are.
      write_crop_unsynced(stem + ".depth.png", crop.depth_png);
      if (record.has_colour) write_crop_unsynced(stem + ".rgb.png", crop.colour_png);
    }
  } catch (...) {
    s.broken = true;
    throw;
  }
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
  const std::int64_t id = record.id;
  std::vector<char> bytes(8 + 4 * static_cast<std::size_t>(dimension()));
  std::memcpy(bytes.data(), &id, 8);
  std::memcpy(bytes.data() + 8, features, bytes.size() - 8);
  try {
    if (!s.vectors.is_open()) s.vectors = AppendFile(path, /*create=*/true);
    s.vectors.append(std::string_view(bytes.data(), bytes.size()));
  } catch (...) {
    s.broken = true;
    throw;
  }
  append_row(record, true);
  return record;
}

void SampleSetWriter::retract(std::int64_t id, const std::string& reason) {
  if (!state_) throw Error("sample set writer: used after close()");
  State& s = *state_;
  if (s.broken) fail(s.dir, "an earlier append failed; reopen the set (which repairs it)");
  const auto found = std::find_if(s.records.rbegin(), s.records.rend(),
                                  [id](const SampleRecord& r) { return r.id == id; });
  if (found == s.records.rend()) {
    fail(s.dir, "cannot retract sample " + std::to_string(id) + ": the set holds no such sample");
  }
  const std::string path = s.retracted_path();
  std::string line = std::to_string(id) + '\t' + utc_now_iso8601();
  if (!reason.empty()) line += '\t' + one_field(reason);
  line += '\n';
  try {
    if (!s.retracted.is_open()) {
      std::error_code ec;
      if (!fs::exists(path, ec)) write_header(path, retraction_log_header());
      s.retracted = AppendFile(path, /*create=*/false);
    }
    s.retracted.append(line);
  } catch (...) {
    s.broken = true;
    throw;
  }
  s.place_keys.erase(place_key(*found));
  if (!found->crop_hash.empty()) s.hash_keys.erase(hash_key(*found));
  s.records.erase(std::next(found).base());
}

std::int64_t SampleSetWriter::id_at_place(const SampleRecord& record) const {
  const auto found = state_->place_keys.find(place_key(record));
  return found == state_->place_keys.end() ? -1 : found->second;
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
const std::vector<std::string>& SampleSetWriter::repairs() const { return state_->repairs; }
bool SampleSetWriter::took_over_stale_lock() const { return state_->lock.took_over_stale(); }
std::string SampleSetWriter::stale_holder() const { return state_->lock.stale_holder(); }
void SampleSetWriter::close() { state_.reset(); }

}  // namespace rdsf
