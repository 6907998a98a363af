#include "io/brep_input.h"

#include <algorithm>
#include <utility>

namespace trimkit::io {

namespace {

// The "0" tokens served past the end, one block at a time.
constexpr std::size_t kPaddingBlock = 4096;

}  // namespace

BrepInputBuffer::BrepInputBuffer(std::string text) : text_(std::move(text)) {
    // A blank first: a number at the very end of the file stops at it unread.
    for (std::size_t k = 0; k < kPaddingBlock / 2; ++k) padding_ += " 0";
    char* begin = text_.data();
    setg(begin, begin, begin + text_.size());
}

bool BrepInputBuffer::past_end() const {
    return padding_served_ > padding_.size() || (padding_served_ > 0 && gptr() > eback());
}

int BrepInputBuffer::line() const {
    if (past_end()) return 0;
    const char* end = padding_served_ > 0 ? text_.data() + text_.size() : gptr();  // at the end
    return 1 + static_cast<int>(std::count(text_.data(), end, '\n'));
}

BrepInputBuffer::int_type BrepInputBuffer::underflow() {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    if (padding_served_ >= kMaxPadding) throw BrepInputEnded();
    padding_served_ += padding_.size();
    char* begin = padding_.data();
    setg(begin, begin, begin + padding_.size());
    return traits_type::to_int_type(*gptr());
}

BrepInput::BrepInput(std::string text) : std::istream(nullptr), buffer_(std::move(text)) {
    rdbuf(&buffer_);
    exceptions(std::ios::failbit | std::ios::badbit);
}

}  // namespace trimkit::io
