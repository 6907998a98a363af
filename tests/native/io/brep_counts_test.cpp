// io/brep_counts.h on .brep texts written here in Open CASCADE's format: counts the
// file can hold pass, a count above the tokens left is a ReadError on its own line,
// and an item the walk does not know stops the walk instead of misreading what follows.
#include <gtest/gtest.h>

#include <string>

#include "geom/error.h"
#include "io/brep_counts.h"

namespace trimkit::io {
namespace {

// A header, one B-spline curve of degree 1 with `poles` poles over two knots, and a
// triangulation of `nodes` nodes and `triangles` triangles (only the first three
// nodes and one triangle written).
std::string brep_text(const std::string& poles, const std::string& nodes, const std::string& triangles,
                      const std::string& curve_type = "7") {
    return "DBRep_DrawableShape\n\nCASCADE Topology V1, (c) Matra-Datavision\n"
           "Locations 0\nCurve2ds 0\nCurves 1\n" +
           curve_type + " 0 0 1 " + poles + " 2\n0 0 0 10 0 0\n0 2 1 2\n"
           "Polygon3D 0\nPolygonOnTriangulations 0\nSurfaces 1\n1 0 0 0 0 0 1 1 0 0 0 1 0\n"
           "Triangulations 1\n" + nodes + " " + triangles + " 0 0.1\n0 0 0 1 0 0 0 1 0\n1 2 3\n"
           "TShapes 0\n";
}

// The ReadError check_brep_counts throws for `text`; a test failure (and an error with
// no line or reason) when it throws none.
geom::ReadError counts_error(const std::string& text, const std::string& name) {
    try {
        check_brep_counts(text, name);
    } catch (const geom::ReadError& e) {
        return e;
    }
    ADD_FAILURE() << name << ": no error";
    return geom::ReadError(name, -1, "");
}

TEST(BrepCounts, CountsTheFileHoldsPass) {
    EXPECT_NO_THROW(check_brep_counts(brep_text("2", "3", "1"), "ok.brep"));
}

TEST(BrepCounts, TooManyPolesIsAnErrorOnTheirLine) {
    const geom::ReadError e = counts_error(brep_text("2000000000", "3", "1"), "poles.brep");
    EXPECT_EQ(e.line(), 7);  // the curve's line
    EXPECT_NE(e.reason().find("2000000000"), std::string::npos) << e.what();
    EXPECT_NE(e.reason().find("Curves"), std::string::npos) << e.what();
}

TEST(BrepCounts, TooManyTrianglesIsAnErrorOnTheirLine) {
    const geom::ReadError e = counts_error(brep_text("2", "3", "2000000000"), "triangles.brep");
    EXPECT_EQ(e.line(), 15);  // the triangulation's header
    EXPECT_NE(e.reason().find("Triangulations"), std::string::npos) << e.what();
}

TEST(BrepCounts, ANegativeCountIsAnError) {
    EXPECT_THROW(check_brep_counts(brep_text("2", "-3", "1"), "negative.brep"), geom::ReadError);
}

TEST(BrepCounts, AnUnknownItemStopsItsSectionsWalk) {
    // Curve type 42 is not OCCT's: its section is not walked, so the pole count is
    // never read as one; the triangulation after it is still checked.
    EXPECT_NO_THROW(check_brep_counts(brep_text("2000000000", "3", "1", "42"), "unknown.brep"));
    EXPECT_THROW(check_brep_counts(brep_text("2000000000", "3", "2000000000", "42"), "unknown.brep"),
                 geom::ReadError);
}

}  // namespace
}  // namespace trimkit::io
