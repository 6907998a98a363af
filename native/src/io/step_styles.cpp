#include "io/step_styles.h"

#include <algorithm>
#include <array>
#include <optional>
#include <string>

namespace trimkit::io {
namespace {

// References followed from a styled item to its colour: STYLED_ITEM ->
// PRESENTATION_STYLE_ASSIGNMENT -> SURFACE_STYLE_USAGE -> SURFACE_SIDE_STYLE ->
// SURFACE_STYLE_FILL_AREA -> FILL_AREA_STYLE -> FILL_AREA_STYLE_COLOUR -> COLOUR_RGB
// is 7; a cycle in a hostile file stops here.
constexpr int kMaxStyleDepth = 10;

// The predefined colours of ISO 10303-46 Sec. 4.4 (draughting_pre_defined_colour).
std::optional<std::array<double, 3>> predefined(const std::string& name) {
    static const std::pair<const char*, std::array<double, 3>> colours[] = {
        {"red", {1, 0, 0}},  {"green", {0, 1, 0}},   {"blue", {0, 0, 1}},  {"yellow", {1, 1, 0}},
        {"magenta", {1, 0, 1}}, {"cyan", {0, 1, 1}}, {"black", {0, 0, 0}}, {"white", {1, 1, 1}}};
    for (const auto& [n, rgb] : colours)
        if (name == n) return rgb;
    return std::nullopt;
}

// The first colour found depth-first under value `v` (references followed, curve
// styles skipped: their colour is a line's, not the face's).
std::optional<std::array<double, 3>> find_colour(const StepPart21& file, const StepValue& v, int depth) {
    if (depth > kMaxStyleDepth) return std::nullopt;
    if (v.kind == StepValue::Kind::kList || v.kind == StepValue::Kind::kTyped) {
        for (const StepValue& item : v.items)
            if (auto c = find_colour(file, item, depth + 1)) return c;
        return std::nullopt;
    }
    if (v.kind != StepValue::Kind::kReference) return std::nullopt;
    const StepInstance* inst = file.find(v.integer);
    if (!inst) return std::nullopt;
    if (const StepRecord* rgb = inst->record("COLOUR_RGB")) {
        std::array<double, 3> c{};
        if (rgb->params.size() < 4) return std::nullopt;
        for (int k = 0; k < 3; ++k) {
            const StepValue& x = rgb->params[k + 1];
            if (x.kind != StepValue::Kind::kReal && x.kind != StepValue::Kind::kInteger) return std::nullopt;
            c[k] = std::clamp(x.real, 0.0, 1.0);
        }
        return c;
    }
    if (const StepRecord* pre = inst->record("DRAUGHTING_PRE_DEFINED_COLOUR"))
        return pre->params.empty() ? std::nullopt : predefined(pre->params[0].text);
    for (const StepRecord& r : inst->records) {
        if (r.type == "CURVE_STYLE" || r.type == "POINT_STYLE") return std::nullopt;
        for (const StepValue& p : r.params)
            if (auto c = find_colour(file, p, depth + 1)) return c;
    }
    return std::nullopt;
}

int colour_index(const std::array<double, 3>& rgb, geom::Model& model) {
    for (std::size_t i = 0; i < model.colors.size(); ++i)
        if (model.colors[i].rgb == rgb) return static_cast<int>(i);
    geom::Color c;
    c.rgb = rgb;
    model.colors.push_back(c);
    return static_cast<int>(model.colors.size()) - 1;
}

}  // namespace

void apply_step_colors(const StepPart21& file, const std::unordered_map<long long, int>& faces,
                       const std::multimap<long long, int>& bodies, geom::Model& model) {
    std::vector<int> own(model.faces.size(), -1), inherited(model.faces.size(), -1);
    for (const char* type : {"STYLED_ITEM", "OVER_RIDING_STYLED_ITEM"})
        for (const StepInstance* styled : file.of_type(type)) {
            const StepRecord* r = styled->record(type);
            if (!r || r->params.size() < 3 || r->params[2].kind != StepValue::Kind::kReference) continue;
            const std::optional<std::array<double, 3>> rgb = find_colour(file, r->params[1], 0);
            if (!rgb) continue;
            const int colour = colour_index(*rgb, model);
            const long long item = r->params[2].integer;
            if (const auto f = faces.find(item); f != faces.end()) own[f->second] = colour;
            const auto [first, last] = bodies.equal_range(item);
            for (auto b = first; b != last; ++b)
                for (int f : model.bodies[b->second].faces) inherited[f] = colour;
        }
    for (std::size_t f = 0; f < model.faces.size(); ++f)
        model.faces[f].color = own[f] >= 0 ? own[f] : inherited[f];
}

}  // namespace trimkit::io
