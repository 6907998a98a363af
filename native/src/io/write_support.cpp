#include "io/write_support.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "geom/error.h"

namespace trimkit::io {
namespace {

template <class Vector>
void check_fits(const std::vector<Vector>& values, const char* array, const std::string& writer) {
    constexpr double kMax = std::numeric_limits<float>::max();
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (values[i].cwiseAbs().maxCoeff() <= kMax) continue;
        std::string text = "(";
        for (Eigen::Index k = 0; k < values[i].size(); ++k)
            text += (k > 0 ? ", " : "") + geom::format_value(values[i][k]);
        throw geom::InvalidInput(writer + ": " + array + "[" + std::to_string(i) + "] = " + text +
                                 ") does not fit a float32");
    }
}

}  // namespace

void check_float_mesh(const mesh::Mesh& mesh, const std::string& writer) {
    try {
        mesh::validate(mesh);
    } catch (const geom::InvalidInput& e) {
        throw geom::InvalidInput(writer + ": " + e.what());
    }
    check_fits(mesh.positions, "positions", writer);
    check_fits(mesh.uvs, "uvs", writer);
}

void put_u8(std::string& bytes, std::uint8_t x) { bytes.push_back(static_cast<char>(x)); }

void put_u16(std::string& bytes, std::uint16_t x) {
    bytes.push_back(static_cast<char>(x & 0xFF));
    bytes.push_back(static_cast<char>(x >> 8));
}

void put_u32(std::string& bytes, std::uint32_t x) {
    for (int shift = 0; shift < 32; shift += 8) bytes.push_back(static_cast<char>((x >> shift) & 0xFF));
}

void put_i32(std::string& bytes, std::int32_t x) { put_u32(bytes, static_cast<std::uint32_t>(x)); }

void put_f32(std::string& bytes, float x) {
    std::uint32_t bits;
    static_assert(sizeof bits == sizeof x, "float must be 32-bit IEEE 754");
    std::memcpy(&bits, &x, sizeof bits);
    put_u32(bytes, bits);
}

std::string shortest_text(double x) {
    char buf[32];
    const auto result = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, result.ptr);
}

}  // namespace trimkit::io
