// Every malformed file in tests/data/bad must be rejected with an InputError that names the file,
// the line and the key given on its first line: "# expect: <key> line <N>" (key "-" for TOML
// syntax errors, which name no key). Files with a top-level `kind` key are studies.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "studies/runner/config/input_error.hpp"
#include "studies/runner/config/study_file.hpp"
#include "studies/runner/config/vehicle_file.hpp"

namespace orni::studies {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMinimumBadFiles = 18;

fs::path badDir() { return fs::path(ORNI_SOURCE_DIR) / "tests" / "data" / "bad"; }

std::vector<std::string> badFiles() {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(badDir(), ec))
    if (e.path().extension() == ".toml") names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

/// True when a `kind = ...` line comes before the first table header (same rule as
/// tests/regression/bad_inputs.sh).
bool isStudy(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  const std::regex kind(R"(^\s*kind\s*=)"), header(R"(^\s*\[)");
  while (std::getline(in, line)) {
    if (std::regex_search(line, header)) return false;
    if (std::regex_search(line, kind)) return true;
  }
  return false;
}

class ConfigBadInput : public ::testing::TestWithParam<std::string> {};

TEST(ConfigBadInputs, FolderHasEnoughFiles) { EXPECT_GE(badFiles().size(), kMinimumBadFiles); }

TEST_P(ConfigBadInput, RejectedWithFileLineAndKey) {
  const fs::path file = badDir() / GetParam();
  std::ifstream in(file);
  std::string first;
  std::getline(in, first);
  std::smatch m;
  ASSERT_TRUE(std::regex_match(first, m, std::regex(R"(# expect: (\S+) line (\d+)\s*)")))
      << "first line must be '# expect: <key> line <N>', got: " << first;
  const std::string key = m[1];
  const int line = std::stoi(m[2]);

  try {
    if (isStudy(file))
      (void)loadStudyFile(file);
    else
      (void)loadVehicleFile(file);
    FAIL() << GetParam() << " was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    SCOPED_TRACE(what);
    EXPECT_NE(what.find(GetParam() + ":" + std::to_string(line) + ":"), std::string::npos);
    EXPECT_EQ(e.line(), line);
    EXPECT_EQ(fs::path(e.file()).filename().string(), GetParam());
    if (key == "-") {
      EXPECT_NE(what.find("TOML syntax error"), std::string::npos);
      EXPECT_TRUE(e.key().empty());
    } else {
      EXPECT_NE(what.find("'" + key + "'"), std::string::npos);
      EXPECT_EQ(e.key(), key);
    }
  }
}

std::string testName(const ::testing::TestParamInfo<std::string>& info) {
  std::string n = fs::path(info.param).stem().string();
  for (char& c : n)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'))) c = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(ConfigBadInputs, ConfigBadInput, ::testing::ValuesIn(badFiles()),
                         testName);

}  // namespace
}  // namespace orni::studies
