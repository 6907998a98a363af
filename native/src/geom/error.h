// Error types shared by every layer. Validation happens at public entry points
// (constructors, algorithm entry functions, readers); hot loops assume valid data.
// Python sees InvalidInput as ValueError and the others as RuntimeError.
#pragma once

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

// A file could not be read. `file` and `line` locate the problem (line 0: none);
// what() is already formatted as "FILE:LINE: reason".
class ReadError : public std::runtime_error {
public:
    ReadError(const std::string& file, int line, const std::string& reason)
        : std::runtime_error(file + ":" + std::to_string(line) + ": " + reason),
          file_(file), line_(line), reason_(reason) {}
    const std::string& file() const { return file_; }
    int line() const { return line_; }
    const std::string& reason() const { return reason_; }

private:
    std::string file_;
    int line_;
    std::string reason_;
};

}  // namespace trimkit::geom
