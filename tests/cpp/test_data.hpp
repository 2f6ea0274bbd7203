// Where the GoogleTest suite finds ../shared/data; tests skip with a message when it is absent.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace vistrack::testing {

inline std::string shared_data_dir() {
  if (const char* env = std::getenv("VISTRACK_DATA")) return env;
  return VISTRACK_SHARED_DATA;
}

// Full path of a file under the data folder, or an empty string when the folder is absent.
inline std::string shared_data(const std::string& relative) {
  const std::filesystem::path path = std::filesystem::path(shared_data_dir()) / relative;
  return std::filesystem::exists(path) ? path.string() : std::string();
}

}  // namespace vistrack::testing

// Skips the current test when a data file is missing.
#define VISTRACK_REQUIRE_DATA(var, relative)                                              \
  const std::string var = ::vistrack::testing::shared_data(relative);                    \
  if (var.empty()) GTEST_SKIP() << "real data not found: " << relative                   \
                                << " under " << ::vistrack::testing::shared_data_dir()   \
                                << " (set VISTRACK_DATA or place ../shared/data)"
