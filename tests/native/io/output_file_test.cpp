#include "io/output_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "io/write_mesh.h"
#include "io/write_test_support.h"
#include "mesh/sample_meshes.h"

namespace trimkit::io {
namespace {

namespace fs = std::filesystem;

void write_text(const std::string& path, const std::string& text) {
    OutputFile out(path);
    out.write(text);
    out.commit();
}

// Files in the folder of `path` whose names start with its name and ".partial-".
int leftover_partials(const std::string& path) {
    const fs::path p(path);
    const std::string prefix = p.filename().string() + ".partial-";
    int count = 0;
    for (const fs::directory_entry& entry : fs::directory_iterator(p.parent_path()))
        if (entry.path().filename().string().rfind(prefix, 0) == 0) ++count;
    return count;
}

TEST(OutputFile, CommitReplacesTheTargetAndLeavesNoTemporaryFile) {
    const std::string path = test::temp_output(".txt");
    write_text(path, "old");
    write_text(path, "new contents");
    EXPECT_EQ(test::read_bytes(path), "new contents");
    EXPECT_EQ(leftover_partials(path), 0);
}

TEST(OutputFile, TargetKeepsItsOldContentsUntilCommit) {
    const std::string path = test::temp_output(".txt");
    write_text(path, "old");
    OutputFile out(path);
    out.write("half of the new");
    out.stream().flush();
    EXPECT_NE(out.temporary_path(), path);
    EXPECT_EQ(fs::path(out.temporary_path()).parent_path(), fs::path(path).parent_path());
    EXPECT_EQ(test::read_bytes(path), "old");
    EXPECT_EQ(test::read_bytes(out.temporary_path()), "half of the new");
    out.commit();
    EXPECT_EQ(test::read_bytes(path), "half of the new");
}

TEST(OutputFile, AnInterruptedWriteLeavesTheOldFileAndRemovesTheTemporary) {
    const std::string path = test::temp_output(".txt");
    write_text(path, "the good file");
    std::string temporary;
    try {
        OutputFile out(path);
        temporary = out.temporary_path();
        out.write("the first half of a");
        throw std::runtime_error("interrupted");  // as a writer that fails half-way
    } catch (const std::runtime_error&) {
    }
    EXPECT_EQ(test::read_bytes(path), "the good file");
    EXPECT_FALSE(fs::exists(temporary)) << temporary;
    EXPECT_EQ(leftover_partials(path), 0);
}

TEST(OutputFile, MeshWriterThatFailsKeepsTheOldMesh) {
    const std::string path = test::temp_output(".stl");
    write_mesh(path, test::cube_mesh());
    const std::string good = test::read_bytes(path);
    mesh::Mesh broken = test::cube_mesh();
    broken.triangles[0][0] = 1000;  // out of range: the writer refuses the mesh
    EXPECT_ANY_THROW(write_mesh(path, broken));
    EXPECT_EQ(test::read_bytes(path), good);
    EXPECT_EQ(leftover_partials(path), 0);
}

TEST(OutputFile, NonRegularTargetIsWrittenInPlace) {
    ASSERT_TRUE(fs::is_character_file("/dev/null"));
    {
        OutputFile out("/dev/null");
        EXPECT_EQ(out.temporary_path(), "/dev/null");
        out.write("discarded");
        out.commit();
    }
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(OutputFile, FailedWriteIsRuntimeErrorNamingThePath) {
    if (!fs::is_character_file("/dev/full")) GTEST_SKIP() << "/dev/full is absent";
    OutputFile out("/dev/full");
    out.write(std::string(1 << 16, 'x'));
    try {
        out.commit();
        ADD_FAILURE() << "wrote to /dev/full";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/dev/full: write failed"), std::string::npos) << e.what();
    }
}

TEST(OutputFile, MissingFolderIsRuntimeErrorNamingThePath) {
    const std::string path = (fs::temp_directory_path() / "trimkit_no_such_dir" / "out.txt").string();
    try {
        OutputFile out(path);
        ADD_FAILURE() << "opened " << path;
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path + ": cannot open for writing"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace trimkit::io
