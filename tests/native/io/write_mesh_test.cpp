#include "io/write_mesh.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "geom/error.h"
#include "io/write_test_support.h"
#include "mesh/sample_meshes.h"

namespace trimkit::io {
namespace {

TEST(WriteMesh, ChoosesFormatByExtension) {
    const mesh::Mesh m = test::cube_mesh();
    const std::string obj = test::temp_output(".obj");
    write_mesh(obj, m);
    EXPECT_EQ(test::read_bytes(obj).substr(0, 13), "# trimkit OBJ");
    const std::string ply = test::temp_output(".ply");
    write_mesh(ply, m);
    EXPECT_EQ(test::read_bytes(ply).substr(0, 4), "ply\n");
    const std::string stl = test::temp_output(".STL");  // extensions are case-insensitive
    write_mesh(stl, m);
    EXPECT_EQ(test::read_bytes(stl).size(), 84 + 50 * m.triangle_count());
    const std::string glb = test::temp_output(".glb");
    write_mesh(glb, m);
    EXPECT_EQ(test::read_bytes(glb).substr(0, 4), "glTF");
}

TEST(WriteMesh, UnknownExtensionIsInvalidInput) {
    const std::string path = test::temp_output(".xyz");
    try {
        write_mesh(path, test::cube_mesh());
        ADD_FAILURE() << "write_mesh accepted .xyz";
    } catch (const geom::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("unknown mesh format '.xyz'"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(path));
    EXPECT_THROW(write_mesh(test::temp_output(""), test::cube_mesh()), geom::InvalidInput);
}

TEST(WriteMesh, UnwritablePathIsRuntimeErrorNamingThePath) {
    const std::string path =
        (std::filesystem::temp_directory_path() / "trimkit_no_such_dir" / "sub" / "out.stl").string();
    for (const char* ext : {".obj", ".ply", ".stl", ".glb"}) {
        const std::string p = std::filesystem::path(path).replace_extension(ext).string();
        try {
            write_mesh(p, test::cube_mesh());
            ADD_FAILURE() << "wrote " << p;
        } catch (const geom::InvalidInput& e) {
            ADD_FAILURE() << "expected a runtime error, got InvalidInput: " << e.what();
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(p + ": cannot open for writing"), std::string::npos)
                << e.what();
        }
    }
}

}  // namespace
}  // namespace trimkit::io
