#include <gtest/gtest.h>

#include <fstream>

#include "rdsf/core/append_only_log.hpp"
#include "rdsf/core/error.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

TEST(AppendOnlyLog, CompleteLinesAndATornTail) {
  test::TempDir dir;
  const std::string path = dir / "log.tsv";
  append_line_synced(path, "header");
  append_line_synced(path, "a\t1");
  std::ofstream(path, std::ios::app) << "b\t2 (killed here";  // a writer killed mid-line
  const LogLines log = read_log_lines(path);
  EXPECT_EQ(log.lines, (std::vector<std::string>{"header", "a\t1"}));
  EXPECT_TRUE(log.torn_tail);
  EXPECT_EQ(log.complete_bytes, 7u + 4u);
  cut_torn_tail(path, log.complete_bytes);
  append_line_synced(path, "c\t3");
  const LogLines repaired = read_log_lines(path);
  EXPECT_EQ(repaired.lines, (std::vector<std::string>{"header", "a\t1", "c\t3"}));
  EXPECT_FALSE(repaired.torn_tail);
}

TEST(AppendOnlyLog, MissingFileIsNamed) {
  try {
    read_log_lines("/no/such/log.tsv", "cannot be opened (is this a sample set folder?)");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "/no/such/log.tsv: cannot be opened (is this a sample set folder?)");
  }
}
