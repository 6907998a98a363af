#include "arguments.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace trimkit::cli {

Arguments::Arguments(const std::vector<std::string>& argv, const std::set<std::string>& flags,
                     const std::set<std::string>& valued) {
    for (size_t i = 0; i < argv.size(); ++i) {
        const std::string& arg = argv[i];
        if (arg.size() < 2 || arg[0] != '-' || (arg[1] != '-' && !std::isalpha(arg[1]))) {
            positionals_.push_back(arg);
            continue;
        }
        std::string name = arg, value;
        const size_t eq = arg.find('=');
        const bool inline_value = eq != std::string::npos;
        if (inline_value) {
            name = arg.substr(0, eq);
            value = arg.substr(eq + 1);
        }
        if (name == "-o") name = "--output";
        if (flags.count(name) && !inline_value) {
            flags_.insert(name);
        } else if (valued.count(name)) {
            if (!inline_value) {
                if (i + 1 >= argv.size()) throw UsageError("option " + name + " needs a value");
                value = argv[++i];
            }
            values_[name] = value;
        } else {
            throw UsageError("unknown option " + arg);
        }
    }
}

std::string Arguments::value(const std::string& name, const std::string& fallback) const {
    auto it = values_.find(name);
    return it == values_.end() ? fallback : it->second;
}

double Arguments::number(const std::string& name, double fallback) const {
    auto it = values_.find(name);
    if (it == values_.end()) return fallback;
    char* end = nullptr;
    const double x = std::strtod(it->second.c_str(), &end);
    if (it->second.empty() || *end != '\0' || !std::isfinite(x))
        throw UsageError("option " + name + " = '" + it->second + "'; expected a number");
    return x;
}

void Arguments::expect_positionals(size_t count, const std::string& usage) const {
    if (positionals_.size() != count) throw UsageError("usage: " + usage);
}

}  // namespace trimkit::cli
