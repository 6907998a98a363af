#include "io/json_value.h"

#include <cmath>
#include <cstdlib>

namespace trimkit::io {
namespace {

class Parser {
public:
    explicit Parser(const std::string& s) : s_(s) {}

    JsonValue document() {
        JsonValue v = value(0);
        space();
        if (pos_ != s_.size()) fail("trailing characters");
        return v;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error("JSON offset " + std::to_string(pos_) + ": " + what);
    }
    void space() {
        while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\n' || s_[pos_] == '\r'))
            ++pos_;
    }
    bool take(char c) {
        space();
        if (pos_ < s_.size() && s_[pos_] == c) {
            ++pos_;
            return true;
        }
        return false;
    }
    void expect(char c) {
        if (!take(c)) fail(std::string("expected '") + c + "'");
    }
    void literal(const char* word) {
        for (const char* p = word; *p; ++p, ++pos_)
            if (pos_ >= s_.size() || s_[pos_] != *p) fail(std::string("expected ") + word);
    }

    std::string string_value() {
        expect('"');
        std::string out;
        while (true) {
            if (pos_ >= s_.size()) fail("unterminated string");
            const char c = s_[pos_++];
            if (c == '"') return out;
            if (static_cast<unsigned char>(c) < 0x20) fail("control character in string");
            if (c != '\\') {
                out += c;
                continue;
            }
            if (pos_ >= s_.size()) fail("unterminated escape");
            const char e = s_[pos_++];
            switch (e) {
                case '"': case '\\': case '/': out += e; break;
                case 'b': out += '\b'; break;
                case 'f': out += '\f'; break;
                case 'n': out += '\n'; break;
                case 'r': out += '\r'; break;
                case 't': out += '\t'; break;
                case 'u': {
                    if (s_.size() - pos_ < 4) fail("short \\u escape");
                    unsigned code = 0;
                    for (int k = 0; k < 4; ++k) {
                        const char h = s_[pos_++];
                        code <<= 4;
                        if (h >= '0' && h <= '9') code |= h - '0';
                        else if (h >= 'a' && h <= 'f') code |= h - 'a' + 10;
                        else if (h >= 'A' && h <= 'F') code |= h - 'A' + 10;
                        else fail("bad \\u escape");
                    }
                    out += code < 0x80 ? static_cast<char>(code) : '?';
                    break;
                }
                default: fail("bad escape");
            }
        }
    }

    JsonValue value(int depth) {
        if (depth > kMaxJsonDepth) fail("nesting deeper than " + std::to_string(kMaxJsonDepth));
        space();
        if (pos_ >= s_.size()) fail("unexpected end");
        JsonValue v;
        v.offset = pos_;
        const char c = s_[pos_];
        if (c == '{') {
            ++pos_;
            v.kind = JsonValue::Kind::kObject;
            if (take('}')) return v;
            do {
                space();
                std::string key = string_value();
                expect(':');
                v.object[key] = value(depth + 1);
            } while (take(','));
            expect('}');
        } else if (c == '[') {
            ++pos_;
            v.kind = JsonValue::Kind::kArray;
            if (take(']')) return v;
            do v.array.push_back(value(depth + 1));
            while (take(','));
            expect(']');
        } else if (c == '"') {
            v.kind = JsonValue::Kind::kString;
            v.string = string_value();
        } else if (c == 't') {
            literal("true");
            v.kind = JsonValue::Kind::kBool;
            v.boolean = true;
        } else if (c == 'f') {
            literal("false");
            v.kind = JsonValue::Kind::kBool;
        } else if (c == 'n') {
            literal("null");
        } else {
            const std::size_t start = pos_;
            while (pos_ < s_.size() && std::string("+-0123456789.eE").find(s_[pos_]) != std::string::npos) ++pos_;
            const std::string text = s_.substr(start, pos_ - start);
            char* stop = nullptr;
            v.number = std::strtod(text.c_str(), &stop);
            if (text.empty() || *stop != '\0' || !std::isfinite(v.number)) {
                pos_ = start;
                fail("bad value");
            }
            v.kind = JsonValue::Kind::kNumber;
        }
        return v;
    }

    const std::string& s_;
    std::size_t pos_ = 0;
};

}  // namespace

const JsonValue* JsonValue::find(const std::string& key) const {
    if (kind != Kind::kObject) return nullptr;
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &it->second;
}

JsonValue parse_json(const std::string& text) { return Parser(text).document(); }

}  // namespace trimkit::io
