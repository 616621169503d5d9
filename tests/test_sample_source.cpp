// The one rule for a sample's source column (dataset/sample_source.hpp): files and folders by their
// absolute, normalised, link-resolved path whatever the working folder; devices as given.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "rdsf/dataset/sample_source.hpp"
#include "support/test_support.hpp"

namespace rdsf {
namespace {

namespace fs = std::filesystem;

// Restores the working folder when the test ends.
class InFolder {
 public:
  explicit InFolder(const fs::path& dir) : before_(fs::current_path()) { fs::current_path(dir); }
  ~InFolder() { fs::current_path(before_); }

 private:
  fs::path before_;
};

TEST(SampleSource, FoldersAreAbsoluteNormalisedAndIndependentOfTheWorkingFolder) {
  const test::TempDir dir("rdsf-source");
  const fs::path root = fs::canonical(dir.path());
  fs::create_directories(root / "data" / "empty");
  fs::create_directories(root / "data" / "x");
  std::string from_root, from_data;
  {
    InFolder here(root);
    from_root = sample_source("./data//empty/");
  }
  {
    InFolder here(root / "data");
    from_data = sample_source("empty");
  }
  EXPECT_EQ(from_root, (root / "data" / "empty").string());
  EXPECT_EQ(from_data, from_root);
  EXPECT_EQ(sample_source((root / "data" / "x" / ".." / "empty").string()), from_root);
}

TEST(SampleSource, LinksAreResolvedAndFilesNamedLikeFolders) {
  const test::TempDir dir("rdsf-source");
  const fs::path root = fs::canonical(dir.path());
  fs::create_directories(root / "real");
  fs::create_directory_symlink(root / "real", root / "link");
  EXPECT_EQ(sample_source((root / "link").string()), (root / "real").string());
  std::ofstream(root / "real" / "take.oni") << "x";
  EXPECT_EQ(sample_source((root / "link" / "take.oni").string()), (root / "real" / "take.oni").string());
}

TEST(SampleSource, DevicesStayAsGiven) {
  EXPECT_EQ(sample_source("openni"), "openni");
  EXPECT_EQ(sample_source("rdsf-png:///nowhere/frames?fps=30"), "rdsf-png:///nowhere/frames?fps=30");
  EXPECT_EQ(sample_source(""), "");
}

}  // namespace
}  // namespace rdsf
