// A parsed JSON document (RFC 8259), for reading the JSON chunk of .glb files.
// Numbers are doubles; objects keep their keys sorted (duplicate keys: the last
// wins); strings keep \u escapes below 0x80 and replace others by '?'.
// Nesting deeper than kMaxJsonDepth is refused so hostile input cannot exhaust the stack.
#pragma once

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace trimkit::io {

constexpr int kMaxJsonDepth = 64;

class JsonValue {
public:
    enum class Kind { kNull, kBool, kNumber, kString, kArray, kObject };

    Kind kind = Kind::kNull;
    std::size_t offset = 0;  // byte offset of the value's first character in the text (for FILE:LINE errors)
    bool boolean = false;
    double number = 0.0;
    std::string string;
    std::vector<JsonValue> array;
    std::map<std::string, JsonValue> object;

    bool is_object() const { return kind == Kind::kObject; }
    bool is_array() const { return kind == Kind::kArray; }
    bool is_number() const { return kind == Kind::kNumber; }
    // The member `key` of an object, or nullptr if absent or not an object.
    const JsonValue* find(const std::string& key) const;
};

// Parses `text`; throws std::runtime_error "JSON offset N: what is wrong".
JsonValue parse_json(const std::string& text);

}  // namespace trimkit::io
