// Shared plumbing of the mesh writers (write_obj, write_ply, write_stl,
// write_glb): checks that a mesh fits the float32 formats, and little-endian
// encoding. The files themselves are written through io/output_file.h.
#pragma once

#include <cstdint>
#include <string>

#include "mesh/mesh.h"

namespace trimkit::io {

// Validates `mesh` (mesh::validate) and checks that every position, normal and
// uv fits a float32 (|x| <= FLT_MAX); throws geom::InvalidInput prefixed with
// `writer` ("write_stl: positions[4] = (1e+39, 0, 0) does not fit a float32").
void check_float_mesh(const mesh::Mesh& mesh, const std::string& writer);

// Appends the little-endian bytes of x to `bytes` (independent of the host's order).
void put_u8(std::string& bytes, std::uint8_t x);
void put_u16(std::string& bytes, std::uint16_t x);
void put_u32(std::string& bytes, std::uint32_t x);
void put_i32(std::string& bytes, std::int32_t x);
void put_f32(std::string& bytes, float x);

// Shortest decimal text that reads back as the same double (std::to_chars).
std::string shortest_text(double x);

}  // namespace trimkit::io
