// MeshFile: triangles read from an OBJ, PLY (ascii or binary) or STL (ascii or binary)
// file, for occt_check. Polygons are split into fans; corners with exactly equal
// coordinates are merged into one vertex (so that STL and per-face OBJ vertices share),
// numbered by first use. Normals, UVs, groups and colours are ignored. Throws
// std::runtime_error naming the file and what is wrong.
#pragma once

#include <array>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "triangle_bvh.h"

namespace occt_reference {

struct MeshFile {
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
};

namespace mesh_file_detail {

class Welder {
 public:
  explicit Welder(MeshFile& mesh) : mesh_(mesh) {}
  int operator()(Vec3 p) {
    const auto key = std::make_tuple(p.x, p.y, p.z);
    auto [it, added] = index_.emplace(key, static_cast<int>(mesh_.points.size()));
    if (added) mesh_.points.push_back(p);
    return it->second;
  }

 private:
  MeshFile& mesh_;
  std::map<std::tuple<double, double, double>, int> index_;
};

inline std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Adds the fan of `corners` (vertex indices) as triangles.
inline void add_polygon(MeshFile& mesh, const std::vector<int>& corners) {
  for (std::size_t k = 2; k < corners.size(); ++k)
    mesh.triangles.push_back({corners[0], corners[k - 1], corners[k]});
}

inline MeshFile read_obj(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::vector<Vec3> raw;
  std::vector<std::vector<int>> faces;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.size() < 2) continue;
    if (line[0] == 'v' && line[1] == ' ') {
      Vec3 p;
      if (std::sscanf(line.c_str() + 2, "%lf %lf %lf", &p.x, &p.y, &p.z) != 3)
        throw std::runtime_error(path + ":" + std::to_string(line_number) + ": bad vertex line");
      raw.push_back(p);
    } else if (line[0] == 'f' && line[1] == ' ') {
      std::istringstream tokens(line.substr(2));
      std::string token;
      std::vector<int> corners;
      while (tokens >> token) {
        const long i = std::strtol(token.c_str(), nullptr, 10);  // "i", "i/j", "i//k", "i/j/k"
        const long index = i > 0 ? i - 1 : static_cast<long>(raw.size()) + i;
        if (i == 0 || index < 0 || index >= static_cast<long>(raw.size()))
          throw std::runtime_error(path + ":" + std::to_string(line_number) + ": face index " +
                                   token + " out of range (" + std::to_string(raw.size()) +
                                   " vertices so far)");
        corners.push_back(static_cast<int>(index));
      }
      faces.push_back(std::move(corners));
    }
  }
  MeshFile mesh;
  Welder weld(mesh);
  std::vector<int> id(raw.size());
  for (std::size_t k = 0; k < raw.size(); ++k) id[k] = weld(raw[k]);
  for (auto& corners : faces) {
    for (int& c : corners) c = id[c];
    add_polygon(mesh, corners);
  }
  return mesh;
}

// PLY: header, then elements in order. Supports ascii, binary_little_endian and
// binary_big_endian; vertex x/y/z of any scalar type; face list "vertex_indices" or
// "vertex_index"; other elements and properties are skipped.
inline MeshFile read_ply(const std::string& path) {
  const std::string bytes = read_all(path);
  const std::size_t header_end = bytes.find("end_header");
  if (bytes.compare(0, 3, "ply") != 0 || header_end == std::string::npos)
    throw std::runtime_error(path + ": not a PLY file (no 'ply' ... 'end_header')");
  struct Property {
    std::string name, type, count_type;  // count_type set for lists
  };
  struct Element {
    std::string name;
    long count = 0;
    std::vector<Property> properties;
  };
  std::vector<Element> elements;
  std::string format;
  std::istringstream header(bytes.substr(0, header_end));
  std::string line;
  while (std::getline(header, line)) {
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "format") {
      words >> format;
    } else if (word == "element") {
      Element e;
      words >> e.name >> e.count;
      elements.push_back(e);
    } else if (word == "property" && !elements.empty()) {
      Property p;
      words >> p.type;
      if (p.type == "list") words >> p.count_type >> p.type;
      words >> p.name;
      elements.back().properties.push_back(p);
    }
  }
  std::size_t pos = bytes.find('\n', header_end);
  if (pos == std::string::npos) throw std::runtime_error(path + ": PLY header not terminated");
  ++pos;
  const bool ascii = format == "ascii";
  const bool big = format == "binary_big_endian";
  if (!ascii && !big && format != "binary_little_endian")
    throw std::runtime_error(path + ": PLY format '" + format + "' not supported");

  std::istringstream text(ascii ? bytes.substr(pos) : std::string());
  const auto size_of = [&](const std::string& t) -> int {
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
    if (t == "double" || t == "float64") return 8;
    throw std::runtime_error(path + ": PLY property type '" + t + "' not supported");
  };
  const auto value = [&](const std::string& t) -> double {
    if (ascii) {
      double v;
      if (!(text >> v)) throw std::runtime_error(path + ": PLY data ends early");
      return v;
    }
    const int n = size_of(t);
    if (pos + n > bytes.size()) throw std::runtime_error(path + ": PLY data ends early");
    unsigned char b[8];
    for (int k = 0; k < n; ++k) b[k] = static_cast<unsigned char>(bytes[pos + (big ? n - 1 - k : k)]);
    pos += n;
    if (t == "char" || t == "int8") return static_cast<std::int8_t>(b[0]);
    if (t == "uchar" || t == "uint8") return b[0];
    if (t == "short" || t == "int16") { std::int16_t v; std::memcpy(&v, b, 2); return v; }
    if (t == "ushort" || t == "uint16") { std::uint16_t v; std::memcpy(&v, b, 2); return v; }
    if (t == "int" || t == "int32") { std::int32_t v; std::memcpy(&v, b, 4); return v; }
    if (t == "uint" || t == "uint32") { std::uint32_t v; std::memcpy(&v, b, 4); return v; }
    if (t == "float" || t == "float32") { float v; std::memcpy(&v, b, 4); return v; }
    double v;
    std::memcpy(&v, b, 8);
    return v;
  };

  std::vector<Vec3> raw;
  std::vector<std::vector<int>> faces;
  for (const Element& e : elements) {
    for (long i = 0; i < e.count; ++i) {
      Vec3 p;
      std::vector<int> corners;
      for (const Property& prop : e.properties) {
        if (!prop.count_type.empty()) {
          const long n = static_cast<long>(value(prop.count_type));
          for (long k = 0; k < n; ++k) {
            const double v = value(prop.type);
            if (e.name == "face" && (prop.name == "vertex_indices" || prop.name == "vertex_index"))
              corners.push_back(static_cast<int>(v));
          }
          continue;
        }
        const double v = value(prop.type);
        if (e.name == "vertex") {
          if (prop.name == "x") p.x = v;
          else if (prop.name == "y") p.y = v;
          else if (prop.name == "z") p.z = v;
        }
      }
      if (e.name == "vertex") raw.push_back(p);
      else if (e.name == "face") faces.push_back(std::move(corners));
    }
  }
  MeshFile mesh;
  Welder weld(mesh);
  std::vector<int> id(raw.size());
  for (std::size_t k = 0; k < raw.size(); ++k) id[k] = weld(raw[k]);
  for (auto& corners : faces) {
    for (int& c : corners) {
      if (c < 0 || c >= static_cast<int>(raw.size()))
        throw std::runtime_error(path + ": PLY face index " + std::to_string(c) + " out of range");
      c = id[c];
    }
    add_polygon(mesh, corners);
  }
  return mesh;
}

inline MeshFile read_stl(const std::string& path) {
  const std::string bytes = read_all(path);
  MeshFile mesh;
  Welder weld(mesh);
  if (bytes.size() >= 84) {
    std::uint32_t count;
    std::memcpy(&count, bytes.data() + 80, 4);
    if (bytes.size() == 84 + 50ull * count) {
      for (std::uint32_t t = 0; t < count; ++t) {
        const char* facet = bytes.data() + 84 + 50ull * t + 12;  // after the normal
        std::array<int, 3> tri;
        for (int k = 0; k < 3; ++k) {
          float xyz[3];
          std::memcpy(xyz, facet + 12 * k, 12);
          tri[k] = weld({xyz[0], xyz[1], xyz[2]});
        }
        mesh.triangles.push_back(tri);
      }
      return mesh;
    }
  }
  std::istringstream text(bytes);
  std::string word;
  std::vector<int> corners;
  while (text >> word) {
    if (word == "vertex") {
      Vec3 p;
      if (!(text >> p.x >> p.y >> p.z)) throw std::runtime_error(path + ": bad STL vertex");
      corners.push_back(weld(p));
    } else if (word == "endloop") {
      add_polygon(mesh, corners);
      corners.clear();
    }
  }
  if (mesh.triangles.empty()) throw std::runtime_error(path + ": no STL triangles");
  return mesh;
}

}  // namespace mesh_file_detail

// Reads `path` by its extension (.obj, .ply, .stl, any case).
inline MeshFile read_mesh_file(const std::string& path) {
  const std::string ext = mesh_file_detail::lower(path.substr(path.find_last_of('.') + 1));
  if (ext == "obj") return mesh_file_detail::read_obj(path);
  if (ext == "ply") return mesh_file_detail::read_ply(path);
  if (ext == "stl") return mesh_file_detail::read_stl(path);
  throw std::runtime_error(path + ": unknown mesh extension '." + ext + "' (expected .obj, .ply or .stl)");
}

}  // namespace occt_reference
