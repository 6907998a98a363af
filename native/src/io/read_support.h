// Shared plumbing of the mesh readers (read_ply, read_obj, read_stl, read_glb) and
// the .brep reader: whole-file reads, a bounds-checked little-endian cursor over
// bytes, and the final validation that turns a bad mesh into a ReadError naming the file.
#pragma once

#include <cstdint>
#include <string>

#include "mesh/mesh.h"

namespace trimkit::io {

// Files larger than this are refused before reading (4 GiB: the glb limit and
// far above any mesh trimkit writes or .brep it reads).
constexpr std::uint64_t kMaxMeshFileBytes = 4ull << 30;

// The bytes of `path`; ReadError(path, 0, ...) if it cannot be opened or read.
std::string read_file_bytes(const std::string& path);

// Reads little-endian values from [begin, end) of a byte string; every read is
// bounds-checked and throws ReadError(file, 0, "truncated ...") past the end.
class ByteCursor {
public:
    ByteCursor(const std::string& bytes, std::size_t begin, std::size_t end, const std::string& file)
        : bytes_(bytes), pos_(begin), end_(end), file_(file) {}

    std::size_t position() const { return pos_; }
    std::size_t remaining() const { return end_ - pos_; }
    void skip(std::size_t n, const char* what);
    std::uint8_t u8(const char* what);
    std::uint16_t u16(const char* what);
    std::uint32_t u32(const char* what);
    std::int32_t i32(const char* what) { return static_cast<std::int32_t>(u32(what)); }
    float f32(const char* what);
    double f64(const char* what);
    std::uint64_t u64(const char* what);

private:
    void need(std::size_t n, const char* what) const;

    const std::string& bytes_;
    std::size_t pos_, end_;
    const std::string& file_;
};

// Renormalises normals (float32 files store them rounded; other tools may not
// normalise them) and drops them all if one is zero; then runs mesh::validate and
// rethrows its InvalidInput as ReadError(file, 0, reason).
void finish_read_mesh(mesh::Mesh& mesh, const std::string& file);

}  // namespace trimkit::io
