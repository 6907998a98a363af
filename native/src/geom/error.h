// Error types shared by every layer. Validation happens at public entry points
// (constructors, algorithm entry functions, readers); hot loops assume valid data.
// Python sees InvalidInput as ValueError and the others as RuntimeError.
#pragma once

#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

namespace trimkit::geom {

// The caller passed data that violates a documented precondition
// (a decreasing knot vector, a negative weight, a NaN coordinate).
class InvalidInput : public std::invalid_argument {
public:
    explicit InvalidInput(const std::string& what) : std::invalid_argument(what) {}
};

// A computation met a degenerate configuration it cannot resolve
// (a zero rational denominator, a singular fitting system).
class NumericalFailure : public std::runtime_error {
public:
    explicit NumericalFailure(const std::string& what) : std::runtime_error(what) {}
};

// A file could not be read. `file` and `line` locate the problem; what() is
// formatted as "FILE:LINE: reason", or "FILE: reason" when line is 0 (no line).
class ReadError : public std::runtime_error {
public:
    ReadError(const std::string& file, int line, const std::string& reason)
        : std::runtime_error(file + (line > 0 ? ":" + std::to_string(line) : std::string()) +
                             ": " + reason),
          file_(file), line_(line), reason_(reason) {}
    const std::string& file() const { return file_; }
    int line() const { return line_; }
    const std::string& reason() const { return reason_; }

private:
    std::string file_;
    int line_;
    std::string reason_;
};

// Shortest decimal text (6 to 17 significant digits) that reads back as x, for
// error messages: 0.2 prints as "0.2", knots 1e-12 apart still print apart.
inline std::string format_value(double x) {
    std::string text;
    for (int digits = 6; digits <= 17; ++digits) {
        std::ostringstream out;
        out.precision(digits);
        out << x;
        text = out.str();
        if (std::strtod(text.c_str(), nullptr) == x) break;
    }
    return text;
}

}  // namespace trimkit::geom
