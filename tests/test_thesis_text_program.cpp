// rdsf-samples: describe a set, import and export the thesis's text format from the command line.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "support/test_support.hpp"

using rdsf::test::quote;
using rdsf::test::run;

namespace {

std::string samples(const std::string& arguments) {
  return quote(rdsf::test::program("rdsf-samples")) + " " + arguments;
}

void write_lines(const std::string& path, int good_lines, const std::string& bad_line = {}) {
  std::ofstream out(path);
  for (int i = 0; i < good_lines; ++i) {
    out << (i % 2);
    for (int f = 0; f < 8128; ++f) out << ' ' << ((f + i) % 100) / 100.0;
    out << '\n';
    if (i == 0 && !bad_line.empty()) out << bad_line << '\n';
  }
}

}  // namespace

TEST(ThesisTextProgram, ImportDescribeExport) {
  rdsf::test::TempDir dir;
  write_lines(dir / "in.txt", 3);
  const auto imported = run(samples("--set " + quote(dir / "set") + " --import " + quote(dir / "in.txt")));
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  EXPECT_NE(imported.err.find("3 samples, imported 3"), std::string::npos) << imported.err;

  const auto info = run(samples("--set " + quote(dir / "set")));
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("samples 3: 1 person, 2 not"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("without crop (imported vectors) 3"), std::string::npos) << info.out;

  const auto exported = run(samples("--set " + quote(dir / "set") + " --export " + quote(dir / "out.txt")));
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  // Same values (the text of each number may differ: "0.1" is written as the float's shortest text).
  std::ifstream a(dir / "in.txt"), b(dir / "out.txt");
  std::string word_a, word_b;
  int words = 0;
  while (a >> word_a) {
    ASSERT_TRUE(static_cast<bool>(b >> word_b));
    EXPECT_EQ(std::stof(word_a), std::stof(word_b)) << "word " << words;
    ++words;
  }
  EXPECT_FALSE(static_cast<bool>(b >> word_b));
  EXPECT_EQ(words, 3 * 8129);
  // No silent overwrite.
  const auto again = run(samples("--set " + quote(dir / "set") + " --export " + quote(dir / "out.txt")));
  EXPECT_EQ(again.exit_code, 1);
  EXPECT_NE(again.err.find("already exists"), std::string::npos) << again.err;
}

TEST(ThesisTextProgram, BadLineIsNamedAndNothingImported) {
  rdsf::test::TempDir dir;
  write_lines(dir / "bad.txt", 3, "1 0.5 0.5");
  const auto result = run(samples("--set " + quote(dir / "set") + " --import " + quote(dir / "bad.txt")));
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find(dir / "bad.txt" + ":2: 2 feature values, expected 8128"), std::string::npos)
      << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;  // one line
  EXPECT_FALSE(std::filesystem::exists(dir / "set"));  // checked before the set is created
}
