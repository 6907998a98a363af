// Arguments: the command line of one `trimkit` subcommand, split into
// positionals and --options. Options take a value unless declared as flags.
// Errors are UsageError (exit status 2 in main).
#pragma once

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace trimkit::cli {

class UsageError : public std::runtime_error {
public:
    explicit UsageError(const std::string& what) : std::runtime_error(what) {}
};

class Arguments {
public:
    // `flags`: options without a value (e.g. "--json"); `valued`: options with one.
    // Throws UsageError for an unknown option or a missing value.
    Arguments(const std::vector<std::string>& argv, const std::set<std::string>& flags,
              const std::set<std::string>& valued);

    const std::vector<std::string>& positionals() const { return positionals_; }
    bool flag(const std::string& name) const { return flags_.count(name) > 0; }
    bool has(const std::string& name) const { return values_.count(name) > 0; }
    std::string value(const std::string& name, const std::string& fallback) const;
    // Parses the option as a finite number; throws UsageError naming it otherwise.
    double number(const std::string& name, double fallback) const;

    // Throws UsageError unless there are exactly `count` positionals.
    void expect_positionals(size_t count, const std::string& usage) const;

private:
    std::vector<std::string> positionals_;
    std::set<std::string> flags_;
    std::map<std::string, std::string> values_;
};

}  // namespace trimkit::cli
