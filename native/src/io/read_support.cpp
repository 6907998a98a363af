#include "io/read_support.h"

#include <cmath>
#include <cstring>
#include <fstream>

#include "geom/error.h"

namespace trimkit::io {

std::string read_file_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) throw geom::ReadError(path, 0, "cannot open for reading");
    const std::streamoff size = in.tellg();
    if (size < 0) throw geom::ReadError(path, 0, "cannot determine the file size");
    if (static_cast<std::uint64_t>(size) > kMaxMeshFileBytes)
        throw geom::ReadError(path, 0, std::to_string(size) + " bytes; files are limited to " +
                                           std::to_string(kMaxMeshFileBytes) + " bytes");
    std::string bytes(static_cast<std::size_t>(size), '\0');
    in.seekg(0);
    if (size > 0 && !in.read(bytes.data(), size)) throw geom::ReadError(path, 0, "read failed");
    return bytes;
}

void ByteCursor::need(std::size_t n, const char* what) const {
    if (n > end_ - pos_)
        throw geom::ReadError(file_, 0, std::string("truncated: ") + what + " needs " +
                                            std::to_string(n) + " bytes at offset " +
                                            std::to_string(pos_) + ", " +
                                            std::to_string(end_ - pos_) + " left");
}

void ByteCursor::skip(std::size_t n, const char* what) {
    need(n, what);
    pos_ += n;
}

std::uint8_t ByteCursor::u8(const char* what) {
    need(1, what);
    return static_cast<std::uint8_t>(bytes_[pos_++]);
}

std::uint16_t ByteCursor::u16(const char* what) {
    need(2, what);
    const auto* b = reinterpret_cast<const unsigned char*>(bytes_.data() + pos_);
    pos_ += 2;
    return static_cast<std::uint16_t>(b[0] | (b[1] << 8));
}

std::uint32_t ByteCursor::u32(const char* what) {
    need(4, what);
    const auto* b = reinterpret_cast<const unsigned char*>(bytes_.data() + pos_);
    pos_ += 4;
    return static_cast<std::uint32_t>(b[0]) | static_cast<std::uint32_t>(b[1]) << 8 |
           static_cast<std::uint32_t>(b[2]) << 16 | static_cast<std::uint32_t>(b[3]) << 24;
}

std::uint64_t ByteCursor::u64(const char* what) {
    const std::uint64_t lo = u32(what);
    const std::uint64_t hi = u32(what);
    return lo | hi << 32;
}

float ByteCursor::f32(const char* what) {
    const std::uint32_t bits = u32(what);
    float x;
    std::memcpy(&x, &bits, sizeof x);
    return x;
}

double ByteCursor::f64(const char* what) {
    const std::uint64_t bits = u64(what);
    double x;
    std::memcpy(&x, &bits, sizeof x);
    return x;
}

void finish_read_mesh(mesh::Mesh& mesh, const std::string& file) {
    for (auto& n : mesh.normals) {
        const double length = n.norm();
        if (!(length > 0.0) || !std::isfinite(length)) {
            mesh.normals.clear();
            break;
        }
        n /= length;
    }
    try {
        mesh::validate(mesh);
    } catch (const geom::InvalidInput& e) {
        throw geom::ReadError(file, 0, e.what());
    }
}

}  // namespace trimkit::io
