// Helpers for the mesh writer tests: a per-test temporary file path and whole-file
// reads, plus little-endian decoding of what the binary writers produced.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace trimkit::test {

// A path in the system temp folder named after the running test, e.g.
// /tmp/trimkit_WriteObj_CubeRoundTrips.obj; any old file there is removed.
inline std::string temp_output(const std::string& extension) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path p = std::filesystem::temp_directory_path() /
        ("trimkit_" + std::string(info->test_suite_name()) + "_" + info->name() + extension);
    std::filesystem::remove(p);
    return p.string();
}

inline std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline std::uint32_t le_u32(const std::string& bytes, std::size_t offset) {
    std::uint32_t x = 0;
    for (int k = 3; k >= 0; --k) x = (x << 8) | static_cast<unsigned char>(bytes.at(offset + k));
    return x;
}

inline std::uint16_t le_u16(const std::string& bytes, std::size_t offset) {
    return static_cast<std::uint16_t>(static_cast<unsigned char>(bytes.at(offset)) |
                                      static_cast<unsigned char>(bytes.at(offset + 1)) << 8);
}

inline std::int32_t le_i32(const std::string& bytes, std::size_t offset) {
    return static_cast<std::int32_t>(le_u32(bytes, offset));
}

inline float le_f32(const std::string& bytes, std::size_t offset) {
    const std::uint32_t bits = le_u32(bytes, offset);
    float x;
    std::memcpy(&x, &bits, sizeof x);
    return x;
}

}  // namespace trimkit::test
