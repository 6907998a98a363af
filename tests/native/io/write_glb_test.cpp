#include "io/write_glb.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "geom/error.h"
#include "io/write_test_support.h"
#include "mesh/sample_meshes.h"

namespace trimkit::io {
namespace {

// A JSON value and a strict recursive-descent parser for it (RFC 8259 grammar,
// without \u escapes), enough to check that the GLB's JSON chunk parses.
struct Json {
    enum class Kind { kNull, kBool, kNumber, kString, kArray, kObject } kind = Kind::kNull;
    double number = 0.0;
    std::string text;
    std::vector<std::string> keys;  // object keys, parallel to items
    std::vector<Json> items;        // array elements or object values

    bool has(const std::string& key) const {
        for (const auto& k : keys)
            if (k == key) return true;
        return false;
    }
    const Json& operator[](const std::string& key) const {
        for (std::size_t i = 0; i < keys.size(); ++i)
            if (keys[i] == key) return items[i];
        throw std::out_of_range("JSON object has no key " + key);
    }
    const Json& operator[](std::size_t i) const { return items.at(i); }
    std::size_t as_size() const { return static_cast<std::size_t>(number); }
};

class JsonParser {
public:
    explicit JsonParser(const std::string& s) : s_(s) {}
    Json parse_document() {
        Json v = value();
        skip_space();
        if (pos_ != s_.size()) fail("trailing characters");
        return v;
    }

private:
    [[noreturn]] void fail(const std::string& what) {
        throw std::runtime_error("JSON at " + std::to_string(pos_) + ": " + what);
    }
    void skip_space() {
        while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    }
    void expect(char c) {
        skip_space();
        if (pos_ >= s_.size() || s_[pos_] != c) fail(std::string("expected ") + c);
        ++pos_;
    }
    bool peek(char c) {
        skip_space();
        return pos_ < s_.size() && s_[pos_] == c;
    }
    std::string string() {
        expect('"');
        std::string out;
        while (pos_ < s_.size() && s_[pos_] != '"') {
            if (s_[pos_] == '\\') ++pos_;
            out += s_.at(pos_++);
        }
        expect('"');
        return out;
    }
    Json value() {
        skip_space();
        Json v;
        if (pos_ >= s_.size()) fail("unexpected end");
        const char c = s_[pos_];
        if (c == '{') {
            v.kind = Json::Kind::kObject;
            ++pos_;
            if (!peek('}')) {
                do {
                    v.keys.push_back(string());
                    expect(':');
                    v.items.push_back(value());
                } while (peek(',') && (++pos_, true));
            }
            expect('}');
        } else if (c == '[') {
            v.kind = Json::Kind::kArray;
            ++pos_;
            if (!peek(']')) {
                do v.items.push_back(value());
                while (peek(',') && (++pos_, true));
            }
            expect(']');
        } else if (c == '"') {
            v.kind = Json::Kind::kString;
            v.text = string();
        } else if (s_.compare(pos_, 4, "true") == 0 || s_.compare(pos_, 5, "false") == 0) {
            v.kind = Json::Kind::kBool;
            pos_ += s_[pos_] == 't' ? 4 : 5;
        } else if (s_.compare(pos_, 4, "null") == 0) {
            pos_ += 4;
        } else {
            v.kind = Json::Kind::kNumber;
            const char* start = s_.c_str() + pos_;
            char* end = nullptr;
            v.number = std::strtod(start, &end);
            if (end == start) fail("expected a value");
            pos_ += static_cast<std::size_t>(end - start);
        }
        return v;
    }

    const std::string& s_;
    std::size_t pos_ = 0;
};

// A GLB split into its JSON document and BIN chunk, with the layout checked.
struct Glb {
    Json json;
    std::string bin;
};

Glb read_glb(const std::string& path) {
    const std::string bytes = test::read_bytes(path);
    Glb glb;
    EXPECT_GE(bytes.size(), 20u);
    EXPECT_EQ(bytes.substr(0, 4), "glTF");
    EXPECT_EQ(test::le_u32(bytes, 4), 2u);
    EXPECT_EQ(test::le_u32(bytes, 8), bytes.size()) << "header length = file size";
    const std::uint32_t json_length = test::le_u32(bytes, 12);
    EXPECT_EQ(json_length % 4, 0u);
    EXPECT_EQ(bytes.substr(16, 4), "JSON");
    glb.json = JsonParser(bytes.substr(20, json_length)).parse_document();
    const std::size_t bin_at = 20 + json_length;
    if (bin_at < bytes.size()) {
        EXPECT_EQ(bin_at % 4, 0u);
        const std::uint32_t bin_length = test::le_u32(bytes, bin_at);
        EXPECT_EQ(bin_length % 4, 0u);
        EXPECT_EQ(bytes.substr(bin_at + 4, 4), std::string("BIN\0", 4));
        EXPECT_EQ(bin_at + 8 + bin_length, bytes.size());
        glb.bin = bytes.substr(bin_at + 8, bin_length);
    }
    return glb;
}

// Float k of element i of accessor `a`, read through its buffer view.
float accessor_float(const Glb& glb, const Json& a, std::size_t i, int k, int width) {
    const Json& view = glb.json["bufferViews"][a["bufferView"].as_size()];
    const std::size_t offset = view.has("byteOffset") ? view["byteOffset"].as_size() : 0;
    return test::le_f32(glb.bin, offset + 4 * (width * i + k));
}

TEST(WriteGlb, CubeLayoutJsonAndBinaryDecode) {
    for (double s : {1e-6, 1.0, 1e6}) {
        const mesh::Mesh m = test::cube_mesh(s, Eigen::Vector3d(0.3 * s, -s, 2 * s));
        const std::string path = test::temp_output(".glb");
        write_glb(path, m);
        const Glb glb = read_glb(path);
        const Json& j = glb.json;
        EXPECT_EQ(j["asset"]["version"].text, "2.0");
        const Json& primitive = j["meshes"][0]["primitives"][0];
        EXPECT_EQ(primitive["mode"].number, 4);
        const Json& accessors = j["accessors"];
        const Json& position = accessors[primitive["attributes"]["POSITION"].as_size()];
        const Json& normal = accessors[primitive["attributes"]["NORMAL"].as_size()];
        const Json& texcoord = accessors[primitive["attributes"]["TEXCOORD_0"].as_size()];
        const Json& indices = accessors[primitive["indices"].as_size()];
        EXPECT_EQ(position["count"].as_size(), m.vertex_count());
        EXPECT_EQ(position["componentType"].number, 5126);
        EXPECT_EQ(position["type"].text, "VEC3");
        EXPECT_EQ(normal["count"].as_size(), m.vertex_count());
        EXPECT_EQ(texcoord["type"].text, "VEC2");
        EXPECT_EQ(indices["count"].as_size(), 3 * m.triangle_count());
        EXPECT_EQ(indices["componentType"].number, 5125);
        EXPECT_EQ(j["buffers"][0]["byteLength"].as_size(), glb.bin.size());
        for (const Json& view : j["bufferViews"].items) {
            EXPECT_EQ(view["byteOffset"].as_size() % 4, 0u);
            EXPECT_LE(view["byteOffset"].as_size() + view["byteLength"].as_size(), glb.bin.size());
        }

        Eigen::Vector3f lo = Eigen::Vector3f::Constant(INFINITY), hi = -lo;
        for (std::size_t i = 0; i < m.vertex_count(); ++i) {
            Eigen::Vector3f p, n;
            for (int k = 0; k < 3; ++k) {
                p[k] = accessor_float(glb, position, i, k, 3);
                n[k] = accessor_float(glb, normal, i, k, 3);
            }
            EXPECT_TRUE(p.cast<double>().isApprox(m.positions[i], 1e-7)) << "scale " << s << " vertex " << i;
            EXPECT_EQ(n, m.normals[i].cast<float>());
            EXPECT_EQ(accessor_float(glb, texcoord, i, 0, 2), static_cast<float>(m.uvs[i].x()));
            EXPECT_EQ(accessor_float(glb, texcoord, i, 1, 2), static_cast<float>(1.0 - m.uvs[i].y()));
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        for (int k = 0; k < 3; ++k) {  // min/max must equal the stored floats exactly
            EXPECT_EQ(static_cast<float>(position["min"][k].number), lo[k]);
            EXPECT_EQ(static_cast<float>(position["max"][k].number), hi[k]);
        }
        const Json& index_view = j["bufferViews"][indices["bufferView"].as_size()];
        for (std::size_t t = 0; t < m.triangle_count(); ++t)
            for (int k = 0; k < 3; ++k)
                EXPECT_EQ(test::le_u32(glb.bin, index_view["byteOffset"].as_size() + 4 * (3 * t + k)),
                          static_cast<std::uint32_t>(m.triangles[t][k]));
    }
}

TEST(WriteGlb, JsonChunkPaddedWithSpaces) {
    mesh::Mesh m = test::square_mesh();
    m.uvs.clear();  // vary the JSON length
    for (int trial = 0; trial < 4; ++trial) {
        const std::string path = test::temp_output(".glb");
        write_glb(path, m);
        const std::string bytes = test::read_bytes(path);
        const std::uint32_t json_length = test::le_u32(bytes, 12);
        const std::string json = bytes.substr(20, json_length);
        const std::size_t last = json.find_last_of('}');
        EXPECT_EQ(json.find_first_not_of(' ', last + 1), std::string::npos);
        EXPECT_FALSE(read_glb(path).json["meshes"][0]["primitives"][0]["attributes"].has("TEXCOORD_0"));
        m.positions.push_back(Eigen::Vector3d(0.5, 0.5, 0.0));  // unused vertex: longer counts
        m.normals.push_back(Eigen::Vector3d::UnitZ());
    }
}

TEST(WriteGlb, EmptyMeshGivesEmptyScene) {
    const std::string path = test::temp_output(".glb");
    write_glb(path, mesh::Mesh{});
    const Glb glb = read_glb(path);
    EXPECT_EQ(glb.json["asset"]["version"].text, "2.0");
    EXPECT_FALSE(glb.json.has("meshes"));
    EXPECT_TRUE(glb.bin.empty());
}

// An assembly: two meshes stored once each and placed by three nodes; the empty third
// mesh's node is left out, matrices are written column-major and left out when the identity.
TEST(WriteGlb, InstancesStoreEachMeshOncePlacedByNodes) {
    const mesh::Mesh cube = test::cube_mesh(1.0, Eigen::Vector3d::Zero());
    const mesh::Mesh square = test::square_mesh();
    Eigen::Matrix4d moved = Eigen::Matrix4d::Identity();
    moved.block<3, 1>(0, 3) = Eigen::Vector3d(10, 20, 30);
    Eigen::Matrix4d turned = Eigen::Matrix4d::Identity();
    turned.block<2, 2>(0, 0) << 0, -1, 1, 0;  // a quarter turn about z
    const std::vector<GlbNode> nodes{{0, Eigen::Matrix4d::Identity(), "cube.1"}, {0, moved, "cube.2"},
                                     {2, moved, "nothing"}, {1, turned, ""}};
    const std::string path = test::temp_output(".glb");
    write_glb(path, {cube, square, mesh::Mesh{}}, nodes);
    const Glb glb = read_glb(path);
    const Json& j = glb.json;
    ASSERT_EQ(j["meshes"].items.size(), 2u);
    ASSERT_EQ(j["nodes"].items.size(), 3u);
    ASSERT_EQ(j["scenes"][0]["nodes"].items.size(), 3u);
    EXPECT_EQ(j["nodes"][0]["mesh"].number, 0);
    EXPECT_FALSE(j["nodes"][0].has("matrix"));
    EXPECT_EQ(j["nodes"][0]["name"].text, "cube.1");
    EXPECT_EQ(j["nodes"][1]["mesh"].number, 0);
    for (int k = 0; k < 16; ++k) EXPECT_EQ(j["nodes"][1]["matrix"][k].number, moved(k % 4, k / 4)) << k;
    EXPECT_EQ(j["nodes"][1]["matrix"][12].number, 10);  // translation in the last column
    EXPECT_EQ(j["nodes"][2]["mesh"].number, 1);
    EXPECT_FALSE(j["nodes"][2].has("name"));
    EXPECT_EQ(j["nodes"][2]["matrix"][1].number, 1);  // column 0 = (0, 1, 0, 0)
    // The square's positions are its own, after the cube's in the buffer.
    const Json& position = j["accessors"][j["meshes"][1]["primitives"][0]["attributes"]["POSITION"].as_size()];
    EXPECT_EQ(position["count"].as_size(), square.vertex_count());
    for (std::size_t i = 0; i < square.vertex_count(); ++i)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(accessor_float(glb, position, i, k, 3), static_cast<float>(square.positions[i][k]));
}

TEST(WriteGlb, SingleMeshIsOneNodeWithoutMatrix) {
    const mesh::Mesh cube = test::cube_mesh(1.0, Eigen::Vector3d::Zero());
    const std::string one = test::temp_output(".glb"), placed = test::temp_output(".glb");
    write_glb(one, cube);
    write_glb(placed, {cube}, {GlbNode{}});
    EXPECT_EQ(test::read_bytes(one), test::read_bytes(placed));
    EXPECT_EQ(read_glb(one).json["nodes"].items.size(), 1u);
}

TEST(WriteGlb, BadNodesAreInvalidInput) {
    const mesh::Mesh cube = test::cube_mesh(1.0, Eigen::Vector3d::Zero());
    const std::string path = test::temp_output(".glb");
    EXPECT_THROW(write_glb(path, {cube}, {GlbNode{1}}), geom::InvalidInput);
    GlbNode projective;
    projective.matrix(3, 0) = 1.0;
    EXPECT_THROW(write_glb(path, {cube}, {projective}), geom::InvalidInput);
    GlbNode not_finite;
    not_finite.matrix(0, 3) = NAN;
    EXPECT_THROW(write_glb(path, {cube}, {not_finite}), geom::InvalidInput);
}

}  // namespace
}  // namespace trimkit::io
