#include "io/tbp_format.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "geom/error.h"
#include "io/json_value.h"
#include "io/json_writer.h"
#include "io/output_file.h"

namespace trimkit::io {
namespace {

int line_of(const std::string& text, std::size_t offset) {
    offset = std::min(offset, text.size());
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

}  // namespace

tbp::TbpSolid parse_tbp(const std::string& text, const std::string& file) {
    if (text.size() > kMaxTbpFileBytes)
        throw geom::ReadError(file, 0, "file has " + std::to_string(text.size()) + " bytes, more than the " +
                                           std::to_string(kMaxTbpFileBytes) + " a .tbp file may have");
    JsonValue doc;
    try {
        doc = parse_json(text);
    } catch (const std::runtime_error& e) {
        // parse_json says "JSON offset N: reason"; turn N into a line.
        const std::string what = e.what();
        std::size_t offset = 0;
        const std::size_t colon = what.find(':');
        if (what.rfind("JSON offset ", 0) == 0 && colon != std::string::npos)
            offset = std::strtoull(what.c_str() + 12, nullptr, 10);
        throw geom::ReadError(file, line_of(text, offset),
                              "malformed JSON: " + (colon == std::string::npos ? what : what.substr(colon + 2)));
    }
    auto fail = [&](const JsonValue& at, const std::string& reason) -> geom::ReadError {
        return geom::ReadError(file, line_of(text, at.offset), reason);
    };
    if (!doc.is_object()) throw fail(doc, "expected a JSON object {\"tbp\": 1, \"degree\": n, \"patches\": [...]}");
    const JsonValue* version = doc.find("tbp");
    if (!version) throw fail(doc, "missing member \"tbp\" (the format version, 1)");
    if (!version->is_number() || version->number != 1.0)
        throw fail(*version, "\"tbp\" is not 1; this reader knows version 1 only");
    const JsonValue* degree = doc.find("degree");
    if (!degree) throw fail(doc, "missing member \"degree\"");
    if (!degree->is_number() || degree->number != std::floor(degree->number) || degree->number < 1 ||
        degree->number > geom::kMaxBezierTriangleDegree)
        throw fail(*degree, "degree " + (degree->is_number() ? geom::format_value(degree->number) : std::string("(not a number)")) +
                                "; expected an integer from 1 to " + std::to_string(geom::kMaxBezierTriangleDegree));
    const int n = static_cast<int>(degree->number);
    const int count = geom::BezierTriangle::point_count(n);
    const JsonValue* patches = doc.find("patches");
    if (!patches) throw fail(doc, "missing member \"patches\"");
    if (!patches->is_array()) throw fail(*patches, "\"patches\" is not an array");
    if (patches->array.empty()) throw fail(*patches, "\"patches\" is empty; a solid needs at least one patch");

    tbp::TbpSolid solid;
    if (const JsonValue* name = doc.find("name")) {
        if (name->kind != JsonValue::Kind::kString) throw fail(*name, "\"name\" is not a string");
        solid.name = name->string;
    }
    solid.patches.reserve(patches->array.size());
    for (std::size_t p = 0; p < patches->array.size(); ++p) {
        const JsonValue& patch = patches->array[p];
        if (!patch.is_array()) throw fail(patch, "patch " + std::to_string(p) + " is not an array of points");
        if (static_cast<int>(patch.array.size()) != count)
            throw fail(patch, "patch " + std::to_string(p) + " has " + std::to_string(patch.array.size()) +
                                  " control points, expected " + std::to_string(count) + " for degree " +
                                  std::to_string(n));
        std::vector<Eigen::Vector3d> points(count);
        for (int q = 0; q < count; ++q) {
            const JsonValue& pt = patch.array[q];
            if (!pt.is_array() || pt.array.size() != 3 || !pt.array[0].is_number() || !pt.array[1].is_number() ||
                !pt.array[2].is_number())
                throw fail(pt, "patch " + std::to_string(p) + " point " + std::to_string(q) +
                                   " is not [x, y, z] with three numbers");
            points[q] = {pt.array[0].number, pt.array[1].number, pt.array[2].number};
            if (!points[q].allFinite())  // parse_json refuses these already; kept for safety
                throw fail(pt, "patch " + std::to_string(p) + " point " + std::to_string(q) + " is not finite");
        }
        solid.patches.emplace_back(n, std::move(points));
    }
    return solid;
}

tbp::TbpSolid read_tbp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw geom::ReadError(path, 0, "cannot open the file");
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0) throw geom::ReadError(path, 0, "cannot read the file");
    if (static_cast<std::uint64_t>(size) > kMaxTbpFileBytes)
        throw geom::ReadError(path, 0, "file has " + std::to_string(size) + " bytes, more than the " +
                                           std::to_string(kMaxTbpFileBytes) + " a .tbp file may have");
    in.seekg(0);
    std::string text(static_cast<std::size_t>(size), '\0');
    if (size > 0 && !in.read(&text[0], size)) throw geom::ReadError(path, 0, "cannot read the file");
    return parse_tbp(text, path);
}

std::string tbp_text(const tbp::TbpSolid& solid) {
    tbp::validate(solid);
    std::ostringstream out;
    out << "{\"tbp\": 1, \"degree\": " << solid.degree();
    if (!solid.name.empty()) out << ", \"name\": " << json_string(solid.name);
    out << ", \"patches\": [\n";
    for (std::size_t p = 0; p < solid.patches.size(); ++p) {
        out << "  [";
        const auto& pts = solid.patches[p].points();
        for (std::size_t q = 0; q < pts.size(); ++q)
            out << (q ? ", " : "") << "[" << json_number(pts[q].x()) << ", " << json_number(pts[q].y()) << ", "
                << json_number(pts[q].z()) << "]";
        out << "]" << (p + 1 < solid.patches.size() ? "," : "") << "\n";
    }
    out << "]}\n";
    return out.str();
}

void write_tbp(const tbp::TbpSolid& solid, const std::string& path) {
    const std::string text = tbp_text(solid);
    OutputFile out(path);
    out.write(text);
    out.commit();
}

}  // namespace trimkit::io
