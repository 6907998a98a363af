// IgesFile: the lexical layer of an IGES 5.3 file (fixed 80-column records in
// Start, Global, Directory, Parameter and Terminate sections). It splits records,
// decodes the Global section, the two-line directory entries and each entity's
// free-format parameters, and knows nothing of geometry. Conventions: directory
// entries are addressed by their sequence number "D n" (odd, 1-based, as pointers
// in the file use them); line numbers are 1-based lines of the source text.
#pragma once

#include <string>
#include <vector>

namespace trimkit::io {

// One free-format parameter. Numbers keep their text's integer-ness (no '.' or
// exponent), so pointers and counts can be told from reals.
struct IgesParam {
    enum class Kind { kEmpty, kNumber, kString };
    Kind kind = Kind::kEmpty;
    double number = 0.0;
    bool is_integer = false;
    std::string text;  // the Hollerith string's characters (kString only)
    int line = 0;      // source line the parameter starts on
};

// The Global section, fields numbered as in IGES 5.3 Table 3. Absent or
// malformed fields keep these defaults (and give a warning).
struct IgesGlobal {
    char parameter_delimiter = ',';   // field 1
    char record_delimiter = ';';      // field 2
    std::string sender_product_id;    // field 3
    std::string file_name;            // field 4
    std::string system_id;            // field 5
    double model_scale = 1.0;         // field 13: model units per real-world unit
    int units_flag = 2;               // field 14: 1 in, 2 mm, 3 named, 4 ft, ... 11 microinch
    std::string units_name;           // field 15
    double min_resolution = 0.0;      // field 19 (0: not given)
    double max_coordinate = 0.0;      // field 20 (0: not given)
};

// A directory entry (two 80-column lines, 10 fields of 8 columns each).
struct IgesDirectoryEntry {
    int sequence = 0;         // D number of the first line (odd)
    int line = 0;             // source line of the first D line
    int type = 0;             // field 1 / 11: entity type number
    int parameter_pointer = 0;  // field 2: P sequence number of the first data line
    int structure = 0;        // field 3
    int line_font = 0;        // field 4
    int level = 0;            // field 5
    int view = 0;             // field 6
    int transform = 0;        // field 7: D pointer to a 124, 0 for none
    int label_display = 0;    // field 8
    int blank_status = 0;     // field 9, digits 1-2
    int subordinate = 0;      // field 9, digits 3-4: 0 independent, 1 physically,
                              // 2 logically, 3 both dependent
    int use = 0;              // field 9, digits 5-6
    int hierarchy = 0;        // field 9, digits 7-8
    int line_weight = 0;      // field 12
    int color = 0;            // field 13: 0-8 standard colour, negative: -D of a 314
    int parameter_line_count = 0;  // field 14
    int form = 0;             // field 15
    std::string label;        // field 18
    int subscript = 0;        // field 19
};

class IgesFile {
public:
    // Parses `text` (the whole file); `name` is used in messages. Throws
    // geom::ReadError(name, line, reason) when the text is not IGES, has no
    // directory section, or a directory entry is cut short. Problems confined to
    // one entity's parameters are kept and reported by `parameters()`.
    static IgesFile parse(const std::string& text, const std::string& name);

    const std::string& name() const { return name_; }
    const IgesGlobal& global() const { return global_; }
    const std::vector<IgesDirectoryEntry>& entries() const { return entries_; }
    // Lexical warnings (Global section fields, missing Terminate, ...).
    const std::vector<std::string>& warnings() const { return warnings_; }

    // Index into entries() of directory sequence number `de` (odd, 1-based),
    // or -1 when `de` is not the first line of an entry of this file.
    int index_of(int de) const;
    const IgesDirectoryEntry& entry(int index) const { return entries_[index]; }

    // The parameters of entries()[index] after the leading entity type number,
    // up to the record delimiter. The parameters after the main list (pointers to
    // associativities and properties) are included. Throws geom::ReadError
    // naming the entity's first parameter line when the pointer, line count or
    // back pointers are wrong, the type number differs from the directory's, or
    // the record delimiter is missing.
    std::vector<IgesParam> parameters(int index) const;
    // First source line of entries()[index]'s parameter data (0 if out of range).
    int parameter_line(int index) const;

private:
    struct DataLine {
        std::string data;     // columns 1-64 (P) or 1-72 (G)
        int back_pointer = 0;  // columns 66-72 of P lines
        int line = 0;         // source line
    };

    std::string name_;
    IgesGlobal global_;
    std::vector<IgesDirectoryEntry> entries_;
    std::vector<DataLine> parameter_lines_;  // P section, index = sequence - 1
    std::vector<int> index_by_de_;           // (de - 1) / 2 -> entry index
    std::vector<std::string> warnings_;
};

// Splits free-format parameter text into parameters, reading Hollerith strings
// (nH...), integers and reals (with E or D exponents), empty fields as kEmpty.
// `line_of` gives the source line of each character offset (may be empty).
// Stops after the record delimiter; sets `terminated` when it was found.
// Throws geom::ReadError(file, line, ...) on a malformed token.
std::vector<IgesParam> tokenize_iges_parameters(const std::string& text, char parameter_delimiter,
                                                char record_delimiter,
                                                const std::vector<int>& line_of,
                                                const std::string& file, bool* terminated);

}  // namespace trimkit::io
