#include "io/step_part21.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <system_error>
#include <utility>

#include "geom/error.h"
#include "mesh/deadline.h"

namespace trimkit::io {
namespace {

constexpr const char* kStage = "STEP parsing";
// Digits of an instance name (after leading zeros): 18 always fit a long long.
constexpr int kMaxIdDigits = 18;
// Characters of a bad token quoted in a message.
constexpr std::size_t kMaxShown = 24;
// Shortest instance text, "#1=A();": bounds the instances a text can hold, so that
// reserving from a count of ';' never reserves more than the text can fill.
constexpr std::size_t kMinInstanceText = 7;
// Lists of at least this many values hand the scratch vector itself to the output
// (at most twice the size needed) instead of moving them into an exact copy: a huge
// list then never exists twice. Shorter lists, the usual ones, are sized exactly.
constexpr std::size_t kHandOverItems = 4096;
// Unicode replacement character, for code points \X2\ and \X4\ cannot make valid.
constexpr std::uint32_t kReplacement = 0xFFFD;

// ---- character classes (ISO 10303-21:2016 Sec. 5: the basic alphabet) ----

enum : unsigned char { kSpace = 1, kDigit = 2, kUpper = 4, kLower = 8, kHex = 16 };

struct CharTable {
    unsigned char bits[256] = {};
    constexpr CharTable() {
        for (int c : {' ', '\t', '\n', '\r', '\f', '\v'}) bits[c] |= kSpace;
        for (int c = '0'; c <= '9'; ++c) bits[c] |= kDigit | kHex;
        for (int c = 'A'; c <= 'Z'; ++c) bits[c] |= kUpper;
        for (int c = 'a'; c <= 'z'; ++c) bits[c] |= kLower;
        bits[static_cast<int>('_')] |= kUpper;  // Part 21's UPPER includes the underscore
        for (int c = 'A'; c <= 'F'; ++c) bits[c] |= kHex;
        for (int c = 'a'; c <= 'f'; ++c) bits[c] |= kHex;
    }
};
constexpr CharTable kChars;

inline bool has(char c, unsigned char bit) { return kChars.bits[static_cast<unsigned char>(c)] & bit; }
inline bool is_space(char c) { return has(c, kSpace); }
inline bool is_digit(char c) { return has(c, kDigit); }
inline bool is_hex(char c) { return has(c, kHex); }
// First character of a keyword or enumeration (lower case accepted, made upper).
inline bool is_word_start(char c) { return has(c, kUpper | kLower); }
inline bool is_word(char c) { return has(c, kUpper | kLower | kDigit); }

void make_upper(std::string& s) {
    for (char& c : s)
        if (has(c, kLower)) c = static_cast<char>(c - 'a' + 'A');
}

int hex_value(char c) {
    if (c <= '9') return c - '0';
    return (c | 0x20) - 'a' + 10;
}

// The value of n hex digits at s, or -1 if one is not a hex digit.
long hex_number(const char* s, int n) {
    long v = 0;
    for (int k = 0; k < n; ++k) {
        if (!is_hex(s[k])) return -1;
        v = v * 16 + hex_value(s[k]);
    }
    return v;
}

void append_utf8(std::string& out, std::uint32_t cp) {
    if (cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) cp = kReplacement;
    if (cp < 0x80) {
        out.push_back(static_cast<char>(cp));
    } else if (cp < 0x800) {
        out.push_back(static_cast<char>(0xC0 | (cp >> 6)));
        out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    } else if (cp < 0x10000) {
        out.push_back(static_cast<char>(0xE0 | (cp >> 12)));
        out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
        out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    } else {
        out.push_back(static_cast<char>(0xF0 | (cp >> 18)));
        out.push_back(static_cast<char>(0x80 | ((cp >> 12) & 0x3F)));
        out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
        out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    }
}

bool starts_with(const std::string& s, std::size_t i, const char* prefix) {
    const std::size_t n = std::strlen(prefix);
    return s.size() - i >= n && s.compare(i, n, prefix) == 0;
}

// Decodes an extended directive "\X2\hhhh...\X0\" (digits = 4) or "\X4\hhhhhhhh...\X0\"
// (digits = 8) starting at s[i]; returns the index after it, or 0 when malformed
// (the caller keeps the backslash as text). UTF-16 surrogate pairs in \X2\ combine.
std::size_t decode_extended(const std::string& s, std::size_t i, int digits, std::string& out) {
    std::size_t j = i + 4;
    std::size_t end = j;
    while (end + digits <= s.size() && hex_number(s.data() + end, digits) >= 0) end += digits;
    if (!starts_with(s, end, "\\X0\\")) return 0;
    for (; j < end; j += digits) {
        auto cp = static_cast<std::uint32_t>(hex_number(s.data() + j, digits));
        if (digits == 4 && cp >= 0xD800 && cp <= 0xDBFF && j + 4 < end) {
            const auto low = static_cast<std::uint32_t>(hex_number(s.data() + j + 4, 4));
            if (low >= 0xDC00 && low <= 0xDFFF) {
                cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
                j += 4;
            }
        }
        append_utf8(out, cp);
    }
    return end + 4;
}

// Decodes the control directives of ISO 10303-21:2016 Sec. 6.4.3 in `s` (quotes
// already undoubled, line breaks removed) into `out`. \S\c is read as ISO 8859-1
// (c + 128): \P?\ switches to other parts are dropped, not followed. A backslash that
// starts no well-formed directive is kept as text, as lenient readers do.
void decode_directives(const std::string& s, std::string& out) {
    out.clear();
    out.reserve(s.size());
    std::size_t i = 0;
    const std::size_t n = s.size();
    while (i < n) {
        const char c = s[i];
        if (c != '\\') {
            out.push_back(c);
            ++i;
            continue;
        }
        if (starts_with(s, i, "\\\\")) {
            out.push_back('\\');
            i += 2;
        } else if (starts_with(s, i, "\\S\\") && i + 3 < n) {
            append_utf8(out, static_cast<unsigned char>(s[i + 3]) | 0x80u);
            i += 4;
        } else if (i + 3 < n && s[i + 1] == 'P' && has(s[i + 2], kUpper) && s[i + 3] == '\\') {
            i += 4;
        } else if (starts_with(s, i, "\\X\\") && i + 5 <= n && hex_number(s.data() + i + 3, 2) >= 0) {
            append_utf8(out, static_cast<std::uint32_t>(hex_number(s.data() + i + 3, 2)));
            i += 5;
        } else if (std::size_t e = starts_with(s, i, "\\X2\\") ? decode_extended(s, i, 4, out) : 0) {
            i = e;
        } else if (std::size_t f = starts_with(s, i, "\\X4\\") ? decode_extended(s, i, 8, out) : 0) {
            i = f;
        } else {
            out.push_back('\\');
            ++i;
        }
    }
}

// splitmix64's finaliser: a bijective mix of all 64 bits into each.
std::uint64_t mix(std::uint64_t x) {
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebULL;
    x ^= x >> 31;
    return x;
}

std::uint64_t hash_id(long long id, std::uint64_t seed) { return mix(static_cast<std::uint64_t>(id) ^ seed); }

std::uint64_t hash_text(const std::string& s, std::uint64_t seed) {
    std::uint64_t h = mix(seed ^ (s.size() * 0x9E3779B97F4A7C15ULL));
    const char* p = s.data();
    std::size_t n = s.size();
    for (; n >= 8; p += 8, n -= 8) {
        std::uint64_t w;
        std::memcpy(&w, p, 8);
        h = mix(h ^ w);
    }
    std::uint64_t w = 0;
    std::memcpy(&w, p, n);
    return mix(h ^ w);
}

std::size_t capacity_for(std::size_t count) {
    std::size_t c = 16;
    while (c < 2 * count) c *= 2;
    return c;
}

}  // namespace

// ---- the parser: one pass over the text, a recursive descent bounded by kMaxNesting ----

class Part21Parser {
public:
    Part21Parser(const std::string& text, StepPart21& out, mesh::Deadline* deadline)
        : begin_(text.data()), p_(text.data()), end_(text.data() + text.size()), out_(out),
          deadline_(deadline), line_pos_(text.data()), scratch_(StepPart21::kMaxNesting + 1) {}

    void run();

private:
    // Line of the character at q (1-based). Newlines are counted lazily from the last
    // position asked for; positions asked for go forward except on the error path.
    int line_at(const char* q) {
        if (q < line_pos_) {
            line_pos_ = begin_;
            line_ = 1;
        }
        while (const void* nl = std::memchr(line_pos_, '\n', static_cast<std::size_t>(q - line_pos_))) {
            line_pos_ = static_cast<const char*>(nl) + 1;
            if (line_ < INT_MAX) ++line_;
        }
        line_pos_ = q;
        return line_;
    }

    [[noreturn]] void fail(const char* at, const std::string& reason) {
        throw geom::ReadError(out_.name_, line_at(at), reason);
    }

    // "'TOKEN'" (a word, number or one character at q), or "end of file", or "byte 0x07".
    std::string describe(const char* q) const {
        if (q >= end_) return "end of file";
        const auto c = static_cast<unsigned char>(*q);
        if (c <= 0x20 || c >= 0x7F) {
            static const char* hex = "0123456789ABCDEF";
            return std::string("byte 0x") + hex[c >> 4] + hex[c & 15];
        }
        const char* e = q + 1;
        if (is_word(*q) || *q == '#' || *q == '-' || *q == '+' || *q == '.')
            while (e < end_ && (is_word(*e) || *e == '-' || *e == '.') && e - q < static_cast<long>(kMaxShown)) ++e;
        return "'" + std::string(q, e) + (e < end_ && is_word(*e) ? "...'" : "'");
    }

    void check_deadline() {
        if (deadline_) deadline_->check(kStage);
    }

    void skip_space() {
        for (;;) {
            while (p_ < end_ && is_space(*p_)) ++p_;
            if (end_ - p_ >= 2 && p_[0] == '/' && p_[1] == '*') {
                const char* open = p_;
                const char* q = p_ + 2;
                for (;;) {
                    q = static_cast<const char*>(std::memchr(q, '*', static_cast<std::size_t>(end_ - q)));
                    if (!q) fail(open, "unterminated comment: '/*' without '*/'");
                    if (q + 1 < end_ && q[1] == '/') break;
                    ++q;
                }
                p_ = q + 2;
                continue;
            }
            return;
        }
    }

    void expect_semicolon(const char* after) {
        skip_space();
        if (p_ == end_ || *p_ != ';') fail(p_, std::string("expected ';' after ") + after + ", found " + describe(p_));
        ++p_;
    }

    // A section keyword ("HEADER", "END-ISO-10303-21"): letters, digits, '_' and '-',
    // upper case. Empty when none starts at p_.
    std::string section_word() {
        const char* s = p_;
        while (p_ < end_ && (is_word(*p_) || *p_ == '-')) ++p_;
        std::string w(s, p_);
        make_upper(w);
        return w;
    }

    // A keyword at p_ (standard, or user-defined with '!'), upper case.
    std::string keyword() {
        const char* s = p_;
        if (p_ < end_ && *p_ == '!') ++p_;
        if (p_ == end_ || !is_word_start(*p_)) fail(s, "expected a keyword, found " + describe(s));
        while (p_ < end_ && is_word(*p_)) ++p_;
        std::string k(s, p_);
        make_upper(k);
        return k;
    }

    void read_header(const char* section);
    void read_data(const char* section);
    void skip_section(const std::string& word, const char* section);
    void read_instance();
    void read_record(StepRecord& record);
    void parse_items(std::vector<StepValue>& out, int depth, const char* open);
    void parse_value(std::vector<StepValue>& items, int depth, const char* open);
    long long read_instance_name();
    void read_number(StepValue& v);
    const char* string_end(const char* open, bool* plain);
    void read_string(std::string& out);

    const char* begin_;
    const char* p_;
    const char* end_;
    StepPart21& out_;
    mesh::Deadline* deadline_;
    const char* line_pos_;
    int line_ = 1;
    // scratch_[d]: the values of the list being read at nesting depth d, moved into an
    // exactly sized vector when it closes (no growth copies in the output).
    std::vector<std::vector<StepValue>> scratch_;
    std::string undoubled_;  // a string's text before its directives are decoded
};

void Part21Parser::run() {
    // Reserve for the instances the text can hold: one per ';', at most one per
    // kMinInstanceText characters.
    const auto size = static_cast<std::size_t>(end_ - begin_);
    const auto semicolons = static_cast<std::size_t>(std::count(begin_, end_, ';'));
    const std::size_t expected = std::min(semicolons, size / kMinInstanceText + 1);
    out_.instances_.reserve(expected);
    out_.id_slots_.assign(capacity_for(expected), StepPart21::IdSlot{});

    if (size >= 3 && std::memcmp(p_, "\xEF\xBB\xBF", 3) == 0) p_ += 3;  // UTF-8 byte order mark
    skip_space();
    const char* at = p_;
    if (section_word() != "ISO-10303-21")
        fail(at, "not a STEP file: expected 'ISO-10303-21;' at the start, found " + describe(at));
    expect_semicolon("ISO-10303-21");
    skip_space();
    at = p_;
    if (section_word() != "HEADER") fail(at, "expected 'HEADER;' after 'ISO-10303-21;', found " + describe(at));
    expect_semicolon("HEADER");
    read_header(at);

    bool data = false;
    for (;;) {
        skip_space();
        at = p_;
        if (p_ == end_)
            fail(at, data ? "no 'END-ISO-10303-21;' after the last section: file truncated?" : "no DATA section");
        const std::string word = section_word();
        if (word == "DATA") {
            read_data(at);
            data = true;
        } else if (word == "ANCHOR" || word == "REFERENCE" || word == "SIGNATURE") {
            skip_section(word, at);
        } else if (word == "END-ISO-10303-21") {
            if (!data) fail(at, "no DATA section");
            expect_semicolon("END-ISO-10303-21");
            break;  // anything after it (padding, old writers' signatures) is not read
        } else {
            fail(at, "expected DATA, ANCHOR, REFERENCE, SIGNATURE or END-ISO-10303-21, found " + describe(at));
        }
    }
}

void Part21Parser::read_header(const char* section) {
    for (;;) {
        skip_space();
        if (p_ == end_) fail(section, "HEADER section has no ENDSEC: file truncated?");
        StepRecord record;
        record.type = keyword();
        if (record.type == "ENDSEC") {
            expect_semicolon("ENDSEC");
            break;
        }
        read_record(record);
        expect_semicolon(("header entity " + record.type).c_str());
        out_.header_.push_back(std::move(record));
    }
    for (const StepRecord& r : out_.header_) {
        if (r.type != "FILE_SCHEMA" || r.params.empty()) continue;
        const StepValue& v = r.params[0];
        if (v.kind == StepValue::Kind::kString) out_.schemas_.push_back(v.text);
        for (const StepValue& item : v.items)
            if (v.kind == StepValue::Kind::kList && item.kind == StepValue::Kind::kString)
                out_.schemas_.push_back(item.text);
    }
}

void Part21Parser::read_data(const char* section) {
    skip_space();
    if (p_ < end_ && *p_ == '(') {  // edition 3: DATA('name', ('SCHEMA'));, not kept
        std::vector<StepValue> ignored;
        const char* open = p_++;
        parse_items(ignored, 0, open);
    }
    expect_semicolon("DATA");
    for (;;) {
        skip_space();
        if (p_ == end_) fail(section, "DATA section has no ENDSEC: file truncated?");
        if (*p_ == '#') {
            read_instance();
            continue;
        }
        const char* at = p_;
        if (is_word_start(*p_) && keyword() == "ENDSEC") {
            expect_semicolon("ENDSEC");
            return;
        }
        fail(at, "expected an entity instance '#n = ...' or ENDSEC, found " + describe(at));
    }
}

// ANCHOR, REFERENCE and SIGNATURE sections (edition 3) carry nothing geometric: read up
// to their ENDSEC, passing strings, <URI>s and comments whole so that none can end them.
void Part21Parser::skip_section(const std::string& word, const char* section) {
    for (;;) {
        check_deadline();
        skip_space();
        if (p_ == end_) fail(section, word + " section has no ENDSEC: file truncated?");
        const char c = *p_;
        if (c == '\'') {
            bool plain = false;
            p_ = string_end(p_, &plain) + 1;
        } else if (c == '<') {
            const void* close = std::memchr(p_, '>', static_cast<std::size_t>(end_ - p_));
            if (!close) fail(p_, "unterminated URI: '<' without '>'");
            p_ = static_cast<const char*>(close) + 1;
        } else if (is_word(c)) {
            if (section_word() == "ENDSEC") {
                expect_semicolon("ENDSEC");
                return;
            }
        } else {
            ++p_;
        }
    }
}

long long Part21Parser::read_instance_name() {
    const char* at = p_;  // '#'
    ++p_;
    const char* s = p_;
    while (p_ < end_ && *p_ == '0') ++p_;
    const char* d = p_;
    while (p_ < end_ && is_digit(*p_)) ++p_;
    if (p_ == s) {
        if (p_ < end_ && is_word_start(*p_))
            fail(at, "instance name " + describe(at) + " is not a number (constant names are not supported)");
        fail(at, "'#' without an instance number");
    }
    if (p_ < end_ && is_word(*p_)) fail(at, "malformed instance name " + describe(at));
    long long id = 0;
    if (p_ - d <= kMaxIdDigits)
        for (const char* q = d; q < p_; ++q) id = id * 10 + (*q - '0');
    if (p_ - d > kMaxIdDigits || id < 1)
        fail(at, "instance name " + describe(at) + " is out of range (1 to " +
                     std::to_string(StepPart21::kMaxInstanceId) + ")");
    return id;
}

void Part21Parser::read_instance() {
    check_deadline();
    const char* at = p_;
    const long long id = read_instance_name();
    const int line = line_at(at);
    skip_space();
    if (p_ == end_ || *p_ != '=')
        fail(p_, "expected '=' after #" + std::to_string(id) + ", found " + describe(p_));
    ++p_;
    const std::size_t first = out_.insert_id(id, out_.instances_.size());
    if (first != StepPart21::kNone) {
        fail(at, "entity #" + std::to_string(id) + " is defined twice (first on line " +
                     std::to_string(out_.instances_[first].line) + ")");
    }

    StepInstance& instance = out_.instances_.emplace_back();
    instance.id = id;
    instance.line = line;
    skip_space();
    if (p_ < end_ && *p_ == '(') {  // complex instance: (A(..) B(..) ...)
        const char* open = p_++;
        for (;;) {
            skip_space();
            if (p_ == end_) fail(open, "unterminated complex instance #" + std::to_string(id) + ": '(' never closed");
            if (*p_ == ')') break;
            if (!is_word_start(*p_) && *p_ != '!')
                fail(p_, "expected a partial record in complex instance #" + std::to_string(id) + ", found " +
                             describe(p_));
            StepRecord& record = instance.records.emplace_back();
            record.type = keyword();
            read_record(record);
        }
        ++p_;
        if (instance.records.empty()) fail(open, "complex instance #" + std::to_string(id) + " has no records");
    } else if (p_ < end_ && (is_word_start(*p_) || *p_ == '!')) {
        StepRecord& record = instance.records.emplace_back();
        record.type = keyword();
        read_record(record);
    } else {
        fail(p_, "expected an entity record after '#" + std::to_string(id) + " =', found " + describe(p_));
    }
    expect_semicolon(("instance #" + std::to_string(id)).c_str());
}

void Part21Parser::read_record(StepRecord& record) {
    skip_space();
    if (p_ == end_ || *p_ != '(') fail(p_, "expected '(' after " + record.type + ", found " + describe(p_));
    const char* open = p_++;
    parse_items(record.params, 0, open);
}

// The values of a list whose '(' is at `open` (p_ just past it), up to its ')'.
void Part21Parser::parse_items(std::vector<StepValue>& out, int depth, const char* open) {
    std::vector<StepValue>& items = scratch_[static_cast<std::size_t>(depth)];
    skip_space();
    if (p_ < end_ && *p_ == ')') {
        ++p_;
        return;
    }
    for (;;) {
        check_deadline();
        parse_value(items, depth, open);
        skip_space();
        if (p_ == end_) break;
        const char c = *p_++;
        if (c == ')') {
            if (items.size() < kHandOverItems) {
                out.assign(std::make_move_iterator(items.begin()), std::make_move_iterator(items.end()));
                items.clear();
            } else {
                out.swap(items);  // out was empty: the scratch regrows next time
            }
            return;
        }
        if (c != ',') fail(p_ - 1, "expected ',' or ')' after a value, found " + describe(p_ - 1));
        skip_space();
    }
    fail(open, "unterminated list: '(' never closed (file truncated?)");
}

void Part21Parser::parse_value(std::vector<StepValue>& items, int depth, const char* open) {
    using Kind = StepValue::Kind;
    skip_space();
    if (p_ == end_) fail(open, "unterminated list: '(' never closed (file truncated?)");
    StepValue& v = items.emplace_back();
    const char c = *p_;
    switch (c) {
    case '$':
        ++p_;
        return;
    case '*':
        v.kind = Kind::kDerived;
        ++p_;
        return;
    case '\'':
        v.kind = Kind::kString;
        read_string(v.text);
        return;
    case '#':
        v.kind = Kind::kReference;
        v.integer = read_instance_name();
        return;
    case '"': {
        const char* at = p_++;
        const char* s = p_;
        while (p_ < end_ && is_hex(*p_)) ++p_;
        if (p_ == end_ || *p_ != '"') fail(at, "malformed binary value: expected hex digits and a closing '\"'");
        if (p_ == s || *s > '3') fail(at, "malformed binary value: the first digit (unused bits) must be 0 to 3");
        v.kind = Kind::kBinary;
        v.text.assign(s, p_);
        make_upper(v.text);
        ++p_;
        return;
    }
    case '(': {
        if (depth + 1 > StepPart21::kMaxNesting)
            fail(p_, "lists nested deeper than " + std::to_string(StepPart21::kMaxNesting));
        v.kind = Kind::kList;
        const char* list_open = p_++;
        parse_items(v.items, depth + 1, list_open);
        return;
    }
    case '.':
        if (p_ + 1 < end_ && is_word_start(p_[1])) {
            const char* at = p_++;
            const char* s = p_;
            while (p_ < end_ && is_word(*p_)) ++p_;
            if (p_ == end_ || *p_ != '.') fail(at, "malformed enumeration " + describe(at) + ": no closing '.'");
            v.kind = Kind::kEnum;
            v.text.assign(s, p_);
            make_upper(v.text);
            ++p_;
            return;
        }
        break;  // ".5": a number
    default:
        break;
    }
    if (is_digit(c) || c == '+' || c == '-' || c == '.') {
        read_number(v);
        return;
    }
    if (is_word_start(c) || c == '!') {  // typed value: KEYWORD(value)
        const char* at = p_;
        v.kind = Kind::kTyped;
        v.text = keyword();
        skip_space();
        if (p_ == end_ || *p_ != '(') fail(p_, "expected '(' after " + v.text + ", found " + describe(p_));
        if (depth + 1 > StepPart21::kMaxNesting)
            fail(p_, "lists nested deeper than " + std::to_string(StepPart21::kMaxNesting));
        const char* typed_open = p_++;
        parse_items(v.items, depth + 1, typed_open);
        if (v.items.size() != 1)
            fail(at, "typed value " + v.text + " has " + std::to_string(v.items.size()) + " values, expected 1");
        return;
    }
    fail(p_, "unexpected " + describe(p_) + " where a value was expected");
}

// [+-] digits [. digits] [E [+-] digits] (at least one mantissa digit): an integer
// without '.' or exponent, else a real. Part 21 wants "1." for reals; ".5" and "1E3"
// are accepted as lenient readers do.
void Part21Parser::read_number(StepValue& v) {
    const char* s = p_;
    const char* q = p_;
    if (*q == '+' || *q == '-') ++q;
    const char* digits = q;
    while (q < end_ && is_digit(*q)) ++q;
    const char* digits_end = q;
    bool real = false;
    bool any_digit = q > digits;
    if (q < end_ && *q == '.') {
        real = true;
        const char* f = ++q;
        while (q < end_ && is_digit(*q)) ++q;
        any_digit = any_digit || q > f;
    }
    if (!any_digit) fail(s, "malformed number " + describe(s));
    if (q < end_ && (*q == 'E' || *q == 'e')) {
        ++q;
        if (q < end_ && (*q == '+' || *q == '-')) ++q;
        const char* e = q;
        while (q < end_ && is_digit(*q)) ++q;
        if (q == e) fail(s, "malformed number " + describe(s) + ": no exponent digits");
        real = true;
    }
    p_ = q;
    if (!real) {
        long long n = 0;
        for (const char* d = digits; d < digits_end; ++d) {
            const int k = *d - '0';
            if (n > (LLONG_MAX - k) / 10) fail(s, "integer " + describe(s) + " is out of range");
            n = n * 10 + k;
        }
        v.kind = StepValue::Kind::kInteger;
        v.integer = *s == '-' ? -n : n;
        v.real = static_cast<double>(v.integer);
        return;
    }
    v.kind = StepValue::Kind::kReal;
    const char* first = *s == '+' ? s + 1 : s;
    const std::from_chars_result r = std::from_chars(first, q, v.real);
    if (r.ec == std::errc() && r.ptr == q) return;
    // Out of double's range (or a form from_chars refuses): strtod decides, on a copy
    // bounded by the token. Underflow reads as 0 or a denormal; overflow is an error.
    const std::string token(first, q);
    char* stop = nullptr;
    v.real = std::strtod(token.c_str(), &stop);
    if (stop != token.c_str() + token.size() || v.real == HUGE_VAL || v.real == -HUGE_VAL)
        fail(s, "real " + describe(s) + " is out of range");
}

// The closing quote of the string opening at `open`; *plain is set when the text
// between needs no decoding (no '', backslash or line break).
const char* Part21Parser::string_end(const char* open, bool* plain) {
    const char* q = open + 1;
    bool doubled = false;
    for (;;) {
        const auto* quote = static_cast<const char*>(std::memchr(q, '\'', static_cast<std::size_t>(end_ - q)));
        if (!quote) fail(open, "unterminated string: no closing quote");
        if (quote + 1 < end_ && quote[1] == '\'') {
            doubled = true;
            q = quote + 2;
            continue;
        }
        *plain = !doubled;
        if (!doubled)
            for (const char* c = open + 1; c < quote; ++c)
                if (*c == '\\' || *c == '\n' || *c == '\r') {
                    *plain = false;
                    break;
                }
        return quote;
    }
}

void Part21Parser::read_string(std::string& out) {
    bool plain = false;
    const char* close = string_end(p_, &plain);
    const char* s = p_ + 1;
    p_ = close + 1;
    if (plain) {
        out.assign(s, close);
        return;
    }
    // Writers wrap long lines inside strings: the line breaks are not text.
    undoubled_.clear();
    bool backslash = false;
    for (const char* c = s; c < close; ++c) {
        if (*c == '\n' || *c == '\r') continue;
        if (*c == '\'') ++c;  // the first of two quotes
        backslash = backslash || *c == '\\';
        undoubled_.push_back(*c);
    }
    if (backslash)
        decode_directives(undoubled_, out);
    else
        out = undoubled_;
}

// ---- StepInstance, StepPart21 ----

const StepRecord* StepInstance::record(const std::string& type) const {
    for (const StepRecord& r : records)
        if (r.type == type) return &r;
    return nullptr;
}

StepPart21 StepPart21::parse(const std::string& text, const std::string& name, mesh::Deadline* deadline) {
    StepPart21 f;
    f.name_ = name;
    // Keyed per parse (a clock reading and an address): names and types a file chooses
    // cannot be made to collide without knowing the key.
    f.seed_ = mix(static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()) ^
                  reinterpret_cast<std::uintptr_t>(&f));
    Part21Parser parser(text, f, deadline);
    parser.run();
    f.index_types();
    return f;
}

std::size_t StepPart21::id_slot(long long id) const {
    const std::size_t mask = id_slots_.size() - 1;
    std::size_t i = hash_id(id, seed_) & mask;
    while (id_slots_[i].index != kNone && id_slots_[i].id != id) i = (i + 1) & mask;
    return i;
}

std::size_t StepPart21::insert_id(long long id, std::size_t index) {
    if (2 * (id_count_ + 1) > id_slots_.size()) {
        std::vector<IdSlot> old = std::move(id_slots_);
        id_slots_.assign(capacity_for(id_count_ + 1), IdSlot{});
        for (const IdSlot& s : old)
            if (s.index != kNone) id_slots_[id_slot(s.id)] = s;
    }
    IdSlot& slot = id_slots_[id_slot(id)];
    if (slot.index != kNone) return slot.index;
    slot = IdSlot{id, index};
    ++id_count_;
    return kNone;
}

const StepInstance* StepPart21::find(long long id) const {
    if (id_slots_.empty()) return nullptr;
    const IdSlot& s = id_slots_[id_slot(id)];
    return s.index == kNone ? nullptr : &instances_[s.index];
}

std::size_t StepPart21::type_slot(const std::string& type) const {
    const std::size_t mask = type_slots_.size() - 1;
    std::size_t i = hash_text(type, seed_) & mask;
    while (type_slots_[i] != kNone && types_[type_slots_[i]].type != type) i = (i + 1) & mask;
    return i;
}

void StepPart21::index_types() {
    type_slots_.assign(capacity_for(64), kNone);
    for (std::size_t i = 0; i < instances_.size(); ++i) {
        for (const StepRecord& r : instances_[i].records) {
            std::size_t slot = type_slot(r.type);
            if (type_slots_[slot] == kNone) {
                if (2 * (types_.size() + 1) > type_slots_.size()) {
                    type_slots_.assign(capacity_for(types_.size() + 1), kNone);
                    for (std::size_t t = 0; t < types_.size(); ++t) type_slots_[type_slot(types_[t].type)] = t;
                    slot = type_slot(r.type);
                }
                type_slots_[slot] = types_.size();
                types_.push_back(TypeGroup{r.type, {}});
            }
            std::vector<std::size_t>& group = types_[type_slots_[slot]].instances;
            if (group.empty() || group.back() != i) group.push_back(i);
        }
    }
}

std::vector<const StepInstance*> StepPart21::of_type(const std::string& type) const {
    std::vector<const StepInstance*> out;
    if (type_slots_.empty()) return out;
    std::string upper = type;
    make_upper(upper);
    const std::size_t t = type_slots_[type_slot(upper)];
    if (t == kNone) return out;
    out.reserve(types_[t].instances.size());
    for (std::size_t i : types_[t].instances) out.push_back(&instances_[i]);
    return out;
}

}  // namespace trimkit::io
