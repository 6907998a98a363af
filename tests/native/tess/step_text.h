// Hand-written STEP text for the own reader's tests: reals with all their digits, a
// Part 21 file around one face, and a cylinder with its two end circles.
#pragma once

#include <cstdio>
#include <string>

namespace trimkit::test {

// A STEP real with all its digits.
inline std::string step_real(double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17E", x);
    return buffer;
}

// A whole Part 21 file around `data`, one OPEN_SHELL of the ADVANCED_FACE #64 in a
// millimetre part (the product structure OCCT's reader transfers from; ids from 9001).
inline std::string step_file(const std::string& data) {
    return "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\nFILE_NAME('t.stp','',(''),(''),'','','');\n"
           "FILE_SCHEMA(('AUTOMOTIVE_DESIGN'));\nENDSEC;\nDATA;\n" +
           data +
           "#65=OPEN_SHELL('',(#64));\n#66=SHELL_BASED_SURFACE_MODEL('',(#65));\n"
           "#99=(GEOMETRIC_REPRESENTATION_CONTEXT(2) PARAMETRIC_REPRESENTATION_CONTEXT() "
           "REPRESENTATION_CONTEXT('2D SPACE',''));\n"
           "#9001=APPLICATION_CONTEXT('automotive design');\n#9002=PRODUCT_CONTEXT('',#9001,'mechanical');\n"
           "#9003=PRODUCT('p','p','',(#9002));\n#9004=PRODUCT_DEFINITION_CONTEXT('part definition',#9001,'design');\n"
           "#9005=PRODUCT_DEFINITION_FORMATION('','',#9003);\n#9006=PRODUCT_DEFINITION('design','',#9005,#9004);\n"
           "#9007=PRODUCT_DEFINITION_SHAPE('','',#9006);\n#9008=(LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.));\n"
           "#9009=(NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.));\n"
           "#9010=(NAMED_UNIT(*) SI_UNIT($,.STERADIAN.) SOLID_ANGLE_UNIT());\n"
           "#9011=UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),#9008,'distance_accuracy_value','');\n"
           "#9012=(GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#9011)) "
           "GLOBAL_UNIT_ASSIGNED_CONTEXT((#9008,#9009,#9010)) REPRESENTATION_CONTEXT('',''));\n"
           "#9013=MANIFOLD_SURFACE_SHAPE_REPRESENTATION('',(#66),#9012);\n"
           "#9014=SHAPE_DEFINITION_REPRESENTATION(#9007,#9013);\nENDSEC;\nEND-ISO-10303-21;\n";
}

// The cylinder #5 of radius r about z, its bottom circle #8 and top circle #9 (height
// h), the 2D unit vectors #31 (along u) and #33 (along v), a 3D unit vector #10 along z.
inline std::string cylinder_entities(double r, double h) {
    return "#1=CARTESIAN_POINT('',(0.,0.,0.));\n#2=DIRECTION('',(0.,0.,1.));\n#3=DIRECTION('',(1.,0.,0.));\n"
           "#4=AXIS2_PLACEMENT_3D('',#1,#2,#3);\n#5=CYLINDRICAL_SURFACE('',#4," + step_real(r) + ");\n"
           "#6=CARTESIAN_POINT('',(0.,0.," + step_real(h) + "));\n#7=AXIS2_PLACEMENT_3D('',#6,#2,#3);\n"
           "#8=CIRCLE('',#4," + step_real(r) + ");\n#9=CIRCLE('',#7," + step_real(r) + ");\n#10=VECTOR('',#2,1.);\n"
           "#30=DIRECTION('',(1.,0.));\n#31=VECTOR('',#30,1.);\n#32=DIRECTION('',(0.,1.));\n#33=VECTOR('',#32,1.);\n";
}

}  // namespace trimkit::test
