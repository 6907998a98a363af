// IgesParameterCursor: reads one IGES entity's parameters in order, with every
// count, index and pointer checked against what the file actually holds.
// Errors throw geom::ReadError(file, line of the offending parameter, reason),
// the reason naming the entity ("entity 128 (D17): ...").
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "io/iges_file.h"

namespace trimkit::io {

class IgesParameterCursor {
public:
    // Loads the parameters of file.entries()[index] (may throw ReadError).
    IgesParameterCursor(const IgesFile& file, int index);

    const IgesDirectoryEntry& entry() const { return file_.entry(index_); }
    std::size_t remaining() const { return params_.size() - pos_; }
    std::size_t position() const { return pos_; }

    // Required integer / real; empty fields give `fallback` in the *_or forms.
    int integer(const char* what);
    int integer_or(const char* what, int fallback);
    double real(const char* what);
    double real_or(const char* what, double fallback);
    std::string string_or(const char* what, const std::string& fallback);
    // x, y, z as three reals (empty fields are 0).
    Eigen::Vector3d point(const char* what);
    // A directory pointer: 0 (none) or the D number of an entry of this file.
    // Negative values are accepted and returned as is only when allow_negative.
    int pointer(const char* what, bool allow_negative = false);
    // A count of items of `per_item` parameters each, checked against the
    // parameters left: never trust a count from the file for an allocation.
    int count(const char* what, int per_item, int minimum = 0);

    // Skips n parameters (bounded by what is left).
    void skip(std::size_t n);
    // Reads the optional trailing associativity/property pointer lists (IGES
    // 5.3 Sec. 2.2.4.5) when the entity's own parameters end here. Returns the
    // property pointers (possibly empty); malformed tails are ignored.
    std::vector<int> property_pointers();

    [[noreturn]] void fail(const std::string& reason) const;
    // Source line of the next parameter (or of the entity's data).
    int line() const;
    std::string who() const;

private:
    const IgesParam& next(const char* what);

    const IgesFile& file_;
    int index_;
    std::vector<IgesParam> params_;
    std::size_t pos_ = 0;
};

}  // namespace trimkit::io
