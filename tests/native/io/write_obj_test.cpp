#include "io/write_obj.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <vector>

#include "geom/error.h"
#include "io/write_test_support.h"
#include "mesh/sample_meshes.h"

namespace trimkit::io {
namespace {

// What an OBJ file holds, parsed back with numbers as doubles.
struct ObjContents {
    std::vector<Eigen::Vector3d> v, vn;
    std::vector<Eigen::Vector2d> vt;
    std::vector<std::array<std::array<int, 3>, 3>> f;  // per corner: v, vt, vn (0 if absent)
    std::vector<std::string> groups, materials, mtllib;
};

ObjContents parse_obj(const std::string& path) {
    ObjContents obj;
    std::istringstream in(test::read_bytes(path));
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string key;
        words >> key;
        if (key == "v" || key == "vn") {
            Eigen::Vector3d p;
            words >> p.x() >> p.y() >> p.z();
            (key == "v" ? obj.v : obj.vn).push_back(p);
        } else if (key == "vt") {
            Eigen::Vector2d uv;
            words >> uv.x() >> uv.y();
            obj.vt.push_back(uv);
        } else if (key == "f") {
            std::array<std::array<int, 3>, 3> face{};
            for (auto& corner : face) {
                std::string token;
                words >> token;
                std::size_t start = 0;
                for (int k = 0; k < 3 && start <= token.size(); ++k) {
                    const std::size_t slash = std::min(token.find('/', start), token.size());
                    if (slash > start) corner[k] = std::stoi(token.substr(start, slash - start));
                    start = slash + 1;
                }
            }
            obj.f.push_back(face);
        } else if (key == "g" || key == "usemtl" || key == "mtllib") {
            std::string name;
            words >> name;
            (key == "g" ? obj.groups : key == "usemtl" ? obj.materials : obj.mtllib).push_back(name);
        }
    }
    return obj;
}

TEST(WriteObj, CubeReadsBackExactly) {
    const mesh::Mesh m = test::cube_mesh(0.1, Eigen::Vector3d(1.0 / 3.0, -2e6, 7e-7));
    const std::string path = test::temp_output(".obj");
    write_obj(path, m);
    const ObjContents obj = parse_obj(path);
    ASSERT_EQ(obj.v.size(), m.vertex_count());
    ASSERT_EQ(obj.vt.size(), m.vertex_count());
    ASSERT_EQ(obj.vn.size(), m.vertex_count());
    ASSERT_EQ(obj.f.size(), m.triangle_count());
    for (std::size_t i = 0; i < m.vertex_count(); ++i) {
        EXPECT_EQ(obj.v[i], m.positions[i]) << "v " << i;  // shortest round-trip text
        EXPECT_EQ(obj.vt[i], m.uvs[i]) << "vt " << i;
        EXPECT_EQ(obj.vn[i], m.normals[i]) << "vn " << i;
    }
    for (std::size_t t = 0; t < m.triangle_count(); ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(obj.f[t][k], (std::array<int, 3>{m.triangles[t][k] + 1, m.triangles[t][k] + 1,
                                                       m.triangles[t][k] + 1}));
    EXPECT_EQ(obj.groups, (std::vector<std::string>{"face_0", "face_1", "face_2", "face_3",
                                                    "face_4", "face_5"}));
    EXPECT_TRUE(obj.materials.empty());
}

TEST(WriteObj, WithoutUvsOrNormalsUsesShorterFaceForms) {
    mesh::Mesh m = test::square_mesh();
    m.uvs.clear();
    const std::string path = test::temp_output(".obj");
    write_obj(path, m);
    EXPECT_NE(test::read_bytes(path).find("\nf 1//1 2//2 3//3\n"), std::string::npos);
    m.normals.clear();
    m.face_ids.clear();
    write_obj(path, m);
    const std::string text = test::read_bytes(path);
    EXPECT_NE(text.find("\nf 1 3 4\n"), std::string::npos) << text;
    EXPECT_EQ(text.find("\ng "), std::string::npos) << "no groups without face ids";
    EXPECT_EQ(parse_obj(path).vt.size(), 0u);
}

TEST(WriteObj, MaterialsFromFaceColours) {
    mesh::Mesh m = test::cube_mesh();
    m.face_colors[4] = m.face_colors[0];  // two faces share red
    const std::string path = test::temp_output(".obj");
    write_obj(path, m, {/*face_groups=*/false, /*materials=*/true});
    const ObjContents obj = parse_obj(path);
    const std::string mtl_path = std::filesystem::path(path).replace_extension(".mtl").string();
    EXPECT_EQ(obj.mtllib, (std::vector<std::string>{std::filesystem::path(mtl_path).filename().string()}));
    EXPECT_TRUE(obj.groups.empty());
    EXPECT_EQ(obj.materials, (std::vector<std::string>{"color_FF0000", "color_00FF00", "color_0000FF",
                                                       "color_FFFF00", "color_FF0000", "color_FF00FF"}));
    const std::string mtl = test::read_bytes(mtl_path);
    std::size_t count = 0;
    for (std::size_t at = mtl.find("newmtl "); at != std::string::npos; at = mtl.find("newmtl ", at + 1))
        ++count;
    EXPECT_EQ(count, 5u);
    EXPECT_NE(mtl.find("newmtl color_FFFF00\nKd 1 1 0\n"), std::string::npos) << mtl;
}

TEST(WriteObj, RejectsInvalidMeshNamingTheWriter) {
    mesh::Mesh m = test::square_mesh();
    m.triangles[0][1] = 9;
    try {
        write_obj(test::temp_output(".obj"), m);
        ADD_FAILURE() << "write_obj accepted an index out of range";
    } catch (const geom::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("write_obj: Mesh: triangles[0][1] = 9"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace trimkit::io
