// Where the GoogleTest suite finds ../shared/data; tests skip with a message when it is absent.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <random>
#include <string>

#include "vistrack/error.hpp"

namespace vistrack::testing {

// A fresh folder under the system temp directory (never the repo or the data folder).
class TempDir {
 public:
  TempDir() {
    std::random_device device;
    path_ = std::filesystem::temp_directory_path() / ("vistrack_test_" + std::to_string(device()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string write(const std::string& name, const std::string& text) const {
    const std::filesystem::path file = path_ / name;
    std::ofstream(file, std::ios::binary) << text;
    return file.string();
  }
  std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

// Runs f, expecting vistrack::Error whose message contains every fragment.
template <class F>
void expect_error(F&& f, std::initializer_list<std::string> fragments) {
  try {
    f();
    ADD_FAILURE() << "expected vistrack::Error";
  } catch (const Error& error) {
    const std::string message = error.what();
    for (const std::string& fragment : fragments)
      EXPECT_NE(message.find(fragment), std::string::npos) << "message: " << message << "\nmissing: " << fragment;
  }
}

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
