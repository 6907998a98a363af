// Lexical and syntactic layer of STEP Part 21: every value kind, complex instances,
// string escapes, comments, typed values, nesting, editions' sections, errors with
// their lines, hostile names, CRLF text, the deadline, and a shared sample file whose
// type counts are derived from its text independently of the parser.
#include "io/step_part21.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cctype>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "geom/error.h"
#include "mesh/deadline.h"
#include "test_support.h"

namespace trimkit::io {
namespace {

using Kind = StepValue::Kind;

// A header of 7 lines: the first instance of `data` is on line kFirstDataLine.
const std::string kHeader =
    "ISO-10303-21;\n"
    "HEADER;\n"
    "FILE_DESCRIPTION(('trimkit test'),'2;1');\n"
    "FILE_NAME('t.stp','2024-01-01T00:00:00',('author'),('org'),'pre','system','');\n"
    "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\n"
    "ENDSEC;\n"
    "DATA;\n";
constexpr int kFirstDataLine = 8;

std::string part21(const std::string& data) { return kHeader + data + "ENDSEC;\nEND-ISO-10303-21;\n"; }

StepPart21 parse(const std::string& text) { return StepPart21::parse(text, "t.stp"); }

// The parameters of the only record of instance #id.
const std::vector<StepValue>& params(const StepPart21& f, long long id) {
    const StepInstance* instance = f.find(id);
    EXPECT_NE(instance, nullptr) << "#" << id;
    EXPECT_EQ(instance->records.size(), 1u);
    return instance->records.at(0).params;
}

// Parses `text`, expecting a ReadError on `line` whose reason contains `words`.
void expect_read_error(const std::string& text, int line, const std::string& words) {
    try {
        parse(text);
        ADD_FAILURE() << "no ReadError; expected line " << line << ": " << words;
    } catch (const geom::ReadError& e) {
        EXPECT_EQ(e.file(), "t.stp");
        EXPECT_EQ(e.line(), line) << e.what();
        EXPECT_NE(e.reason().find(words), std::string::npos) << e.what();
    }
}

TEST(StepPart21, SimpleInstanceHoldsEveryValueKind) {
    const StepPart21 f = parse(part21(
        "#1=TEST_ENTITY($,*,42,-7,+3,1.5,-2.5E-3,1.E-07,'text',.FORWARD.,#12,(1,2.,'a'),"
        "LENGTH_MEASURE(1.5),\"0FF\",.t.,());\n"));
    ASSERT_EQ(f.instances().size(), 1u);
    const StepInstance& instance = f.instances()[0];
    EXPECT_EQ(instance.id, 1);
    EXPECT_EQ(instance.line, kFirstDataLine);
    ASSERT_EQ(instance.records.size(), 1u);
    EXPECT_EQ(instance.records[0].type, "TEST_ENTITY");
    const std::vector<StepValue>& p = instance.records[0].params;
    ASSERT_EQ(p.size(), 16u);
    EXPECT_EQ(p[0].kind, Kind::kUnset);
    EXPECT_EQ(p[1].kind, Kind::kDerived);
    EXPECT_EQ(p[2].kind, Kind::kInteger);
    EXPECT_EQ(p[2].integer, 42);
    EXPECT_EQ(p[2].real, 42.0);
    EXPECT_EQ(p[3].integer, -7);
    EXPECT_EQ(p[3].real, -7.0);
    EXPECT_EQ(p[4].integer, 3);
    EXPECT_EQ(p[5].kind, Kind::kReal);
    EXPECT_EQ(p[5].real, 1.5);
    EXPECT_EQ(p[6].real, -2.5e-3);
    EXPECT_EQ(p[7].kind, Kind::kReal);
    EXPECT_EQ(p[7].real, 1e-7);
    EXPECT_EQ(p[8].kind, Kind::kString);
    EXPECT_EQ(p[8].text, "text");
    EXPECT_EQ(p[9].kind, Kind::kEnum);
    EXPECT_EQ(p[9].text, "FORWARD");
    EXPECT_EQ(p[10].kind, Kind::kReference);
    EXPECT_EQ(p[10].integer, 12);
    ASSERT_EQ(p[11].kind, Kind::kList);
    ASSERT_EQ(p[11].items.size(), 3u);
    EXPECT_EQ(p[11].items[0].kind, Kind::kInteger);
    EXPECT_EQ(p[11].items[1].kind, Kind::kReal);
    EXPECT_EQ(p[11].items[1].real, 2.0);
    EXPECT_EQ(p[11].items[2].text, "a");
    EXPECT_EQ(p[12].kind, Kind::kTyped);
    EXPECT_EQ(p[12].text, "LENGTH_MEASURE");
    ASSERT_EQ(p[12].items.size(), 1u);
    EXPECT_EQ(p[12].items[0].real, 1.5);
    EXPECT_EQ(p[13].kind, Kind::kBinary);
    EXPECT_EQ(p[13].text, "0FF");
    EXPECT_EQ(p[14].kind, Kind::kEnum);
    EXPECT_EQ(p[14].text, "T");  // lower case made upper
    EXPECT_EQ(p[15].kind, Kind::kList);
    EXPECT_TRUE(p[15].items.empty());
    // #12 is not defined: not an error at this layer.
    EXPECT_EQ(f.find(12), nullptr);
}

TEST(StepPart21, NumbersAtTheEdgesOfTheirTypes) {
    const StepPart21 f = parse(part21(
        "#1=R(1.E-400,-1.E-400,4.9E-324,1.7976931348623157E308,.5,-.25E1,1E3,9223372036854775807,"
        "-9223372036854775807,0.000000000000000000000000000000000000000000000000000000000000000000000001);\n"));
    const std::vector<StepValue>& p = params(f, 1);
    ASSERT_EQ(p.size(), 10u);
    EXPECT_EQ(p[0].real, 0.0);  // underflow reads as zero
    EXPECT_EQ(p[1].real, 0.0);
    EXPECT_GT(p[2].real, 0.0);  // the smallest denormal
    EXPECT_EQ(p[3].real, std::numeric_limits<double>::max());
    EXPECT_EQ(p[4].real, 0.5);  // lenient forms: no leading digit, no '.'
    EXPECT_EQ(p[5].real, -2.5);
    EXPECT_EQ(p[6].kind, Kind::kReal);
    EXPECT_EQ(p[6].real, 1000.0);
    EXPECT_EQ(p[7].kind, Kind::kInteger);
    EXPECT_EQ(p[7].integer, std::numeric_limits<long long>::max());
    EXPECT_EQ(p[8].integer, -std::numeric_limits<long long>::max());
    EXPECT_EQ(p[9].real, 1e-72);
}

TEST(StepPart21, HeaderAndSchemasAreKept) {
    const StepPart21 f = parse(part21("#1=A();\n"));
    EXPECT_EQ(f.name(), "t.stp");
    ASSERT_EQ(f.header().size(), 3u);
    EXPECT_EQ(f.header()[0].type, "FILE_DESCRIPTION");
    EXPECT_EQ(f.header()[1].type, "FILE_NAME");
    ASSERT_EQ(f.header()[1].params.size(), 7u);
    EXPECT_EQ(f.header()[1].params[0].text, "t.stp");
    EXPECT_EQ(f.header()[2].type, "FILE_SCHEMA");
    ASSERT_EQ(f.schemas().size(), 1u);
    EXPECT_EQ(f.schemas()[0], "AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }");
    EXPECT_TRUE(params(f, 1).empty());
}

TEST(StepPart21, ComplexInstanceRecordsAreFoundByType) {
    // A rational B-spline surface as OCCT and most writers put it: partial records in
    // alphabetical order, the supertypes' empty records included.
    const StepPart21 f = parse(part21(
        "#5=CARTESIAN_POINT('',(0.,0.,0.));\n"
        "#10=( BOUNDED_SURFACE() B_SPLINE_SURFACE(1,1,((#1,#2),(#3,#4)),.UNSPECIFIED.,.F.,.F.,.F.)\n"
        "  B_SPLINE_SURFACE_WITH_KNOTS((2,2),(2,2),(0.,1.),(0.,1.),.UNSPECIFIED.)\n"
        "  GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_SURFACE(((1.,0.5),(0.5,2.)))\n"
        "  REPRESENTATION_ITEM('') SURFACE() );\n"));
    const StepInstance* s = f.find(10);
    ASSERT_NE(s, nullptr);
    EXPECT_EQ(s->line, kFirstDataLine + 1);
    ASSERT_EQ(s->records.size(), 7u);
    const std::vector<std::string> order = {"BOUNDED_SURFACE",
                                            "B_SPLINE_SURFACE",
                                            "B_SPLINE_SURFACE_WITH_KNOTS",
                                            "GEOMETRIC_REPRESENTATION_ITEM",
                                            "RATIONAL_B_SPLINE_SURFACE",
                                            "REPRESENTATION_ITEM",
                                            "SURFACE"};
    for (std::size_t k = 0; k < order.size(); ++k) EXPECT_EQ(s->records[k].type, order[k]);
    EXPECT_TRUE(s->record("BOUNDED_SURFACE")->params.empty());

    const StepRecord* surface = s->record("B_SPLINE_SURFACE");
    ASSERT_NE(surface, nullptr);
    ASSERT_EQ(surface->params.size(), 7u);
    EXPECT_EQ(surface->params[0].integer, 1);
    const StepValue& poles = surface->params[2];
    ASSERT_EQ(poles.items.size(), 2u);
    EXPECT_EQ(poles.items[1].items[0].kind, Kind::kReference);
    EXPECT_EQ(poles.items[1].items[0].integer, 3);

    const StepRecord* knots = s->record("B_SPLINE_SURFACE_WITH_KNOTS");
    ASSERT_NE(knots, nullptr);
    EXPECT_EQ(knots->params[2].items[1].real, 1.0);

    const StepRecord* rational = s->record("RATIONAL_B_SPLINE_SURFACE");
    ASSERT_NE(rational, nullptr);
    ASSERT_EQ(rational->params.size(), 1u);
    const StepValue& w = rational->params[0];
    ASSERT_EQ(w.items.size(), 2u);
    EXPECT_EQ(w.items[0].items[1].real, 0.5);
    EXPECT_EQ(w.items[1].items[1].real, 2.0);
    EXPECT_EQ(s->record("PLANE"), nullptr);

    // Each partial record's type indexes the instance.
    ASSERT_EQ(f.of_type("RATIONAL_B_SPLINE_SURFACE").size(), 1u);
    EXPECT_EQ(f.of_type("RATIONAL_B_SPLINE_SURFACE")[0], s);
    EXPECT_EQ(f.of_type("surface").size(), 1u);  // queries are made upper case
    EXPECT_EQ(f.of_type("CARTESIAN_POINT").size(), 1u);
    EXPECT_TRUE(f.of_type("PLANE").empty());
}

TEST(StepPart21, StringsAreDecodedToUtf8) {
    const StepPart21 f = parse(part21(
        "#1=S('it''s','''','',"
        "'caf\\X2\\00E9\\X0\\','\\X\\E9t\\X\\E9','\\X4\\0001F600\\X0\\','\\X2\\D83DDE00\\X0\\',"
        "'\\S\\a','\\PA\\x','back\\\\slash','C:\\temp','\\X2\\00E\\X0\\','\\X2\\0041004200430044\\X0\\');\n"));
    const std::vector<StepValue>& p = params(f, 1);
    ASSERT_EQ(p.size(), 13u);
    EXPECT_EQ(p[0].text, "it's");
    EXPECT_EQ(p[1].text, "'");
    EXPECT_EQ(p[2].text, "");
    EXPECT_EQ(p[3].text, "caf\xC3\xA9");                 // U+00E9
    EXPECT_EQ(p[4].text, "\xC3\xA9t\xC3\xA9");           // 8-bit \X\hh as ISO 8859-1
    EXPECT_EQ(p[5].text, "\xF0\x9F\x98\x80");            // U+1F600 from \X4\ ...
    EXPECT_EQ(p[6].text, "\xF0\x9F\x98\x80");            // ... and from a \X2\ surrogate pair
    EXPECT_EQ(p[7].text, "\xC3\xA1");                    // \S\a: 'a' + 128 = U+00E1
    EXPECT_EQ(p[8].text, "x");                           // \PA\ dropped
    EXPECT_EQ(p[9].text, "back\\slash");
    EXPECT_EQ(p[10].text, "C:\\temp");                   // no directive: the backslash stays
    EXPECT_EQ(p[11].text, "\\X2\\00E\\X0\\");            // malformed \X2\: kept as written
    EXPECT_EQ(p[12].text, "ABCD");
}

TEST(StepPart21, LineBreaksInsideStringsAreDropped) {
    // Writers wrap long lines inside strings (screw.step: 'Undefined De' / 'scription').
    const StepPart21 f = parse(part21("#1=S('Undefined De\nscription','a''\n''b');\n#2=T();\n"));
    EXPECT_EQ(params(f, 1)[0].text, "Undefined Description");
    EXPECT_EQ(params(f, 1)[1].text, "a''b");
    EXPECT_EQ(f.find(2)->line, kFirstDataLine + 3);
}

TEST(StepPart21, CommentsMayStandBetweenAnyTokens) {
    const std::string text =
        "/* before */ ISO-10303-21 /* a */ ;\n"
        "HEADER; /* ; ) ' */\n"
        "FILE_DESCRIPTION(/* x */('d'),'2;1');\n"
        "ENDSEC;\n"
        "DATA;\n"
        "/* a comment\n   over two lines with #9=X(); inside */\n"
        "#1 /*c*/ = /*c*/ A /*c*/ ( /*c*/ 1 /*c*/ , /*c*/ ( 2 /*c*/ ) /*c*/ ) /*c*/ ;\n"
        "#2=B('/* not a comment */',*/**/);\n"
        "#3=(C()/*c*/D(.X./**/));\n"
        "ENDSEC; /* trailing */\n"
        "END-ISO-10303-21;\n";
    const StepPart21 f = parse(text);
    ASSERT_EQ(f.instances().size(), 3u);
    EXPECT_EQ(f.find(9), nullptr);
    EXPECT_EQ(f.find(1)->line, 8);
    const std::vector<StepValue>& a = params(f, 1);
    ASSERT_EQ(a.size(), 2u);
    EXPECT_EQ(a[0].integer, 1);
    EXPECT_EQ(a[1].items.at(0).integer, 2);
    EXPECT_EQ(params(f, 2)[0].text, "/* not a comment */");
    EXPECT_EQ(params(f, 2)[1].kind, Kind::kDerived);
    ASSERT_EQ(f.find(3)->records.size(), 2u);
    EXPECT_EQ(f.find(3)->record("D")->params.at(0).text, "X");
}

TEST(StepPart21, TypedValuesHoldOneValueOfAnyKind) {
    const StepPart21 f = parse(part21(
        "#1=MEASURE_REPRESENTATION_ITEM('',POSITIVE_LENGTH_MEASURE(2.5),#2);\n"
        "#2=X((LENGTH_MEASURE(1.),plane_angle_measure(0.5)),A(B(3)),LIST_TYPE((1,2)),D ( 'x' ),E(.T.));\n"));
    EXPECT_EQ(params(f, 1)[1].kind, Kind::kTyped);
    EXPECT_EQ(params(f, 1)[1].items.at(0).real, 2.5);
    const std::vector<StepValue>& p = params(f, 2);
    ASSERT_EQ(p.size(), 5u);
    EXPECT_EQ(p[0].items.at(1).text, "PLANE_ANGLE_MEASURE");
    EXPECT_EQ(p[0].items.at(1).items.at(0).real, 0.5);
    EXPECT_EQ(p[1].text, "A");
    EXPECT_EQ(p[1].items.at(0).kind, Kind::kTyped);
    EXPECT_EQ(p[1].items.at(0).text, "B");
    EXPECT_EQ(p[1].items.at(0).items.at(0).integer, 3);
    ASSERT_EQ(p[2].items.size(), 1u);
    EXPECT_EQ(p[2].items[0].kind, Kind::kList);
    EXPECT_EQ(p[2].items[0].items.size(), 2u);
    EXPECT_EQ(p[3].items.at(0).text, "x");
    EXPECT_EQ(p[4].items.at(0).text, "T");
}

TEST(StepPart21, ListsNestToTheLimitAndNoFurther) {
    auto nested = [](int depth) {
        return "#2=N(" + std::string(depth, '(') + "7" + std::string(depth, ')') + ");\n";
    };
    const StepPart21 f = parse(part21(nested(StepPart21::kMaxNesting)));
    const StepValue* v = &params(f, 2).at(0);
    int depth = 0;
    while (v->kind == Kind::kList) {
        ASSERT_EQ(v->items.size(), 1u);
        v = &v->items[0];
        ++depth;
    }
    EXPECT_EQ(depth, StepPart21::kMaxNesting);
    EXPECT_EQ(v->integer, 7);
    expect_read_error(part21("#1=A();\n" + nested(StepPart21::kMaxNesting + 1)), kFirstDataLine + 1,
                      "nested deeper than 64");
    // Typed values count as a level: they recurse the same way.
    std::string typed = "#1=N(";
    for (int k = 0; k < StepPart21::kMaxNesting + 1; ++k) typed += "T(";
    typed += "1" + std::string(StepPart21::kMaxNesting + 1, ')') + ");\n";
    expect_read_error(part21(typed), kFirstDataLine, "nested deeper than 64");
    // A hostile depth far beyond the limit ends at the limit, without deep recursion.
    expect_read_error(part21(std::string("#1=N(") + std::string(1000000, '(')), kFirstDataLine,
                      "nested deeper than 64");
}

TEST(StepPart21, DuplicateInstanceNamesAreErrors) {
    expect_read_error(part21("#1=A();\n#44=B();\n#2=C();\n#44=D();\n"), kFirstDataLine + 3,
                      "entity #44 is defined twice (first on line 9)");
    // Across DATA sections too: names are unique in the whole exchange structure.
    expect_read_error(kHeader + "#7=A();\nENDSEC;\nDATA;\n#7=A();\nENDSEC;\nEND-ISO-10303-21;\n",
                      kFirstDataLine + 3, "entity #7 is defined twice (first on line 8)");
}

TEST(StepPart21, UnterminatedTokensNameTheLineWhereTheyOpen) {
    expect_read_error(part21("#1=A();\n#2=B('no end);\n#3=C();\n"), kFirstDataLine + 1, "unterminated string");
    expect_read_error(part21("#1=A();\n/* no end\n#2=B();\n"), kFirstDataLine + 1, "unterminated comment");
    expect_read_error(kHeader + "#1=A();\n#2=B((1,2),\n(3,", kFirstDataLine + 2, "unterminated list");
    expect_read_error(kHeader + "#1=A();\n#2=(B() C()", kFirstDataLine + 1, "unterminated complex instance");
    expect_read_error(kHeader + "#1=A();\n", kFirstDataLine - 1, "DATA section has no ENDSEC");
    expect_read_error(kHeader + "#1=A();\nENDSEC;\n", kFirstDataLine + 2, "no 'END-ISO-10303-21;'");
    expect_read_error("ISO-10303-21;\nHEADER;\nFILE_NAME('x');\n", 2, "HEADER section has no ENDSEC");
    expect_read_error(part21("#1=A(\"0F);\n"), kFirstDataLine, "malformed binary value");
    expect_read_error(part21("#1=A(.FORWARD);\n"), kFirstDataLine, "malformed enumeration");
}

TEST(StepPart21, MissingSectionsAreErrors) {
    expect_read_error("ISO-10303-21;\nHEADER;\nFILE_NAME('x');\nENDSEC;\nEND-ISO-10303-21;\n", 5,
                      "no DATA section");
    expect_read_error("ISO-10303-21;\nHEADER;\nFILE_NAME('x');\nENDSEC;\n", 5, "no DATA section");
    expect_read_error("", 1, "not a STEP file");
    expect_read_error("\n\nISO-10303-22;\n", 3, "not a STEP file");
    expect_read_error("ISO-10303-21;\nDATA;\n#1=A();\nENDSEC;\n", 2, "expected 'HEADER;'");
    expect_read_error("ISO-10303-21\nHEADER;\n", 2, "expected ';' after ISO-10303-21");
}

TEST(StepPart21, GarbageTokensAreErrorsOnTheirLine) {
    expect_read_error(part21("#1=A();\n#2=B(1,?);\n"), kFirstDataLine + 1, "unexpected '?'");
    expect_read_error(part21("#1=A();\n#2=B(1 2);\n"), kFirstDataLine + 1, "expected ',' or ')'");
    expect_read_error(part21("#1=A();\n#2=B(1)\n#3=C();\n"), kFirstDataLine + 2, "expected ';' after instance #2");
    expect_read_error(part21("#1=A();\nB();\n"), kFirstDataLine + 1, "expected an entity instance");
    expect_read_error(part21("#1 A();\n"), kFirstDataLine, "expected '=' after #1");
    expect_read_error(part21("#1=;\n"), kFirstDataLine, "expected an entity record");
    expect_read_error(part21("#1=A(1.E);\n"), kFirstDataLine, "no exponent digits");
    expect_read_error(part21("#1=A(-);\n"), kFirstDataLine, "malformed number");
    expect_read_error(part21("#1=A(B);\n"), kFirstDataLine, "expected '(' after B");
    expect_read_error(part21("#1=A(B(1,2));\n"), kFirstDataLine, "typed value B has 2 values, expected 1");
    expect_read_error(part21("#1=A(B());\n"), kFirstDataLine, "typed value B has 0 values, expected 1");
    expect_read_error(part21("#1=A(99999999999999999999);\n"), kFirstDataLine, "integer");
    expect_read_error(part21("#1=A(1.E999);\n"), kFirstDataLine, "real '1.E999' is out of range");
    expect_read_error(part21("#1=A(#PI);\n"), kFirstDataLine, "constant names are not supported");
    expect_read_error(part21("#1=A(#12B);\n"), kFirstDataLine, "malformed instance name");
    expect_read_error(part21(std::string("#1=A(\x01);\n")), kFirstDataLine, "unexpected byte 0x01");
}

TEST(StepPart21, InstanceNamesOutOfRangeAreErrors) {
    expect_read_error(part21("#0=A();\n"), kFirstDataLine, "out of range");
    expect_read_error(part21("#1000000000000000000=A();\n"), kFirstDataLine, "out of range");
    expect_read_error(part21("#1=A(#99999999999999999999999999);\n"), kFirstDataLine, "out of range");
    // The largest name, and leading zeros that do not count as digits.
    const StepPart21 f = parse(part21("#999999999999999999=A(#0000000000000000000000005);\n"));
    EXPECT_NE(f.find(StepPart21::kMaxInstanceId), nullptr);
    EXPECT_EQ(params(f, StepPart21::kMaxInstanceId)[0].integer, 5);
}

TEST(StepPart21, NamesAbove2To31AreFoundByHash) {
    const StepPart21 f = parse(part21(
        "#3000000000=A(#9000000000000);\n#9000000000000=B(#3000000000);\n#2147483648=C();\n#9000000=D();\n"));
    ASSERT_NE(f.find(3000000000LL), nullptr);
    EXPECT_EQ(f.find(3000000000LL)->records[0].type, "A");
    EXPECT_EQ(params(f, 3000000000LL)[0].integer, 9000000000000LL);
    EXPECT_EQ(f.find(9000000000000LL)->line, kFirstDataLine + 1);
    EXPECT_EQ(params(f, 9000000000000LL)[0].integer, 3000000000LL);
    EXPECT_NE(f.find(2147483648LL), nullptr);
    EXPECT_NE(f.find(9000000), nullptr);
    EXPECT_EQ(f.find(2147483647LL), nullptr);
    EXPECT_EQ(f.find(-1), nullptr);
    EXPECT_EQ(f.find(0), nullptr);
}

TEST(StepPart21, ManyNamesSpacedByPowersOfTwoAreAllFound) {
    // Names a naive "id mod capacity" table would pile into one slot.
    std::string data;
    constexpr int kCount = 5000;
    for (long long k = 1; k <= kCount; ++k) data += "#" + std::to_string(k << 24) + "=P(" + std::to_string(k) + ");\n";
    const StepPart21 f = parse(part21(data));
    ASSERT_EQ(f.instances().size(), static_cast<std::size_t>(kCount));
    for (long long k = 1; k <= kCount; ++k) {
        const StepInstance* instance = f.find(k << 24);
        ASSERT_NE(instance, nullptr) << k;
        EXPECT_EQ(instance->line, kFirstDataLine + static_cast<int>(k) - 1);
        EXPECT_EQ(instance->records[0].params[0].integer, k);
    }
    EXPECT_EQ(f.of_type("P").size(), static_cast<std::size_t>(kCount));
}

// `text` with every "\n" made "\r\n".
std::string crlf(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '\n') out += '\r';
        out += c;
    }
    return out;
}

TEST(StepPart21, CrlfLineEndsGiveTheSameValuesAndLines) {
    const StepPart21 f = parse(crlf(part21(
        "#1=A('x',1.5);\n"
        "#2=B('wrapped\nstring',(#1,\n#3));\n"
        "#3=(C() D(2));\n")));
    ASSERT_EQ(f.instances().size(), 3u);
    EXPECT_EQ(f.find(1)->line, kFirstDataLine);
    EXPECT_EQ(f.find(2)->line, kFirstDataLine + 1);
    EXPECT_EQ(f.find(3)->line, kFirstDataLine + 4);
    EXPECT_EQ(params(f, 1)[0].text, "x");
    EXPECT_EQ(params(f, 1)[1].real, 1.5);
    EXPECT_EQ(params(f, 2)[0].text, "wrappedstring");
    EXPECT_EQ(params(f, 2)[1].items.at(1).integer, 3);
    EXPECT_EQ(f.find(3)->record("D")->params.at(0).integer, 2);
    expect_read_error(crlf(part21("#1=A('a\nb');\n#2=B(?);\n")), kFirstDataLine + 2, "unexpected '?'");
}

TEST(StepPart21, SeveralDataSectionsAndSkippedSections) {
    // Edition 3: named DATA sections, ANCHOR, REFERENCE and SIGNATURE sections.
    const std::string text =
        "\xEF\xBB\xBFISO-10303-21;\n"
        "HEADER;\nFILE_SCHEMA(('A_SCHEMA','B_SCHEMA'));\nENDSEC;\n"
        "ANCHOR;\n<first> = #1;\n<uri/*not a comment*/> = 'ENDSEC;';\nENDSEC;\n"
        "REFERENCE;\n#100 = <http://example.com/part.stp#12>;\nENDSEC;\n"
        "DATA('first',('A_SCHEMA'));\n#1=A(#2);\nENDSEC;\n"
        "DATA('second',('B_SCHEMA'));\n#2=B(#1);\nENDSEC;\n"
        "SIGNATURE;\nTWFueSBoYW5kcyBtYWtlIGxpZ2h0IHdvcmsu\nENDSEC;\n"
        "END-ISO-10303-21;\n"
        "trailing bytes after the end are not read ( ' /*";
    const StepPart21 f = parse(text);
    ASSERT_EQ(f.schemas().size(), 2u);
    EXPECT_EQ(f.schemas()[1], "B_SCHEMA");
    ASSERT_EQ(f.instances().size(), 2u);
    EXPECT_EQ(f.instances()[0].id, 1);
    EXPECT_EQ(f.instances()[1].id, 2);
    EXPECT_EQ(f.find(2)->line, 16);
    EXPECT_EQ(f.find(100), nullptr);
    expect_read_error(kHeader + "#1=A();\nENDSEC;\nSIGNATURE;\nABC\n", kFirstDataLine + 2,
                      "SIGNATURE section has no ENDSEC");
}

TEST(StepPart21, OfTypeListsInstancesInFileOrder) {
    const StepPart21 f = parse(part21(
        "#5=POINT();\n#2=LINE();\n#9=POINT();\n#1=(POINT() POINT());\n#3=line();\n"));
    const std::vector<const StepInstance*> points = f.of_type("POINT");
    ASSERT_EQ(points.size(), 3u);  // #1 once, though it has two POINT records
    EXPECT_EQ(points[0]->id, 5);
    EXPECT_EQ(points[1]->id, 9);
    EXPECT_EQ(points[2]->id, 1);
    const std::vector<const StepInstance*> lines = f.of_type("LINE");
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[1]->id, 3);
    EXPECT_TRUE(f.of_type("CIRCLE").empty());
    EXPECT_TRUE(StepPart21().of_type("POINT").empty());
    EXPECT_EQ(StepPart21().find(1), nullptr);
}

TEST(StepPart21, StopsAtTheDeadline) {
    std::string data;
    for (int k = 1; k <= 2000; ++k) data += "#" + std::to_string(k) + "=P((1.,2.,3.));\n";
    std::atomic<bool> cancel{true};
    mesh::Deadline deadline(0.0, &cancel);
    EXPECT_THROW(StepPart21::parse(part21(data), "t.stp", &deadline), mesh::DeadlineExceeded);
    mesh::Deadline unlimited;
    EXPECT_EQ(StepPart21::parse(part21(data), "t.stp", &unlimited).instances().size(), 2000u);
}

// Occurrences of "TYPE(" not preceded by a keyword character ("B_SPLINE_CURVE(" is not
// counted inside "RATIONAL_B_SPLINE_CURVE(").
std::size_t count_records(const std::string& text, const std::string& type) {
    const std::string needle = type + "(";
    std::size_t n = 0;
    for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) {
        const char before = at == 0 ? ' ' : text[at - 1];
        if (!(std::isalnum(static_cast<unsigned char>(before)) || before == '_')) ++n;
    }
    return n;
}

// Lines of the form "#digits = ...": this writer's instance definitions.
std::size_t count_definition_lines(const std::string& text) {
    std::size_t n = 0;
    for (std::size_t start = 0; start < text.size();) {
        std::size_t k = start;
        if (text[k] == '#') {
            ++k;
            const std::size_t digits = k;
            while (k < text.size() && std::isdigit(static_cast<unsigned char>(text[k]))) ++k;
            if (k > digits && text.compare(k, 3, " = ") == 0) ++n;
        }
        const std::size_t nl = text.find('\n', start);
        start = nl == std::string::npos ? text.size() : nl + 1;
    }
    return n;
}

TEST(StepPart21, SharedScrewFileMatchesCountsFromItsText) {
    TRIMKIT_CAD_SAMPLE(path, "step/screw.step");
    std::ifstream in(path, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const StepPart21 f = StepPart21::parse(text, path);
    ASSERT_EQ(f.schemas().size(), 1u);
    EXPECT_EQ(f.schemas()[0].rfind("AUTOMOTIVE_DESIGN", 0), 0u) << f.schemas()[0];
    // Every instance of this writer starts a line with "#id = ".
    EXPECT_EQ(f.instances().size(), count_definition_lines(text));
    for (const char* type : {"ADVANCED_FACE", "CARTESIAN_POINT", "EDGE_CURVE", "ORIENTED_EDGE", "PCURVE",
                             "B_SPLINE_CURVE", "B_SPLINE_CURVE_WITH_KNOTS", "RATIONAL_B_SPLINE_CURVE",
                             "REPRESENTATION_CONTEXT", "TOROIDAL_SURFACE"}) {
        const std::size_t expected = count_records(text, type);
        EXPECT_GT(expected, 0u) << type;
        EXPECT_EQ(f.of_type(type).size(), expected) << type;
    }
    EXPECT_EQ(f.of_type("ADVANCED_FACE").size(), 10u);  // OCCT makes 10 faces (read_step_test)
    // Each instance's line holds its "#id =", and every reference resolves.
    std::vector<std::size_t> line_start = {0};
    for (std::size_t k = 0; k < text.size(); ++k)
        if (text[k] == '\n') line_start.push_back(k + 1);
    std::size_t references = 0;
    std::vector<const StepValue*> stack;
    for (const StepInstance& instance : f.instances()) {
        ASSERT_GE(instance.line, 1);
        ASSERT_LE(static_cast<std::size_t>(instance.line), line_start.size());
        const std::string head = "#" + std::to_string(instance.id) + " =";
        EXPECT_EQ(text.compare(line_start[instance.line - 1], head.size(), head), 0) << head;
        for (const StepRecord& r : instance.records)
            for (const StepValue& v : r.params) stack.push_back(&v);
        while (!stack.empty()) {
            const StepValue* v = stack.back();
            stack.pop_back();
            if (v->kind == Kind::kReference) {
                ++references;
                EXPECT_NE(f.find(v->integer), nullptr) << "#" << v->integer << " in #" << instance.id;
            }
            for (const StepValue& item : v->items) stack.push_back(&item);
        }
    }
    // The text's '#' outside strings ('Context #1' has one) are the definitions and the
    // references. A doubled quote toggles twice: it stays in the string.
    std::size_t hashes = 0;
    bool in_string = false;
    for (char c : text) {
        if (c == '\'') in_string = !in_string;
        if (c == '#' && !in_string) ++hashes;
    }
    EXPECT_EQ(references + f.instances().size(), hashes);
}

}  // namespace
}  // namespace trimkit::io
