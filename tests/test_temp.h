// Temporary files of the tests: under a directory of the test process's own.  CTest runs
// every test in its own process, so two tests, or two runs of the suite on one machine at
// once, never write the same file.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace mirage::testing {

/// `name` in this process's temporary directory (made on first use).
inline std::filesystem::path test_temp_path(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) /
                                      ("mirage_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir / name;
}

}  // namespace mirage::testing
