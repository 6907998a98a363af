// Helpers shared by the native tests: the CAD sample folder, temporary paths and
// finiteness checks.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <Eigen/Core>

namespace trimkit::test {

// Path of a file under ../shared/data/cad (e.g. "iges/bearing.iges"), or empty
// if the folder is absent; use TRIMKIT_CAD_SAMPLE to skip with the reason.
inline std::string cad_sample(const std::string& relative) {
    std::filesystem::path p = std::filesystem::path(TRIMKIT_CAD_DIR) / relative;
    return std::filesystem::exists(p) ? p.string() : std::string();
}

// A path in the system's temporary folder, "trimkit_" + name (names are per case: ctest
// runs cases in parallel processes).
inline std::string temp_path(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("trimkit_" + name)).string();
}

template <class Derived>
::testing::AssertionResult is_finite(const Eigen::MatrixBase<Derived>& m) {
    if (m.allFinite()) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "non-finite value in " << m.transpose();
}

}  // namespace trimkit::test

// Declares `var` as the sample's path or skips the test, naming what is missing.
#define TRIMKIT_CAD_SAMPLE(var, relative)                                        \
    const std::string var = ::trimkit::test::cad_sample(relative);               \
    if (var.empty()) GTEST_SKIP() << "CAD sample " << relative << " not found under " \
                                  << TRIMKIT_CAD_DIR << " (../shared/data/cad)"
