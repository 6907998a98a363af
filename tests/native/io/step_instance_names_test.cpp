// check_step_instance_names: a STEP text that defines an entity name twice is refused
// with the line of the second definition (before Open CASCADE, whose transfer can
// recurse without end on such a file: fuzz finding 9); names elsewhere on a line,
// references and blanks before a name are read as Part 21 means them.
#include "io/step_instance_names.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "geom/error.h"

namespace trimkit::io {
namespace {

void check(const std::string& text) {
    std::istringstream in(text);
    check_step_instance_names(in, "t.stp");
}

// The ReadError check() throws on `text` (a failure and an empty error if none).
geom::ReadError error_of(const std::string& text) {
    try {
        check(text);
    } catch (const geom::ReadError& e) {
        return e;
    }
    ADD_FAILURE() << "no ReadError";
    return geom::ReadError("", 0, "");
}

const std::string kHeader =
    "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('a #9 = b'),'2;1');\nENDSEC;\nDATA;\n";  // lines 1-5

TEST(StepInstanceNames, EachNameOnceIsAccepted) {
    EXPECT_NO_THROW(check(kHeader +
                          "#1 = CARTESIAN_POINT('',(0.,0.,0.));\n"
                          "  #2=DIRECTION('#1 = not a definition',(0.,0.,1.));\n"
                          "#3 = AXIS2_PLACEMENT_3D('',#1,#2,$);\n"
                          "#12\t=( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) );\n"
                          "ENDSEC;\nEND-ISO-10303-21;\n"));
}

TEST(StepInstanceNames, SecondDefinitionIsNamedWithItsLine) {
    const std::string text = kHeader +
                             "#1 = CARTESIAN_POINT('',(0.,0.,0.));\n"  // line 6
                             "#2 = DIRECTION('',(0.,0.,1.));\n"        // line 7
                             "   #1 = CARTESIAN_POINT('',(1.,0.,0.));\n"  // line 8
                             "ENDSEC;\n";
    const geom::ReadError e = error_of(text);
    EXPECT_EQ(e.file(), "t.stp");
    EXPECT_EQ(e.line(), 8);
    EXPECT_NE(e.reason().find("entity #1 is defined twice (first on line 6)"), std::string::npos) << e.what();
}

// The fuzzer's file: a string broken by control characters and a line break in the
// header, so a statement-by-statement reading would be out of step for the rest; the
// names at the lines' starts are still read.
TEST(StepInstanceNames, DamagedStringDoesNotHideALaterDuplicate) {
    const std::string text = std::string("ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('STEP \x12\0\0,\n", 51) +
                             "    '1' );\nENDSEC;\nDATA;\n"  // lines 4-6
                             "#44 = PRODUCT_DEFINITION_SHAPE('','',#117);\n"  // line 7
                             "#45 = PRODUCT_DEFINITION_SHAPE('','',#116);\n"
                             "#44 = PRODUCT_DEFINITION_SHAPE('','',#117);\n"  // line 9
                             "ENDSEC;\n";
    const geom::ReadError e = error_of(text);
    EXPECT_EQ(e.line(), 9);
    EXPECT_NE(e.reason().find("#44"), std::string::npos) << e.what();
}

// The earliest second definition is the one reported; names of 19 digits and more are
// not names (left to OCCT's parser), so they are not compared.
TEST(StepInstanceNames, EarliestDuplicateIsReported) {
    const std::string text = kHeader +
                             "#7 = A();\n#8 = B();\n#8 = C();\n#7 = D();\n"  // lines 6-9
                             "#1234567890123456789 = E();\n#1234567890123456789 = F();\n";
    const geom::ReadError e = error_of(text);
    EXPECT_EQ(e.line(), 8);
    EXPECT_NE(e.reason().find("entity #8 is defined twice (first on line 7)"), std::string::npos) << e.what();
    EXPECT_NO_THROW(check(kHeader + "#1234567890123456789 = E();\n#1234567890123456789 = F();\n"));
}

}  // namespace
}  // namespace trimkit::io
