#include "io/iges_parameter_cursor.h"

#include <cmath>
#include <limits>

#include "geom/error.h"

namespace trimkit::io {

IgesParameterCursor::IgesParameterCursor(const IgesFile& file, int index)
    : file_(file), index_(index), params_(file.parameters(index)) {}

std::string IgesParameterCursor::who() const {
    const IgesDirectoryEntry& d = entry();
    return "entity " + std::to_string(d.type) + " (D" + std::to_string(d.sequence) + ")";
}

int IgesParameterCursor::line() const {
    if (pos_ < params_.size() && params_[pos_].line > 0) return params_[pos_].line;
    if (!params_.empty() && params_.back().line > 0) return params_.back().line;
    return file_.parameter_line(index_);
}

void IgesParameterCursor::fail(const std::string& reason) const {
    throw geom::ReadError(file_.name(), line(), who() + ": " + reason);
}

const IgesParam& IgesParameterCursor::next(const char* what) {
    if (pos_ >= params_.size()) {
        fail(std::string("parameter list ends before ") + what + " (parameter " +
             std::to_string(pos_ + 1) + ")");
    }
    return params_[pos_++];
}

int IgesParameterCursor::integer_or(const char* what, int fallback) {
    const IgesParam& p = next(what);
    if (p.kind == IgesParam::Kind::kEmpty) return fallback;
    if (p.kind != IgesParam::Kind::kNumber) {
        --pos_;
        fail(std::string(what) + " is a string, expected an integer");
    }
    // Some writers put integers as "1." or "1.0E0"; accept integral reals.
    if (p.number != std::floor(p.number) || std::fabs(p.number) > std::numeric_limits<int>::max()) {
        --pos_;
        fail(std::string(what) + " = " + geom::format_value(p.number) + ", expected an integer");
    }
    return static_cast<int>(p.number);
}

int IgesParameterCursor::integer(const char* what) {
    if (pos_ < params_.size() && params_[pos_].kind == IgesParam::Kind::kEmpty)
        fail(std::string(what) + " is empty, expected an integer");
    return integer_or(what, 0);
}

double IgesParameterCursor::real_or(const char* what, double fallback) {
    const IgesParam& p = next(what);
    if (p.kind == IgesParam::Kind::kEmpty) return fallback;
    if (p.kind != IgesParam::Kind::kNumber) {
        --pos_;
        fail(std::string(what) + " is a string, expected a number");
    }
    return p.number;
}

double IgesParameterCursor::real(const char* what) {
    if (pos_ < params_.size() && params_[pos_].kind == IgesParam::Kind::kEmpty)
        fail(std::string(what) + " is empty, expected a number");
    return real_or(what, 0.0);
}

std::string IgesParameterCursor::string_or(const char* what, const std::string& fallback) {
    const IgesParam& p = next(what);
    if (p.kind == IgesParam::Kind::kString) return p.text;
    return fallback;
}

Eigen::Vector3d IgesParameterCursor::point(const char* what) {
    Eigen::Vector3d x;
    for (int k = 0; k < 3; ++k) x[k] = real_or(what, 0.0);
    return x;
}

int IgesParameterCursor::pointer(const char* what, bool allow_negative) {
    int v = integer_or(what, 0);
    if (v == 0) return 0;
    if (v < 0) {
        if (allow_negative) return v;
        --pos_;
        fail(std::string(what) + " = " + std::to_string(v) + " is not a directory pointer");
    }
    if (file_.index_of(v) < 0) {
        --pos_;
        fail(std::string(what) + " points to D" + std::to_string(v) +
             ", which is not a directory entry of this file (" +
             std::to_string(file_.entries().size()) + " entries)");
    }
    return v;
}

int IgesParameterCursor::count(const char* what, int per_item, int minimum) {
    int n = integer(what);
    if (n < minimum) {
        --pos_;
        fail(std::string(what) + " = " + std::to_string(n) + ", expected at least " +
             std::to_string(minimum));
    }
    if (per_item > 0 && static_cast<long long>(n) * per_item > static_cast<long long>(remaining())) {
        --pos_;
        fail(std::string(what) + " = " + std::to_string(n) + " needs " +
             std::to_string(static_cast<long long>(n) * per_item) + " more parameters but only " +
             std::to_string(remaining() - 1) + " follow");
    }
    return n;
}

void IgesParameterCursor::skip(std::size_t n) { pos_ = std::min(params_.size(), pos_ + n); }

std::vector<int> IgesParameterCursor::property_pointers() {
    std::vector<int> out;
    try {
        if (remaining() == 0) return out;
        int nv = count("associativity count", 1);
        skip(static_cast<std::size_t>(nv));
        if (remaining() == 0) return out;
        int np = count("property count", 1);
        for (int i = 0; i < np; ++i) {
            int p = integer_or("property pointer", 0);
            if (p > 0 && file_.index_of(p) >= 0) out.push_back(p);
        }
    } catch (const geom::ReadError&) {
        // The tail is optional; a malformed one only loses names.
    }
    return out;
}

}  // namespace trimkit::io
