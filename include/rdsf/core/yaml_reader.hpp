#pragma once
// The one reader of the YAML files the workbench reads (model files, sample-set manifests, training
// recipes), through OpenCV's cv::FileStorage:
//   1. the text is checked by yaml_layout_problem() first (OpenCV 4.6's reader never returns on some damaged
//      layouts, found by fuzzing): a layout this workbench never writes is refused before OpenCV sees it;
//   2. it is opened from memory; any exception OpenCV lets through becomes one rdsf::Error line;
//   3. every lookup is typed: a missing or mistyped entry is "<path>: missing 'camera.fx_px'" or
//      "<path>: 'rounds' is not an integer" (`context` is the dotted path of the parent with a trailing '.',
//      "" at the top level; a parent that is no mapping is named as such instead of letting OpenCV assert);
//   4. read() runs the caller's parse and turns whatever escapes it into "<path>: unreadable <kind> (...)".
// Every message is one line (text quoted from the file is passed through one_line()).
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/core/error.hpp"
#include "rdsf/core/yaml_guard.hpp"

namespace rdsf {

class YamlReader {
 public:
  /// Opens `text`, read from `path`; `kind` names what the file should be in messages ("model file",
  /// "manifest", "recipe"). Throws Error.
  YamlReader(const std::string& text, std::string path, std::string kind);
  /// Reads the file at `path` (Error "cannot be read" when it cannot), then as above.
  static YamlReader from_file(const std::string& path, const std::string& kind);

  const std::string& path() const { return path_; }
  cv::FileNode root() const { return storage_.root(); }
  /// Throws Error("<path>: <problem>") with `problem` on one line.
  [[noreturn]] void bad(const std::string& problem) const;

  // Required entries.
  cv::FileNode need(const cv::FileNode& parent, const std::string& key, const std::string& context = "") const;
  std::string text(const cv::FileNode& parent, const std::string& key, const std::string& context = "") const;
  int integer(const cv::FileNode& parent, const std::string& key, const std::string& context = "") const;
  double real(const cv::FileNode& parent, const std::string& key, const std::string& context = "") const;
  /// A number that must fit a float (converting a larger double to float is undefined behaviour).
  float single(const cv::FileNode& parent, const std::string& key, const std::string& context = "") const;

  // Optional entries: `fallback` when absent; a present entry of the wrong type is an error.
  bool has(const cv::FileNode& parent, const std::string& key) const;
  std::string text_or(const cv::FileNode& parent, const std::string& key, std::string fallback,
                      const std::string& context = "") const;
  int integer_or(const cv::FileNode& parent, const std::string& key, int fallback,
                 const std::string& context = "") const;
  double real_or(const cv::FileNode& parent, const std::string& key, double fallback,
                 const std::string& context = "") const;
  /// A list of texts; absent: empty; a single text: a list of one.
  std::vector<std::string> text_list(const cv::FileNode& parent, const std::string& key,
                                     const std::string& context = "") const;

  // Informational entries, read leniently: a wrong type reads as empty or 0. `child` is none when `parent`
  // is no mapping.
  static cv::FileNode child(const cv::FileNode& parent, const char* key);
  static std::string opt_text(const cv::FileNode& n);
  static double opt_real(const cv::FileNode& n);
  static int opt_int(const cv::FileNode& n);

  /// `parse(*this)`, with any cv::Exception or standard exception turned into
  /// "<path>: unreadable <kind> (<what>)"; an Error passes through (kept on one line).
  template <typename Parse>
  auto read(Parse&& parse) const -> decltype(parse(*this)) {
    try {
      return parse(*this);
    } catch (const Error& e) {
      const std::string message = e.what();
      if (message.find_first_of("\n\r") == std::string::npos) throw;
      throw Error(one_line(message));
    } catch (const cv::Exception& e) {
      bad("unreadable " + kind_ + " (" + e.err + ")");
    } catch (const std::exception& e) {
      bad("unreadable " + kind_ + " (" + e.what() + ")");
    }
  }

 private:
  std::string path_;
  std::string kind_;
  cv::FileStorage storage_;
};

}  // namespace rdsf
