// A .brep file as the stream Open CASCADE's BRepTools::Read takes, safe on a damaged
// file. OCCT's reader loops over the values it reads (an edge's representations
// until a 0) without looking at the stream's state: at the end of a cut-off file, or
// after a word where a number belongs, extraction fails, the last value stays, and it
// spins for ever (a CrankArm.brep cut in its shapes' section). This stream throws
// instead: a failed extraction throws std::ios_base::failure; past the end of the
// file it serves " 0" tokens (which end those loops and the counts that follow) up to
// kMaxPadding characters, then throws BrepInputEnded. `line()` is the line of the
// file being read, for the error message.
#pragma once

#include <cstddef>
#include <istream>
#include <stdexcept>
#include <streambuf>
#include <string>

namespace trimkit::io {

// Characters of "0" tokens served past the end of the file before the stream gives up.
constexpr std::size_t kMaxPadding = 1 << 16;

struct BrepInputEnded : std::runtime_error {
    BrepInputEnded() : std::runtime_error("the file ends before its shapes do (cut off?)") {}
};

class BrepInputBuffer : public std::streambuf {
public:
    explicit BrepInputBuffer(std::string text);
    // The line (from 1) of the next character to read; 0 once past the end.
    int line() const;
    // True once a character past the end of the file has been read (a value needed
    // the padding); not when a number at the very end only looked at what follows it.
    bool past_end() const;

protected:
    int_type underflow() override;

private:
    std::string text_;
    std::string padding_;
    std::size_t padding_served_ = 0;
};

class BrepInput : public std::istream {
public:
    // The stream over a file's text.
    explicit BrepInput(std::string text);
    int line() const { return buffer_.line(); }
    bool past_end() const { return buffer_.past_end(); }

private:
    BrepInputBuffer buffer_;
};

}  // namespace trimkit::io
