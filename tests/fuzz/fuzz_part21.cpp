// libFuzzer harness: text -> StepPart21 (the Part 21 lexical and syntactic layer, no
// OCCT), then its indexes cross-checked: every instance is found under its name,
// every reference and every record's type is looked up, and a broken invariant
// aborts (libFuzzer records the input as a crash) as an escaping internal error does.
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include "fuzz_support.h"
#include "io/step_part21.h"

namespace {

using trimkit::io::StepPart21;
using trimkit::io::StepValue;

void require(bool condition) {
    if (!condition) std::abort();
}

// Looks up each reference in `v` (lists and typed values nest at most kMaxNesting deep).
void visit(const StepPart21& file, const StepValue& v, int depth) {
    require(depth <= StepPart21::kMaxNesting + 1);
    if (v.kind == StepValue::Kind::kReference) {
        require(v.integer >= 1 && v.integer <= StepPart21::kMaxInstanceId);
        const auto* target = file.find(v.integer);
        require(!target || target->id == v.integer);
    }
    if (v.kind == StepValue::Kind::kTyped) require(v.items.size() == 1);
    for (const StepValue& item : v.items) visit(file, item, depth + 1);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trimkit;
    fuzz::expect_bad_input_at_most([&] {
        const StepPart21 file = StepPart21::parse(fuzz::input_text(data, size), fuzz::kInputName);
        int previous_line = 0;
        std::set<std::string> types;
        std::size_t typed_instances = 0;  // (instance, distinct type of its records) pairs
        for (const io::StepInstance& instance : file.instances()) {
            require(file.find(instance.id) == &instance);
            require(!instance.records.empty());
            require(instance.line >= previous_line);
            previous_line = instance.line;
            std::set<std::string> own;
            for (const io::StepRecord& record : instance.records) {
                require(!record.type.empty());
                require(instance.record(record.type) != nullptr);
                own.insert(record.type);
                for (const StepValue& v : record.params) visit(file, v, 1);
            }
            typed_instances += own.size();
            types.insert(own.begin(), own.end());
        }
        // of_type lists each instance with a record of the type once, in file order.
        std::size_t listed = 0;
        for (const std::string& type : types) {
            const std::vector<const io::StepInstance*> same = file.of_type(type);
            for (std::size_t k = 0; k < same.size(); ++k) {
                require(same[k]->record(type) != nullptr);
                require(k == 0 || same[k - 1] < same[k]);
            }
            listed += same.size();
        }
        require(listed == typed_instances);
        for (const io::StepRecord& record : file.header())
            for (const StepValue& v : record.params) visit(file, v, 1);
    });
    return 0;
}
