#include "rdsf/dataset/sample_set_check.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include "rdsf/core/append_only_log.hpp"
#include "rdsf/core/durable_io.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/utc_time.hpp"
#include "rdsf/dataset/retraction_log.hpp"
#include "rdsf/dataset/sample_crop.hpp"
#include "rdsf/dataset/sample_set_lock.hpp"
#include "rdsf/dataset/sample_set_manifest.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/dataset/sample_tsv.hpp"
#include "rdsf/frame/png_decoder.hpp"

namespace rdsf {

namespace fs = std::filesystem;

namespace {

/// The PNG at `path` as the frame readers decode it (read_png_file: the signature and CRCs checked, what
/// cv::imdecode(IMREAD_UNCHANGED) gives), or an empty image when it is not a readable PNG. cv::imread, used
/// here before, sniffs every format it knows and threw cv::Exception on a 16-byte "PF" (PFM) file the
/// depth-crop fuzzer made.
cv::Mat read_png_or_empty(const std::string& path) {
  try {
    return read_png_file(path);
  } catch (const Error&) {
    return {};
  }
}

}  // namespace

std::string depth_crop_problem(const std::string& path, const SampleRecord& record, const FeatureSpec& spec,
                               bool full) {
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (ec) return "crop missing";
  if (size == 0) return "crop empty";
  if (!full) return "";
  const cv::Mat image = read_png_or_empty(path);
  if (image.empty()) return "crop truncated or not a PNG";
  if (image.type() != CV_16UC1 || image.cols != spec.window_width_px || image.rows != spec.window_height_px) {
    return "crop is not a " + std::to_string(spec.window_width_px) + "x" + std::to_string(spec.window_height_px) +
           " 16-bit depth image";
  }
  if (!record.crop_hash.empty() && depth_crop_hash(cv::Mat1w(image)) != record.crop_hash) {
    return "crop does not match its hash in samples.tsv (replaced by another image?)";
  }
  return "";
}

namespace {

struct Findings {
  std::vector<SetProblem> problems;
  bool manifest_ok = false;
  std::uint64_t keep_bytes = 0;            ///< samples.tsv bytes up to the last complete row
  bool torn = false;
  std::set<std::size_t> drop_lines;        ///< index lines (1-based) to drop
  std::vector<std::string> lines;          ///< complete lines of samples.tsv
  std::map<std::int64_t, std::string> retract;  ///< sample id -> reason
  std::vector<std::string> remove;         ///< files (relative) to remove

  void add(std::string where, std::string what, std::string fix) {
    problems.push_back({std::move(where), std::move(what), std::move(fix)});
  }
};

// The index's rows that read, in order, each id once and ascending (the others dropped), and the line of
// each id.
struct IndexRows {
  std::vector<SampleRecord> kept;
  std::map<std::int64_t, std::size_t> first_line;  // id -> line
};

IndexRows check_rows(const std::string& tsv, Findings& f) {
  IndexRows rows;
  std::int64_t last_id = 0;
  for (std::size_t i = 1; i < f.lines.size(); ++i) {
    const std::string where = "samples.tsv:" + std::to_string(i + 1);
    SampleRecord r;
    try {
      r = parse_sample_row(f.lines[i], tsv + ":" + std::to_string(i + 1));
    } catch (const Error& e) {
      f.add(where, e.what(), "row dropped from the index (the backup keeps it)");
      f.drop_lines.insert(i + 1);
      continue;
    }
    if (const auto seen = rows.first_line.find(r.id); seen != rows.first_line.end()) {
      f.add(where, "sample " + std::to_string(r.id) + ": id appears again (first on line " +
                       std::to_string(seen->second) + ")",
            "row dropped from the index (the backup keeps it)");
      f.drop_lines.insert(i + 1);
      continue;
    }
    if (r.id <= last_id) {
      f.add(where, "sample " + std::to_string(r.id) + ": id does not follow id " + std::to_string(last_id),
            "row dropped from the index (the backup keeps it)");
      f.drop_lines.insert(i + 1);
      continue;
    }
    rows.first_line[r.id] = i + 1;
    last_id = r.id;
    rows.kept.push_back(r);
  }
  return rows;
}

// Every kept sample's crops (not the retracted ones'): a bad depth crop retracts its sample.
void check_crops(const fs::path& root, const std::vector<SampleRecord>& kept, const RetractionLog& retracted,
                 const FeatureSpec& spec, Findings& f) {
  for (const SampleRecord& r : kept) {
    if (retracted.ids.count(r.id) != 0 || !r.has_crop) continue;
    const std::string stem = crop_stem(r.id);
    const std::string problem = depth_crop_problem((root / (stem + ".depth.png")).string(), r, spec, /*full=*/true);
    if (!problem.empty()) {
      f.add(stem + ".depth.png", "sample " + std::to_string(r.id) + ": " + problem, "sample retracted");
      f.retract[r.id] = problem;
    }
    if (r.has_colour && problem.empty()) {
      const cv::Mat colour = read_png_or_empty((root / (stem + ".rgb.png")).string());
      if (colour.empty() || colour.cols != spec.window_width_px || colour.rows != spec.window_height_px) {
        f.add(stem + ".rgb.png", "sample " + std::to_string(r.id) + ": colour crop missing or unusable", "");
      }
    }
  }
}

// Files in crops/ to remove: temporary files of interrupted writes and crops without a row.
void find_strays(const fs::path& root, const std::map<std::int64_t, std::size_t>& first_line, Findings& f) {
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(root / "crops", ec)) {
    const std::string name = e.path().filename().string();
    std::size_t digits = 0;
    while (digits < name.size() && name[digits] >= '0' && name[digits] <= '9') ++digits;
    const bool temporary = name.size() > 4 && name.compare(name.size() - 4, 4, ".tmp") == 0;
    const bool orphan = digits > 0 && digits < 19 && first_line.count(std::stoll(name.substr(0, digits))) == 0;
    if (temporary || orphan) {
      f.add("crops/" + name, temporary ? "temporary file of an interrupted write" : "crop without a row", "removed");
      f.remove.push_back("crops/" + name);
    }
  }
  std::sort(f.remove.begin(), f.remove.end());
}

Findings find(const std::string& dir) {
  Findings f;
  const fs::path root(dir);
  SampleSetManifest manifest;
  try {
    manifest = SampleSetManifest::read((root / "manifest.yml").string());
    f.manifest_ok = true;
  } catch (const Error& e) {
    f.add("manifest.yml", e.what(), "");
    return f;
  }
  const std::string tsv = (root / "samples.tsv").string();
  LogLines log;
  try {
    log = read_log_lines(tsv);
  } catch (const Error& e) {
    f.add("samples.tsv", e.what(), "");
    return f;
  }
  f.lines = log.lines;
  f.torn = log.torn_tail;
  f.keep_bytes = log.complete_bytes;
  if (log.torn_tail) f.add("samples.tsv", "the last row is torn (no newline)", "cut off");
  if (f.lines.empty() || f.lines[0] != sample_tsv_header()) {
    f.add("samples.tsv:1", "not a samples.tsv header", "");
    return f;
  }
  RetractionLog retracted;
  try {
    retracted = read_retraction_log((root / "retracted.tsv").string());
  } catch (const Error& e) {
    f.add("retracted.tsv", e.what(), "");
  }
  const IndexRows rows = check_rows(tsv, f);
  check_crops(root, rows.kept, retracted, manifest.feature_spec, f);
  find_strays(root, rows.first_line, f);
  return f;
}

std::string compact_utc() {
  std::string t = utc_now_iso8601();
  t.erase(std::remove_if(t.begin(), t.end(), [](char c) { return c == ':' || c == '-'; }), t.end());
  return t;
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

std::vector<SetProblem> check_sample_set(const std::string& dir) { return find(dir).problems; }

std::vector<std::string> repair_sample_set(const std::string& dir) {
  std::vector<std::string> changes;
  const fs::path root(dir);
  {
    SampleSetLock lock(dir);
    const Findings f = find(dir);
    if (!f.manifest_ok) fail(dir, "manifest.yml is unusable: nothing repaired (" + f.problems.front().what + ")");
    if (f.problems.empty()) return changes;
    const std::string stamp = compact_utc();
    for (const char* name : {"samples.tsv", "retracted.tsv"}) {
      const fs::path file = root / name;
      std::error_code ec;
      if (!fs::exists(file, ec)) continue;
      const std::string backup = file.string() + ".bak-" + stamp;
      write_file_durably(backup, read_all(file.string()), Replace::never);
      changes.push_back(std::string(name) + ": copied to " + fs::path(backup).filename().string());
    }
    if (f.torn || !f.drop_lines.empty()) {
      std::string text;
      for (std::size_t i = 0; i < f.lines.size(); ++i) {
        if (f.drop_lines.count(i + 1) == 0) text += f.lines[i] + "\n";
      }
      write_file_durably((root / "samples.tsv").string(), text);
      if (f.torn) changes.push_back("samples.tsv: torn last row cut off");
      for (std::size_t line : f.drop_lines) {
        changes.push_back("samples.tsv:" + std::to_string(line) + ": row dropped (kept in the backup)");
      }
    }
    for (const std::string& name : f.remove) {
      remove_file((root / name).string());
      changes.push_back(name + ": removed");
    }
    if (!f.remove.empty()) sync_folder((root / "crops").string());
  }
  // Retractions through the writer (which also repairs what it does on every open).
  SampleSetWriter writer = SampleSetWriter::open_existing(dir);
  for (const std::string& repair : writer.repairs()) changes.push_back(repair);
  const Findings after = find(dir);
  for (const auto& [id, reason] : after.retract) {
    writer.retract(id, reason);
    changes.push_back("sample " + std::to_string(id) + ": retracted (" + reason + ")");
  }
  return changes;
}

}  // namespace rdsf
