// Replays the inputs the fuzzers found (fuzz/regressions/<parser>/) through the same entry points as the fuzz
// targets (fuzz/fuzz_entry_points.hpp): each must either parse or be refused with an rdsf::Error of one line
// naming the file - never crash, never throw anything else. The seed corpora (fuzz/corpus/<parser>/) are
// valid files and must parse. See docs/fuzzing.md.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fuzz/fuzz_entry_points.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path kFuzzDir = fs::path(RDSF_SOURCE_DIR) / "fuzz";

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> files;
  if (!fs::is_directory(dir)) return files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().filename() != "README.md") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

enum class Outcome { Parsed, Refused, Broken };

/// Feeds one file to `parser`; `detail` receives the error message (or what broke).
Outcome replay(const std::string& parser, const fs::path& file, std::string& detail) {
  try {
    rdsf::fuzz::parse_bytes(parser, rdsf::test::file_text(file));
    return Outcome::Parsed;
  } catch (const rdsf::Error& e) {
    detail = e.what();
    return Outcome::Refused;
  } catch (const std::exception& e) {
    detail = std::string("threw a non-rdsf exception: ") + e.what();
  } catch (...) {
    detail = "threw something that is not a std::exception";
  }
  return Outcome::Broken;
}

TEST(FuzzRegressions, KeptInputsParseOrAreRefusedWithOneLine) {
  std::size_t replayed = 0;
  for (const std::string& parser : rdsf::fuzz::parser_names()) {
    for (const fs::path& file : files_in(kFuzzDir / "regressions" / parser)) {
      std::string detail;
      const Outcome outcome = replay(parser, file, detail);
      EXPECT_NE(outcome, Outcome::Broken) << parser << " on " << file << ": " << detail;
      if (outcome == Outcome::Refused) {
        EXPECT_EQ(detail.find('\n'), std::string::npos) << file;
        EXPECT_FALSE(detail.empty()) << file;
      }
      ++replayed;
    }
  }
  // The folder holds the inputs found so far; losing them would silently turn this test into nothing.
  EXPECT_GT(replayed, 0u) << "no regression inputs under " << (kFuzzDir / "regressions");
}

TEST(FuzzRegressions, SeedCorporaAreValidFiles) {
  for (const std::string& parser : rdsf::fuzz::parser_names()) {
    const std::vector<fs::path> seeds = files_in(kFuzzDir / "corpus" / parser);
    EXPECT_FALSE(seeds.empty()) << "no seed inputs for " << parser;
    for (const fs::path& file : seeds) {
      std::string detail;
      EXPECT_EQ(replay(parser, file, detail), Outcome::Parsed) << parser << " on " << file << ": " << detail;
    }
  }
}

TEST(FuzzRegressions, EveryParserIsReachable) {
  // An unknown name is a programming error of the caller, not bad input.
  EXPECT_THROW(rdsf::fuzz::parse_bytes("no-such-parser", ""), std::invalid_argument);
  // Empty input is refused with an rdsf::Error by every parser except the answer journal, samples.tsv and
  // adapt-state.tsv, which treat an empty file as a fresh (or interrupted) one.
  for (const std::string& parser : rdsf::fuzz::parser_names()) {
    if (parser == "answer_journal" || parser == "sample_tsv" || parser == "adapt_state") {
      EXPECT_NO_THROW(rdsf::fuzz::parse_bytes(parser, "")) << parser;
    } else {
      EXPECT_THROW(rdsf::fuzz::parse_bytes(parser, ""), rdsf::Error) << parser;
    }
  }
}

}  // namespace
