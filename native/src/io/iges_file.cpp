#include "io/iges_file.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "geom/error.h"

namespace trimkit::io {
namespace {

// IGES 5.3 Sec. 2.1: 80-column records; data in columns 1-72, the section
// letter in column 73, the sequence number in 74-80. Parameter lines keep
// columns 1-64 for data and 66-72 for the directory back pointer.
constexpr int kSectionColumn = 72;     // 0-based column of the section letter
constexpr std::size_t kRecordWidth = 80;  // columns of a fixed-format record
constexpr int kParameterDataWidth = 64;
constexpr int kGlobalDataWidth = 72;
// Lines without a section letter that are tolerated (with a warning) before the
// file is declared unreadable: stray blank-ish lines happen, garbage does not.
constexpr int kMaxStrayLines = 100;
// Longest Hollerith count or number text accepted; longer ones are corrupt.
constexpr std::size_t kMaxNumberText = 64;

bool is_section_letter(char c) {
    return c == 'S' || c == 'G' || c == 'D' || c == 'P' || c == 'T' || c == 'C' || c == 'B';
}

struct RawLine {
    char section = 0;
    std::string data;  // columns 1-72, padded with blanks to 72
    int line = 0;
};

// Section letter and data of one physical line; section 0 for a blank or
// unrecognised line. Accepts 80-column lines (letter at column 73) and lines
// of another width that end in the letter and a sequence number.
RawLine classify_line(const std::string& text, int line_number) {
    RawLine out;
    out.line = line_number;
    if (static_cast<int>(text.size()) > kSectionColumn && is_section_letter(text[kSectionColumn])) {
        out.section = text[kSectionColumn];
        out.data = text.substr(0, kSectionColumn);
        return out;
    }
    // Not 80 wide: look for "<letter><blanks?><digits>" at the end of the line.
    std::size_t end = text.find_last_not_of(" \t");
    if (end == std::string::npos) return out;
    std::size_t k = end + 1;
    while (k > 0 && std::isdigit(static_cast<unsigned char>(text[k - 1]))) --k;
    while (k > 0 && text[k - 1] == ' ') --k;
    if (k == 0 || !is_section_letter(text[k - 1])) return out;
    out.section = text[k - 1];
    out.data = text.substr(0, k - 1);
    if (static_cast<int>(out.data.size()) > kSectionColumn) out.data.resize(kSectionColumn);
    return out;
}

// The records of one physical line: the line itself, or, when it runs 80-column
// records together without line terminators (HP ME's IGES translator; OCCT reads
// such files), each record: the line is a whole number (> 1) of 80-column records,
// each with a section letter in column 73.
std::vector<std::string> line_records(const std::string& line) {
    const std::size_t n = line.size();
    if (n < 2 * kRecordWidth || n % kRecordWidth != 0) return {line};
    for (std::size_t at = 0; at < n; at += kRecordWidth)
        if (!is_section_letter(line[at + kSectionColumn])) return {line};
    std::vector<std::string> records;
    for (std::size_t at = 0; at < n; at += kRecordWidth) records.push_back(line.substr(at, kRecordWidth));
    return records;
}

// The file's records in order: its lines without their terminators, each as
// line_records splits it.
std::vector<std::string> file_records(const std::string& text) {
    std::vector<std::string> records;
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t e = text.find('\n', pos);
        if (e == std::string::npos) e = text.size();
        std::string line = text.substr(pos, e - pos);
        pos = e + 1;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        for (std::string& record : line_records(line)) records.push_back(std::move(record));
    }
    return records;
}

std::string pad(std::string s, std::size_t width) {
    if (s.size() < width) s.append(width - s.size(), ' ');
    return s;
}

// Integer in a fixed-width directory field; blank is 0. Returns false on junk.
bool parse_field_int(const std::string& field, int* value) {
    std::size_t b = field.find_first_not_of(' ');
    if (b == std::string::npos) {
        *value = 0;
        return true;
    }
    std::size_t e = field.find_last_not_of(' ');
    std::string t = field.substr(b, e - b + 1);
    std::size_t i = 0;
    if (t[0] == '-' || t[0] == '+') i = 1;
    if (i == t.size()) return false;
    long long v = 0;
    for (; i < t.size(); ++i) {
        if (!std::isdigit(static_cast<unsigned char>(t[i]))) return false;
        v = v * 10 + (t[i] - '0');
        if (v > std::numeric_limits<int>::max()) return false;
    }
    *value = static_cast<int>(t[0] == '-' ? -v : v);
    return true;
}

// Parses the number in `t` (blanks removed, D exponent allowed).
bool parse_number(std::string t, double* value, bool* is_integer) {
    std::string s;
    s.reserve(t.size());
    for (char c : t)
        if (c != ' ') s.push_back(c == 'D' || c == 'd' ? 'E' : c);
    if (s.empty() || s.size() > kMaxNumberText) return false;
    *is_integer = s.find_first_of(".Ee") == std::string::npos;
    for (char c : s)
        if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == 'E' || c == 'e' ||
              c == '+' || c == '-'))
            return false;
    const char* begin = s.c_str();
    char* stop = nullptr;
    errno = 0;
    double v = std::strtod(begin, &stop);
    if (stop != begin + s.size() || !std::isfinite(v)) return false;
    *value = v;
    return true;
}

int line_at(const std::vector<int>& line_of, std::size_t offset) {
    if (line_of.empty()) return 0;
    return line_of[std::min(offset, line_of.size() - 1)];
}

}  // namespace

std::vector<IgesParam> tokenize_iges_parameters(const std::string& text, char parameter_delimiter,
                                                char record_delimiter,
                                                const std::vector<int>& line_of,
                                                const std::string& file, bool* terminated) {
    std::vector<IgesParam> out;
    *terminated = false;
    std::size_t pos = 0;
    const std::size_t n = text.size();
    while (true) {
        while (pos < n && text[pos] == ' ') ++pos;
        IgesParam p;
        p.line = line_at(line_of, pos);
        if (pos >= n) {
            // Data ended without a record delimiter; a field begun after a
            // delimiter is an empty field only if something preceded it.
            return out;
        }
        // Hollerith string: digits, 'H', then exactly that many characters.
        std::size_t d = pos;
        while (d < n && std::isdigit(static_cast<unsigned char>(text[d]))) ++d;
        bool field_done = false;
        if (d > pos && d < n && (text[d] == 'H' || text[d] == 'h')) {
            if (d - pos > 9) {
                throw geom::ReadError(file, p.line, "Hollerith count '" + text.substr(pos, d - pos) +
                                                        "' is too large");
            }
            std::size_t count = std::stoul(text.substr(pos, d - pos));
            std::size_t start = d + 1;
            if (start + count > n) {
                throw geom::ReadError(file, p.line,
                                      "Hollerith string of " + std::to_string(count) +
                                          " characters runs past the end of the entity's data");
            }
            p.kind = IgesParam::Kind::kString;
            p.text = text.substr(start, count);
            pos = start + count;
            while (pos < n && text[pos] == ' ') ++pos;
            field_done = true;
        }
        if (!field_done) {
            std::size_t e = pos;
            while (e < n && text[e] != parameter_delimiter && text[e] != record_delimiter) ++e;
            std::string field = text.substr(pos, e - pos);
            pos = e;
            if (field.find_first_not_of(' ') != std::string::npos) {
                double v = 0;
                bool integer = false;
                if (!parse_number(field, &v, &integer)) {
                    std::size_t b = field.find_first_not_of(' ');
                    std::string shown = field.substr(b, std::min<std::size_t>(20, field.size() - b));
                    throw geom::ReadError(file, p.line,
                                          "parameter " + std::to_string(out.size() + 1) + " '" +
                                              shown + "' is neither a number nor a Hollerith string");
                }
                p.kind = IgesParam::Kind::kNumber;
                p.number = v;
                p.is_integer = integer;
            }
        }
        out.push_back(std::move(p));
        if (pos >= n) return out;
        char c = text[pos];
        if (c == record_delimiter) {
            *terminated = true;
            return out;
        }
        if (c != parameter_delimiter) {
            throw geom::ReadError(file, line_at(line_of, pos),
                                  std::string("unexpected character '") + c +
                                      "' after parameter " + std::to_string(out.size()) +
                                      "; expected a delimiter");
        }
        ++pos;
    }
}

IgesFile IgesFile::parse(const std::string& text, const std::string& name) {
    IgesFile f;
    f.name_ = name;

    std::vector<RawLine> start, global, directory, parameter, terminate;
    int line_number = 0;
    int stray = 0;
    // Section order S G D P T; a letter going back is an error.
    const std::string order = "SGDPT";
    int current = -1;
    bool any = false;
    for (const std::string& raw : file_records(text)) {
        ++line_number;
        RawLine l = classify_line(raw, line_number);
        if (l.section == 0) {
            if (raw.find_first_not_of(" \t\r\f\x1a") == std::string::npos) continue;  // blank
            if (!any) {
                throw geom::ReadError(name, line_number,
                                      "not an IGES file: no section letter (S, G, D, P or T) in "
                                      "column 73");
            }
            if (++stray > kMaxStrayLines) {
                throw geom::ReadError(name, line_number,
                                      "too many lines without a section letter in column 73");
            }
            f.warnings_.push_back(name + ":" + std::to_string(line_number) +
                                  ": line without a section letter ignored");
            continue;
        }
        if (l.section == 'C' || l.section == 'B') {
            throw geom::ReadError(name, line_number,
                                  std::string("compressed or binary IGES (section letter '") +
                                      l.section + "') is not supported");
        }
        int rank = static_cast<int>(order.find(l.section));
        if (!any && rank > 1) {
            throw geom::ReadError(name, line_number,
                                  "not an IGES file: expected a Start or Global section line, "
                                  "found section '" + std::string(1, l.section) + "'");
        }
        if (rank < current) {
            throw geom::ReadError(name, line_number,
                                  std::string("section '") + l.section + "' line after section '" +
                                      order[current] + "'");
        }
        current = rank;
        any = true;
        switch (l.section) {
            case 'S': start.push_back(std::move(l)); break;
            case 'G': global.push_back(std::move(l)); break;
            case 'D': directory.push_back(std::move(l)); break;
            case 'P': parameter.push_back(std::move(l)); break;
            default: terminate.push_back(std::move(l)); break;
        }
    }
    if (!any) throw geom::ReadError(name, 0, "not an IGES file: empty");
    if (directory.empty()) {
        throw geom::ReadError(name, line_number, "no directory (D) section: file truncated?");
    }
    if (terminate.empty()) f.warnings_.push_back("no Terminate (T) section: file may be truncated");

    // ---- Global section ----
    {
        std::string g;
        std::vector<int> line_of;
        for (const RawLine& l : global) {
            std::string d = pad(l.data, kGlobalDataWidth).substr(0, kGlobalDataWidth);
            g += d;
            line_of.insert(line_of.end(), d.size(), l.line);
        }
        IgesGlobal& G = f.global_;
        std::size_t p = 0;
        auto skip_blanks = [&] {
            while (p < g.size() && g[p] == ' ') ++p;
        };
        // Fields 1 and 2 are single characters given as "1Hc" or left empty.
        char delims[2] = {',', ';'};
        bool ok = true;
        for (int k = 0; k < 2 && ok && p < g.size(); ++k) {
            skip_blanks();
            if (p + 2 < g.size() && g[p] == '1' && (g[p + 1] == 'H' || g[p + 1] == 'h')) {
                delims[k] = g[p + 2];
                p += 3;
            }
            skip_blanks();
            // The separator after field 1 is the (possibly new) parameter delimiter.
            if (p < g.size() && g[p] == delims[0]) {
                ++p;
            } else if (p < g.size() && g[p] == delims[1]) {
                p = g.size();  // the Global section ends here
            } else {
                ok = false;
            }
        }
        if (!ok) f.warnings_.push_back("Global section: delimiters unreadable, using ',' and ';'");
        if (delims[0] == delims[1] || delims[0] == ' ' || std::isdigit((unsigned char)delims[0]) ||
            delims[1] == ' ' || std::isdigit((unsigned char)delims[1])) {
            f.warnings_.push_back("Global section: unusable delimiters, using ',' and ';'");
            delims[0] = ',';
            delims[1] = ';';
            ok = false;
        }
        G.parameter_delimiter = delims[0];
        G.record_delimiter = delims[1];
        std::vector<IgesParam> fields;
        if (ok && p < g.size()) {
            try {
                bool terminated = false;
                std::vector<int> sub_lines(line_of.begin() + static_cast<long>(p), line_of.end());
                fields = tokenize_iges_parameters(g.substr(p), delims[0], delims[1], sub_lines,
                                                  name, &terminated);
            } catch (const geom::ReadError& err) {
                f.warnings_.push_back("Global section unreadable (" + err.reason() +
                                      "); using defaults");
                fields.clear();
            }
        }
        // fields[0] is Global field 3.
        auto field = [&](int number) -> const IgesParam* {
            int i = number - 3;
            if (i < 0 || i >= static_cast<int>(fields.size())) return nullptr;
            return &fields[i];
        };
        auto string_field = [&](int number, std::string* out) {
            const IgesParam* q = field(number);
            if (q && q->kind == IgesParam::Kind::kString) *out = q->text;
        };
        auto real_field = [&](int number, double* out, const char* what) {
            const IgesParam* q = field(number);
            if (!q || q->kind == IgesParam::Kind::kEmpty) return;
            if (q->kind == IgesParam::Kind::kNumber) {
                *out = q->number;
            } else {
                f.warnings_.push_back(std::string("Global field ") + std::to_string(number) + " (" +
                                      what + ") is not a number; default used");
            }
        };
        string_field(3, &G.sender_product_id);
        string_field(4, &G.file_name);
        string_field(5, &G.system_id);
        real_field(13, &G.model_scale, "model scale");
        if (!(G.model_scale > 0)) {
            f.warnings_.push_back("Global field 13 (model scale) is not positive; using 1");
            G.model_scale = 1.0;
        }
        double unit = 1.0;  // IGES 5.3 default: inches
        const IgesParam* uf = field(14);
        if (uf && uf->kind != IgesParam::Kind::kEmpty) real_field(14, &unit, "unit flag");
        G.units_flag = (unit >= 1 && unit <= 11 && unit == std::floor(unit)) ? static_cast<int>(unit)
                                                                            : 0;
        string_field(15, &G.units_name);
        if (G.units_flag == 0) {
            f.warnings_.push_back("Global field 14: unit flag " + geom::format_value(unit) +
                                  " is not 1-11; using the unit name or inches");
            G.units_flag = G.units_name.empty() ? 1 : 3;
        }
        real_field(19, &G.min_resolution, "minimum resolution");
        real_field(20, &G.max_coordinate, "maximum coordinate");
        if (!(G.max_coordinate >= 0)) G.max_coordinate = 0;
        if (!(G.min_resolution >= 0)) G.min_resolution = 0;
    }

    // ---- Directory section ----
    if (directory.size() % 2 != 0) {
        throw geom::ReadError(name, directory.back().line,
                              "directory section has an odd number of lines: file truncated?");
    }
    f.entries_.reserve(directory.size() / 2);
    for (std::size_t i = 0; i + 1 < directory.size(); i += 2) {
        const std::string a = pad(directory[i].data, kSectionColumn);
        const std::string b = pad(directory[i + 1].data, kSectionColumn);
        IgesDirectoryEntry d;
        d.sequence = static_cast<int>(i) + 1;
        d.line = directory[i].line;
        auto get = [&](const std::string& s, int fieldno, int* out, const char* what) {
            std::string t = s.substr(static_cast<std::size_t>((fieldno % 10) * 8 - 8), 8);
            if (!parse_field_int(t, out)) {
                f.warnings_.push_back("D" + std::to_string(d.sequence) + ": directory field " +
                                      std::to_string(fieldno) + " (" + what + ") '" + t +
                                      "' is not an integer");
                *out = 0;
                return false;
            }
            return true;
        };
        // Fields 1-9 on line 1, 11-19 on line 2, eight columns each.
        bool good = get(a, 1, &d.type, "entity type");
        get(a, 2, &d.parameter_pointer, "parameter data");
        get(a, 3, &d.structure, "structure");
        get(a, 4, &d.line_font, "line font");
        get(a, 5, &d.level, "level");
        get(a, 6, &d.view, "view");
        get(a, 7, &d.transform, "transformation matrix");
        get(a, 8, &d.label_display, "label display");
        {
            std::string s = a.substr(64, 8);
            for (char& c : s)
                if (c == ' ') c = '0';
            auto two = [&](int k) {
                int v = 0;
                parse_field_int(s.substr(k, 2), &v);
                return v;
            };
            d.blank_status = two(0);
            d.subordinate = two(2);
            d.use = two(4);
            d.hierarchy = two(6);
        }
        int type2 = 0;
        get(b, 11, &type2, "entity type");
        get(b, 12, &d.line_weight, "line weight");
        get(b, 13, &d.color, "color");
        get(b, 14, &d.parameter_line_count, "parameter line count");
        get(b, 15, &d.form, "form");
        {
            std::string s = b.substr(56, 8);
            std::size_t e = s.find_last_not_of(' ');
            std::size_t s0 = s.find_first_not_of(' ');
            d.label = e == std::string::npos ? std::string() : s.substr(s0, e - s0 + 1);
        }
        get(b, 19, &d.subscript, "subscript");
        if (good && type2 != d.type && type2 != 0) {
            f.warnings_.push_back("D" + std::to_string(d.sequence) + ": entity type " +
                                  std::to_string(d.type) + " on the first line but " +
                                  std::to_string(type2) + " on the second");
            good = false;
        }
        if (!good) d.type = -1;  // skipped by the reader with a warning
        f.entries_.push_back(std::move(d));
    }
    f.index_by_de_.resize(f.entries_.size());
    for (std::size_t i = 0; i < f.entries_.size(); ++i) f.index_by_de_[i] = static_cast<int>(i);

    // ---- Parameter section ----
    f.parameter_lines_.reserve(parameter.size());
    for (const RawLine& l : parameter) {
        DataLine d;
        std::string s = pad(l.data, kSectionColumn);
        d.data = s.substr(0, kParameterDataWidth);
        int bp = 0;
        if (!parse_field_int(s.substr(kParameterDataWidth, 8), &bp)) bp = 0;
        d.back_pointer = bp;
        d.line = l.line;
        f.parameter_lines_.push_back(std::move(d));
    }
    // A file cut short loses its Terminate section and leaves directory entries
    // pointing past the parameter data or the last record unfinished.
    if (terminate.empty()) {
        const int count = static_cast<int>(f.parameter_lines_.size());
        for (const IgesDirectoryEntry& d : f.entries_) {
            if (d.parameter_pointer > count) {
                throw geom::ReadError(name, line_number,
                                      "file truncated: D" + std::to_string(d.sequence) +
                                          " points to parameter line " +
                                          std::to_string(d.parameter_pointer) + " but there are " +
                                          std::to_string(count));
            }
        }
        if (count > 0 &&
            f.parameter_lines_.back().data.find(f.global_.record_delimiter) == std::string::npos) {
            throw geom::ReadError(name, f.parameter_lines_.back().line,
                                  "file truncated: the last parameter record is unfinished");
        }
    }
    return f;
}

int IgesFile::index_of(int de) const {
    if (de <= 0 || de % 2 == 0) return -1;
    std::size_t k = static_cast<std::size_t>(de - 1) / 2;
    if (k >= index_by_de_.size()) return -1;
    return index_by_de_[k];
}

int IgesFile::parameter_line(int index) const {
    if (index < 0 || index >= static_cast<int>(entries_.size())) return 0;
    int p = entries_[index].parameter_pointer;
    if (p < 1 || p > static_cast<int>(parameter_lines_.size())) return entries_[index].line;
    return parameter_lines_[p - 1].line;
}

std::vector<IgesParam> IgesFile::parameters(int index) const {
    const IgesDirectoryEntry& d = entries_.at(index);
    const int count = static_cast<int>(parameter_lines_.size());
    const std::string who = "entity " + std::to_string(d.type) + " (D" + std::to_string(d.sequence) + ")";
    if (d.parameter_pointer < 1 || d.parameter_pointer > count) {
        throw geom::ReadError(name_, d.line,
                              who + ": parameter data pointer " +
                                  std::to_string(d.parameter_pointer) + " is outside the " +
                                  std::to_string(count) + " parameter lines");
    }
    const int first = d.parameter_pointer - 1;
    if (parameter_lines_[first].back_pointer != d.sequence) {
        throw geom::ReadError(name_, parameter_lines_[first].line,
                              who + ": parameter line points back to D" +
                                  std::to_string(parameter_lines_[first].back_pointer) +
                                  ", expected D" + std::to_string(d.sequence));
    }
    // Gather the lines belonging to this entity: the directory's line count
    // when it agrees with the back pointers, else as far as they agree.
    std::string text;
    std::vector<int> line_of;
    int k = first;
    for (; k < count && parameter_lines_[k].back_pointer == d.sequence; ++k) {
        text += parameter_lines_[k].data;
        line_of.insert(line_of.end(), parameter_lines_[k].data.size(), parameter_lines_[k].line);
        if (d.parameter_line_count > 0 && k - first + 1 == d.parameter_line_count) {
            ++k;
            break;
        }
    }
    bool terminated = false;
    std::vector<IgesParam> params = tokenize_iges_parameters(
        text, global_.parameter_delimiter, global_.record_delimiter, line_of, name_, &terminated);
    const int last_line = parameter_lines_[std::max(first, k - 1)].line;
    if (!terminated) {
        throw geom::ReadError(name_, last_line,
                              who + ": parameter data has no record delimiter '" +
                                  std::string(1, global_.record_delimiter) + "'");
    }
    if (params.empty() || params[0].kind != IgesParam::Kind::kNumber || !params[0].is_integer ||
        static_cast<int>(params[0].number) != d.type) {
        throw geom::ReadError(name_, parameter_lines_[first].line,
                              who + ": parameter data does not start with the entity type " +
                                  std::to_string(d.type));
    }
    params.erase(params.begin());
    return params;
}

}  // namespace trimkit::io
