#include "geom/select_faces.h"

#include <gtest/gtest.h>

#include "geom/analytic_surfaces.h"
#include "geom/error.h"
#include "geom/flatten_instances.h"

namespace trimkit::geom {
namespace {

Model three_planes() {
    Model m;
    for (int k = 0; k < 3; ++k) {
        Face f;
        f.surface = plane_patch(Eigen::Vector3d(0, 0, k), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 0, 1, 0, 1);
        f.loops = {natural_boundary_loop(f.surface)};
        f.name = "plane " + std::to_string(k);
        m.faces.push_back(f);
    }
    m.bodies.push_back({"pair", {0, 2}, false});
    m.free_faces = {1};
    return m;
}

TEST(SelectFaces, KeepsTheListedFacesInOrderAsFreeFaces) {
    const Model part = select_faces(three_planes(), {2, 0});
    ASSERT_EQ(part.faces.size(), 2u);
    EXPECT_EQ(part.faces[0].name, "plane 2");
    EXPECT_EQ(part.faces[1].name, "plane 0");
    EXPECT_TRUE(part.bodies.empty());
    EXPECT_EQ(part.free_faces, (std::vector<int>{0, 1}));
    EXPECT_THROW(select_faces(three_planes(), {3}), InvalidInput);
    EXPECT_THROW(select_faces(three_planes(), {1, 1}), InvalidInput);
}

TEST(FlattenInstances, CopiesEachInstancedBodyIntoPlace) {
    Model m = three_planes();
    EXPECT_EQ(flatten_instances(m).faces.size(), 3u);  // no instances: unchanged
    Eigen::Affine3d up = Eigen::Affine3d::Identity();
    up.translate(Eigen::Vector3d(0, 0, 10));
    m.instances = {{0, Eigen::Affine3d::Identity(), "a"}, {0, up, "b"}};
    const Model flat = flatten_instances(m);
    ASSERT_EQ(flat.faces.size(), 5u);  // the free face, then 2 x the pair
    EXPECT_EQ(flat.faces[0].name, "plane 1");
    EXPECT_EQ(flat.free_faces, (std::vector<int>{0}));
    ASSERT_EQ(flat.bodies.size(), 2u);
    EXPECT_EQ(flat.bodies[1].name, "b");
    EXPECT_EQ(flat.bodies[1].faces, (std::vector<int>{3, 4}));
    EXPECT_TRUE(flat.faces[4].surface.evaluate(0, 0).isApprox(Eigen::Vector3d(0, 0, 12)));
}

}  // namespace
}  // namespace trimkit::geom
