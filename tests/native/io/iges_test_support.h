// Builds small IGES texts in memory for the reader tests: fixed 80-column
// records with the Start, Global, Directory, Parameter and Terminate sections.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace trimkit::test {

struct IgesEntitySpec {
    IgesEntitySpec(int type_, std::string params_, int form_ = 0, int transform_ = 0,
                   std::string status_ = "00000000", int color_ = 0, std::string label_ = "")
        : type(type_), params(std::move(params_)), form(form_), transform(transform_),
          status(std::move(status_)), color(color_), label(std::move(label_)) {}
    int type = 0;
    std::string params;  // free-format parameters after the type, ending in the record delimiter
    int form = 0;
    int transform = 0;
    std::string status = "00000000";
    int color = 0;
    std::string label;
    // Parameter lines break at 64 columns (inside strings too, as writers do)
    // or, when narrower, after the last delimiter that fits.
    int width = 64;
};

class IgesTextBuilder {
public:
    // `global` is the Global section's text (delimiters and fields).
    explicit IgesTextBuilder(std::string global = "1H,,1H;,4Htest,8Htest.igs,,,32,38,6,308,15,,1.0,2,2HMM,"
                                                  "1,0.1,13H250101.120000,1.0E-6,100.0,,,11,0;")
        : global_(std::move(global)) {}

    // Adds an entity; returns its directory sequence number (D pointer).
    int add(IgesEntitySpec e) {
        entities_.push_back(std::move(e));
        return static_cast<int>(entities_.size()) * 2 - 1;
    }

    std::string text() const {
        std::string out;
        out += record("trimkit test file", 'S', 1);
        int g = 0;
        for (std::size_t i = 0; i < global_.size(); i += 72) out += record(global_.substr(i, 72), 'G', ++g);
        std::vector<std::vector<std::string>> plines;
        for (std::size_t k = 0; k < entities_.size(); ++k) {
            const char delimiter = global_.rfind("1H", 0) == 0 ? global_[2] : ',';
            const int width = entities_[k].width;
            std::string full = std::to_string(entities_[k].type) + delimiter + entities_[k].params;
            std::vector<std::string> lines;
            std::size_t i = 0;
            while (i < full.size()) {
                std::size_t n = std::min<std::size_t>(static_cast<std::size_t>(width), full.size() - i);
                if (width < 64 && i + n < full.size()) {
                    const std::size_t comma = full.rfind(delimiter, i + n - 1);
                    if (comma != std::string::npos && comma >= i) n = comma + 1 - i;
                }
                lines.push_back(full.substr(i, n));
                i += n;
            }
            plines.push_back(lines);
        }
        int p = 1, d = 0;
        std::string dsec, psec;
        for (std::size_t k = 0; k < entities_.size(); ++k) {
            const IgesEntitySpec& e = entities_[k];
            const int de = static_cast<int>(k) * 2 + 1;
            char a[96], b[96];
            std::snprintf(a, sizeof a, "%8d%8d%8d%8d%8d%8d%8d%8d%8s", e.type, p, 0, 1, 0, 0, e.transform, 0,
                          e.status.c_str());
            std::snprintf(b, sizeof b, "%8d%8d%8d%8d%8d%8s%8s%8s%8d", e.type, 0, e.color,
                          static_cast<int>(plines[k].size()), e.form, "", "", e.label.c_str(), 0);
            dsec += record(a, 'D', ++d);
            dsec += record(b, 'D', ++d);
            for (const std::string& l : plines[k]) {
                char bp[16];
                std::snprintf(bp, sizeof bp, "%8d", de);
                std::string data = l;
                data.resize(64, ' ');
                psec += record(data + bp, 'P', p++);
            }
        }
        out += dsec + psec;
        char t[80];
        std::snprintf(t, sizeof t, "S%7dG%7dD%7dP%7d", 1, g, d, p - 1);
        out += record(t, 'T', 1);
        return out;
    }

    static std::string record(std::string data, char section, int seq) {
        data.resize(72, ' ');
        char s[16];
        std::snprintf(s, sizeof s, "%c%7d", section, seq);
        return data + s + "\n";
    }

private:
    std::string global_;
    std::vector<IgesEntitySpec> entities_;
};

// A bilinear 128 patch over [0,1]² with corners (0,0,0) (10,0,0) (0,10,0) (10,10,0).
inline std::string plane_128_params(const std::string& degree = "1", const std::string& knots_u = "0.,0.,1.,1.") {
    return "1,1," + degree + ",1,0,0,1,0,0," + knots_u +
           ",0.,0.,1.,1.,1.,1.,1.,1.,0.,0.,0.,10.,0.,0.,0.,10.,0.,10.,10.,0.,0.,1.,0.,1.;";
}

}  // namespace trimkit::test
