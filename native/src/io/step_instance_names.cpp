#include "io/step_instance_names.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "geom/error.h"

namespace trimkit::io {
namespace {

// Digits of a name beyond this are not a name Part 21 allows (and would overflow).
constexpr int kMaxNameDigits = 18;

// One pass over the text, a character at a time: a line that starts (past blanks) with
// "#digits" and then (past blanks) '=' defines that name. Lines, not statements: a
// damaged string (a control character, a quote lost: the fuzzer's files) would put
// a statement-by-statement reading out of step for the rest of the file, while no
// valid file has a line starting so inside a string.
class NameScanner {
public:
    // (name, line) of every definition, in file order.
    std::vector<std::pair<std::uint64_t, int>> definitions;

    void feed(char c) {
        if (c == '\n') {
            ++line_;
            state_ = State::kLineStart;
            return;
        }
        const bool blank = c == ' ' || c == '\t' || c == '\r';
        switch (state_) {
        case State::kLineStart:
            if (c == '#') state_ = State::kHash, name_ = 0, digits_ = 0;
            else if (!blank) state_ = State::kRest;
            break;
        case State::kHash:
        case State::kDigits:
            if (c >= '0' && c <= '9' && digits_ < kMaxNameDigits) {
                name_ = name_ * 10 + static_cast<std::uint64_t>(c - '0');
                ++digits_;
                state_ = State::kDigits;
            } else if (state_ == State::kDigits && (blank || c == '=')) {
                state_ = State::kAfterDigits;
                feed(c);
            } else {
                state_ = State::kRest;
            }
            break;
        case State::kAfterDigits:
            if (c == '=') definitions.emplace_back(name_, line_);
            if (!blank) state_ = State::kRest;
            break;
        case State::kRest:
            break;
        }
    }

private:
    enum class State { kLineStart, kHash, kDigits, kAfterDigits, kRest };
    State state_ = State::kLineStart;
    int line_ = 1, digits_ = 0;
    std::uint64_t name_ = 0;
};

}  // namespace

void check_step_instance_names(std::istream& in, const std::string& path) {
    NameScanner scanner;
    std::vector<char> buffer(1 << 16);
    while (in) {
        in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        const auto count = static_cast<std::size_t>(in.gcount());
        for (std::size_t i = 0; i < count; ++i) scanner.feed(buffer[i]);
    }
    auto& names = scanner.definitions;
    // Sorted by name, then line: the second of two equal names is the later definition.
    std::stable_sort(names.begin(), names.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    // The duplicate whose second definition comes first in the file is reported.
    std::pair<std::uint64_t, int> first{}, second{0, 0};
    for (std::size_t i = 1; i < names.size(); ++i)
        if (names[i].first == names[i - 1].first && (second.second == 0 || names[i].second < second.second)) {
            first = names[i - 1];
            second = names[i];
        }
    if (second.second > 0)
        throw geom::ReadError(path, second.second,
                              "entity #" + std::to_string(second.first) + " is defined twice (first on line " +
                                  std::to_string(first.second) + "); a STEP file names each entity once");
}

}  // namespace trimkit::io
