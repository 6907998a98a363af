// StepPart21: the lexical and syntactic layer of an ISO 10303-21 exchange file (STEP
// "Part 21", editions 1 to 3): the header entities and every entity instance of the
// DATA sections as typed values, knowing nothing of any schema (the translation layer
// decides what a record means). Conventions: keywords and enumerations upper case;
// strings decoded to UTF-8; instances in file order; lines are 1-based lines of the
// source text. References to undefined instances are kept (the translator reports them).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace trimkit::mesh {
class Deadline;
}

namespace trimkit::io {

// One parameter value (ISO 10303-21:2016 Sec. 12.2.2).
struct StepValue {
    enum class Kind {
        kUnset,      // $  (an omitted optional attribute)
        kDerived,    // *  (an attribute derived in a supertype)
        kInteger,    // 42
        kReal,       // 1.5E-3
        kString,     // 'text'
        kEnum,       // .FORWARD.
        kReference,  // #12
        kList,       // (a, b, ...)
        kTyped,      // LENGTH_MEASURE(1.5): a select value named by its type
        kBinary,     // "0FF"
    };
    Kind kind = Kind::kUnset;
    double real = 0.0;      // kReal, and kInteger as a double too
    long long integer = 0;  // kInteger; kReference: the instance name (#12 -> 12)
    // kString: decoded ('' -> ', \X\hh, \X2\..\X0\, \X4\..\X0\ and \S\c to UTF-8, \\ -> \,
    // \P?\ dropped, line breaks inside the string dropped); kEnum: without the dots,
    // upper case ("T", "FORWARD"); kTyped: the type keyword, upper case; kBinary: the
    // characters between the quotes (the unused-bit count digit, then hex digits).
    std::string text;
    std::vector<StepValue> items;  // kList; kTyped: exactly one item
};

// One entity record: KEYWORD(params). A user-defined keyword keeps its leading '!'.
struct StepRecord {
    std::string type;  // upper case
    std::vector<StepValue> params;
};

// One entity instance "#id = ...;".
struct StepInstance {
    long long id = 0;  // #id
    int line = 0;      // line of the '#id' token
    // One record for a simple instance; one per partial record of a complex instance
    // "#id = (A(..) B(..));", in file order.
    std::vector<StepRecord> records;

    // The (first) record of this type (upper case), or nullptr.
    const StepRecord* record(const std::string& type) const;
};

class StepPart21 {
public:
    // Lists (and typed values) nest at most this deep inside a record's parameters:
    // "((1,2),(3,4))" is 2 deep. No schema needs more than a handful of levels.
    static constexpr int kMaxNesting = 64;
    // Largest instance name: 18 digits always fit a long long.
    static constexpr long long kMaxInstanceId = 999'999'999'999'999'999LL;

    // Parses the whole text; `name` is used in errors. Throws geom::ReadError(name,
    // line, reason) for anything that is not Part 21: no "ISO-10303-21;" at the start,
    // no HEADER or DATA section, a section without ENDSEC, no "END-ISO-10303-21;",
    // an unterminated string, comment or list, a malformed token, an instance defined
    // twice, lists nested deeper than kMaxNesting, an instance name out of 1 to
    // kMaxInstanceId, an integer beyond long long, a real beyond double. ANCHOR,
    // REFERENCE and SIGNATURE sections are skipped. Calls deadline->check("STEP
    // parsing") per instance and per value when given (mesh::DeadlineExceeded).
    // Time and memory are linear in the text's size.
    static StepPart21 parse(const std::string& text, const std::string& name,
                            mesh::Deadline* deadline = nullptr);

    const std::string& name() const { return name_; }
    // The strings of FILE_SCHEMA's list, e.g. "AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }".
    const std::vector<std::string>& schemas() const { return schemas_; }
    // The header entities in file order: FILE_DESCRIPTION, FILE_NAME, FILE_SCHEMA, ...
    const std::vector<StepRecord>& header() const { return header_; }
    // Every instance of every DATA section, in file order.
    const std::vector<StepInstance>& instances() const { return instances_; }
    // The instance named #id, or nullptr when it is not defined.
    const StepInstance* find(long long id) const;
    // The instances with a record of this type (upper or lower case), in file order.
    std::vector<const StepInstance*> of_type(const std::string& type) const;

private:
    friend class Part21Parser;

    // Instance name -> index into instances_: open addressing, linear probing, a
    // power-of-two capacity kept at most half full. Hashes are keyed by seed_ (drawn
    // per parse) so that chosen names cannot pile into one run of slots.
    static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
    struct IdSlot {
        long long id = 0;
        std::size_t index = kNone;  // into instances_; kNone: empty slot
    };
    // One entity type and the instances that have it (instance indices, file order).
    struct TypeGroup {
        std::string type;
        std::vector<std::size_t> instances;
    };

    std::size_t id_slot(long long id) const;               // slot of id, or the empty slot for it
    std::size_t type_slot(const std::string& type) const;  // the same in type_slots_
    // Maps id to index and returns kNone; when id is already present, returns its
    // index and changes nothing. Grows the table to stay at most half full.
    std::size_t insert_id(long long id, std::size_t index);
    void index_types();  // fills types_ and type_slots_ from instances_

    std::string name_;
    std::vector<std::string> schemas_;
    std::vector<StepRecord> header_;
    std::vector<StepInstance> instances_;
    std::vector<IdSlot> id_slots_;
    std::size_t id_count_ = 0;
    std::vector<TypeGroup> types_;
    std::vector<std::size_t> type_slots_;  // index into types_, kNone: empty slot
    std::uint64_t seed_ = 0;
};

}  // namespace trimkit::io
