// The library as a package: its version, the optional OpenNI2 part, and where a build-tree program finds
// the shipped models (the installed case is checked by scripts/check-install.sh, the CTest test
// Package.InstallAndBuildTheExample).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/shipped_data.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/version.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;

TEST(Version, LibraryAndHeadersAgree) {
  EXPECT_EQ(rdsf::version(), RDSF_VERSION_STRING);
  EXPECT_TRUE(std::regex_match(rdsf::version(), std::regex("[0-9]+\\.[0-9]+\\.[0-9]+"))) << rdsf::version();
  EXPECT_EQ(rdsf::version(), std::to_string(RDSF_VERSION_MAJOR) + "." + std::to_string(RDSF_VERSION_MINOR) + "." +
                                 std::to_string(RDSF_VERSION_PATCH));
  EXPECT_EQ(rdsf::has_openni(), RDSF_WITH_OPENNI != 0);
}

TEST(ShippedModels, BuildTreeProgramsUseTheSourceTreeModels) {
  const fs::path expected = fs::path(RDSF_SOURCE_DIR) / "models";
  EXPECT_EQ(fs::path(rdsf::shipped_models_dir()), expected);
  EXPECT_EQ(rdsf::shipped_data_models_dir(), rdsf::shipped_models_dir());
  EXPECT_TRUE(fs::is_regular_file(expected / rdsf::kDefaultModelName / "v1.yml"));
  EXPECT_TRUE(fs::is_regular_file(expected / rdsf::kDefaultModelName / "v2.yml"));
  EXPECT_TRUE(fs::is_regular_file(expected / rdsf::kDefaultModelName / "v3.yml"));
  EXPECT_TRUE(fs::is_regular_file(expected / rdsf::kDefaultModelName / "v4.yml"));
}

TEST(ShippedModels, DefaultModelResolvesFromAnyWorkingFolder) {
  rdsf::test::TempDir dir;
  const fs::path before = fs::current_path();
  fs::current_path(dir.path());
  std::string resolved;
  EXPECT_NO_THROW(resolved = rdsf::resolve_model(rdsf::kDefaultModelName));
  fs::current_path(before);
  EXPECT_EQ(fs::path(resolved), fs::path(RDSF_SOURCE_DIR) / "models" / rdsf::kDefaultModelName / "v4.yml");  // the newest
}

// NAME/vN too: `--model people/v1` from any folder that has no models/people of its own; a folder that has
// one is never mixed with the shipped models, and a version neither has names both places looked in.
TEST(ShippedModels, NamedVersionResolvesFromAnyWorkingFolder) {
  rdsf::test::TempDir dir;
  const fs::path before = fs::current_path();
  fs::current_path(dir.path());
  const std::string name = rdsf::kDefaultModelName;
  std::string resolved, missing, own;
  EXPECT_NO_THROW(resolved = rdsf::resolve_model(name + "/v1"));
  try {
    rdsf::resolve_model(name + "/v99");
  } catch (const rdsf::Error& e) {
    missing = e.what();
  }
  fs::create_directories(dir.path() / "models" / name);  // a lab's own 'people' models
  try {
    rdsf::resolve_model(name + "/v1");
  } catch (const rdsf::Error& e) {
    own = e.what();
  }
  fs::current_path(before);
  EXPECT_EQ(fs::path(resolved), fs::path(RDSF_SOURCE_DIR) / "models" / name / "v1.yml");
  EXPECT_NE(missing.find("looked for models/" + name + "/v99.yml and "), std::string::npos) << missing;
  EXPECT_NE(missing.find((fs::path(RDSF_SOURCE_DIR) / "models" / name / "v99.yml").string()), std::string::npos) << missing;
  EXPECT_NE(own.find("no such model version (looked for models/" + name + "/v1.yml)"), std::string::npos) << own;
}

#if !RDSF_WITH_OPENNI
// A build without OpenNI2 refuses every OpenNI2 spec with one line naming it; image files still open.
TEST(WithoutOpenNI, OpenNISpecsAreRefusedInOneLine) {
  for (const std::string spec : {"openni", "take.oni", "rdsf-png:///tmp/frames"}) {
    try {
      rdsf::open_frame_source(spec);
      ADD_FAILURE() << spec << " was accepted";
    } catch (const rdsf::Error& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(spec + ": this build has no OpenNI2", 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
}
#endif
