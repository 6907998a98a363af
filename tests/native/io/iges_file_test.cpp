// Lexical layer of the IGES reader: records, Global section, directory
// entries, free-format parameters (Hollerith strings, D exponents,
// continuation lines, custom delimiters) and tolerated deviations.
#include "io/iges_file.h"

#include <gtest/gtest.h>

#include "geom/error.h"
#include "io/iges_test_support.h"

namespace trimkit::io {
namespace {

using test::IgesEntitySpec;
using test::IgesTextBuilder;

std::vector<IgesParam> tokens(const std::string& text, char p = ',', char r = ';') {
    bool terminated = false;
    auto out = tokenize_iges_parameters(text, p, r, {}, "t.igs", &terminated);
    EXPECT_TRUE(terminated);
    return out;
}

TEST(IgesTokenizer, ReadsNumbersWithDAndEExponents) {
    auto t = tokens("1, -2.5D2 ,3.E-3,1.0d0, +7 ;");
    ASSERT_EQ(t.size(), 5u);
    EXPECT_TRUE(t[0].is_integer);
    EXPECT_EQ(t[0].number, 1);
    EXPECT_DOUBLE_EQ(t[1].number, -250.0);
    EXPECT_FALSE(t[1].is_integer);
    EXPECT_DOUBLE_EQ(t[2].number, 3e-3);
    EXPECT_DOUBLE_EQ(t[3].number, 1.0);
    EXPECT_EQ(t[4].number, 7);
}

TEST(IgesTokenizer, HollerithStringsMayHoldDelimitersAndBlanks) {
    auto t = tokens("5Ha,b;c,3H  x,0H,2;");
    ASSERT_EQ(t.size(), 4u);
    EXPECT_EQ(t[0].kind, IgesParam::Kind::kString);
    EXPECT_EQ(t[0].text, "a,b;c");
    EXPECT_EQ(t[1].text, "  x");
    EXPECT_EQ(t[2].kind, IgesParam::Kind::kString);
    EXPECT_EQ(t[2].text, "");
    EXPECT_EQ(t[3].number, 2);
}

TEST(IgesTokenizer, EmptyFieldsAreKeptAsDefaults) {
    auto t = tokens("1,,  ,4,;");
    ASSERT_EQ(t.size(), 5u);
    EXPECT_EQ(t[1].kind, IgesParam::Kind::kEmpty);
    EXPECT_EQ(t[2].kind, IgesParam::Kind::kEmpty);
    EXPECT_EQ(t[4].kind, IgesParam::Kind::kEmpty);
}

TEST(IgesTokenizer, CustomDelimiters) {
    auto t = tokens("1/2.5/3Ha/b#", '/', '#');
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[2].text, "a/b");
}

TEST(IgesTokenizer, RejectsJunkAndOverlongHollerith) {
    bool term = false;
    EXPECT_THROW(tokenize_iges_parameters("1,abc;", ',', ';', {}, "t.igs", &term), geom::ReadError);
    EXPECT_THROW(tokenize_iges_parameters("1,20Hshort;", ',', ';', {}, "t.igs", &term), geom::ReadError);
    EXPECT_THROW(tokenize_iges_parameters("1,99999999999Hx;", ',', ';', {}, "t.igs", &term),
                 geom::ReadError);
}

TEST(IgesFile, ParsesGlobalDirectoryAndParameters) {
    IgesTextBuilder b;
    const int line = b.add({110, "0.,0.,0.,1.D1,2.5E0,-3.;", 0, 0, "00010000", 2, "CURVE1"});
    const IgesFile f = IgesFile::parse(b.text(), "g.igs");
    EXPECT_EQ(f.global().parameter_delimiter, ',');
    EXPECT_EQ(f.global().record_delimiter, ';');
    EXPECT_EQ(f.global().units_flag, 2);
    EXPECT_EQ(f.global().units_name, "MM");
    EXPECT_DOUBLE_EQ(f.global().max_coordinate, 100.0);
    EXPECT_DOUBLE_EQ(f.global().min_resolution, 1e-6);
    ASSERT_EQ(f.entries().size(), 1u);
    const IgesDirectoryEntry& d = f.entries()[0];
    EXPECT_EQ(d.sequence, line);
    EXPECT_EQ(d.type, 110);
    EXPECT_EQ(d.subordinate, 1);
    EXPECT_EQ(d.color, 2);
    EXPECT_EQ(d.label, "CURVE1");
    EXPECT_EQ(d.line, 4);  // after one S and two G lines
    auto p = f.parameters(0);
    ASSERT_EQ(p.size(), 6u);
    EXPECT_DOUBLE_EQ(p[3].number, 10.0);
    EXPECT_EQ(f.index_of(line), 0);
    EXPECT_EQ(f.index_of(line + 1), -1);
    EXPECT_EQ(f.index_of(99), -1);
}

TEST(IgesFile, ContinuationLinesJoinParametersAndStrings) {
    IgesTextBuilder b;
    const std::string name(90, 'x');
    b.add({406, "1,90H" + name + ";", 15});  // the string runs over columns 64
    IgesEntitySpec line{110, "1.5,2.5,3.5,4.5,5.5,6.5;"};
    line.width = 12;  // numbers broken after commas, lines blank-padded
    b.add(line);
    const IgesFile f = IgesFile::parse(b.text(), "c.igs");
    auto p = f.parameters(0);
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[1].text, name);
    auto q = f.parameters(1);
    ASSERT_EQ(q.size(), 6u);
    EXPECT_DOUBLE_EQ(q[5].number, 6.5);
    EXPECT_GT(q[5].line, q[0].line);  // read from a continuation line
}

TEST(IgesFile, CustomDelimitersFromTheGlobalSection) {
    IgesTextBuilder b("1H//1H#/4Htest/8Htest.igs/////////1.0/1/2HIN#");
    b.add({110, "0./0./0./1./1./1.#"});
    const IgesFile f = IgesFile::parse(b.text(), "d.igs");
    EXPECT_EQ(f.global().parameter_delimiter, '/');
    EXPECT_EQ(f.global().record_delimiter, '#');
    EXPECT_EQ(f.global().units_flag, 1);
    EXPECT_EQ(f.parameters(0).size(), 6u);
}

TEST(IgesFile, DefaultDelimitersWhenLeftEmpty) {
    IgesTextBuilder b(",,4Htest,,,,,,,,,,1.0,6,1HM;");
    b.add({110, "0.,0.,0.,1.,1.,1.;"});
    const IgesFile f = IgesFile::parse(b.text(), "e.igs");
    EXPECT_EQ(f.global().parameter_delimiter, ',');
    EXPECT_EQ(f.global().units_flag, 6);
}

// Records run together without line terminators (HP ME's IGES translator, which
// OCCT reads): the same entities and parameters as the file with its line breaks,
// and errors still name the record as the line.
TEST(IgesFile, RecordsWithoutLineBreaksAreSplitAt80Columns) {
    IgesTextBuilder b;
    b.add({110, "0.,0.,0.,1.,1.,1.;"});
    b.add({110, "1.,2.,3.,4.,5.,6.;"});
    const std::string text = b.text();
    std::string joined;
    for (char c : text)
        if (c != '\n') joined += c;
    joined += '\n';
    const IgesFile lines = IgesFile::parse(text, "lines.igs"), run = IgesFile::parse(joined, "run.igs");
    ASSERT_EQ(run.entries().size(), lines.entries().size());
    ASSERT_EQ(run.entries().size(), 2u);
    for (int k = 0; k < 2; ++k) {
        ASSERT_EQ(run.parameters(k).size(), lines.parameters(k).size());
        for (std::size_t i = 0; i < run.parameters(k).size(); ++i)
            EXPECT_EQ(run.parameters(k)[i].number, lines.parameters(k)[i].number);
    }
    EXPECT_TRUE(run.warnings().empty());
    // A run whose 4th record has no section letter is not split: a read error (the
    // directory is not found), not a crash or a partial file.
    std::string damaged = joined;
    damaged[3 * 80 + 72] = 'X';
    EXPECT_THROW(IgesFile::parse(damaged, "damaged.igs"), geom::ReadError);
}

TEST(IgesFile, ToleratesCrlfShortLinesAndMissingTerminate) {
    IgesTextBuilder b;
    b.add({110, "0.,0.,0.,1.,1.,1.;"});
    std::string text = b.text();
    // CRLF line ends, and the S line shortened to "text S      1".
    std::string crlf;
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t e = text.find('\n', pos);
        std::string l = text.substr(pos, e - pos);
        pos = e + 1;
        if (l[72] == 'T') continue;  // drop the Terminate section
        if (l[72] == 'S') l = "trimkit test file S      1";
        crlf += l + "\r\n";
    }
    const IgesFile f = IgesFile::parse(crlf, "crlf.igs");
    EXPECT_EQ(f.entries().size(), 1u);
    EXPECT_EQ(f.parameters(0).size(), 6u);
    bool warned = false;
    for (const auto& w : f.warnings()) warned |= w.find("Terminate") != std::string::npos;
    EXPECT_TRUE(warned);
}

TEST(IgesFile, RejectsTextThatIsNotIges) {
    try {
        IgesFile::parse("hello world\nthis is not IGES\n", "hello.txt");
        FAIL() << "no ReadError";
    } catch (const geom::ReadError& e) {
        EXPECT_EQ(e.line(), 1);
        EXPECT_NE(std::string(e.what()).find("hello.txt:1:"), std::string::npos);
    }
    EXPECT_THROW(IgesFile::parse("", "empty.igs"), geom::ReadError);
}

TEST(IgesFile, BackPointerMismatchNamesTheLine) {
    IgesTextBuilder b;
    b.add({110, "0.,0.,0.,1.,1.,1.;"});
    std::string text = b.text();
    const std::size_t p = text.find("P      1");
    ASSERT_NE(p, std::string::npos);
    text.replace(p - 8, 8, "       7");  // back pointer to D7
    const IgesFile f = IgesFile::parse(text, "bp.igs");
    try {
        f.parameters(0);
        FAIL() << "no ReadError";
    } catch (const geom::ReadError& e) {
        EXPECT_EQ(e.line(), 6);  // S, two G and two D lines before it
        EXPECT_NE(e.reason().find("D7"), std::string::npos);
    }
}

}  // namespace
}  // namespace trimkit::io
