#include "io/step_units.h"

#include <cmath>
#include <optional>

#include "io/step_geometry.h"

namespace trimkit::io {
namespace {

// Conversion chains (a unit defined by a measure in another conversion-based unit)
// followed at most this deep; real files use one step.
constexpr int kMaxConversionDepth = 8;

const StepValue* param(const StepRecord* r, std::size_t i) {
    return r && i < r->params.size() ? &r->params[i] : nullptr;
}

// SI prefixes of ISO 10303-41 (si_prefix) as powers of ten.
std::optional<double> si_prefix(const StepValue* v) {
    if (!v || v->kind == StepValue::Kind::kUnset) return 1.0;
    if (v->kind != StepValue::Kind::kEnum) return std::nullopt;
    static const std::pair<const char*, double> prefixes[] = {
        {"EXA", 1e18}, {"PETA", 1e15}, {"TERA", 1e12}, {"GIGA", 1e9}, {"MEGA", 1e6}, {"KILO", 1e3},
        {"HECTO", 1e2}, {"DECA", 1e1}, {"DECI", 1e-1}, {"CENTI", 1e-2}, {"MILLI", 1e-3}, {"MICRO", 1e-6},
        {"NANO", 1e-9}, {"PICO", 1e-12}, {"FEMTO", 1e-15}, {"ATTO", 1e-18}};
    for (const auto& [name, factor] : prefixes)
        if (v->text == name) return factor;
    return std::nullopt;
}

// The size of unit #id in SI base units (metres or radians), following conversions.
std::optional<double> unit_size(const StepPart21& file, long long id, int depth) {
    const StepInstance* unit = file.find(id);
    if (!unit || depth > kMaxConversionDepth) return std::nullopt;
    if (const StepRecord* si = unit->record("SI_UNIT")) {
        const StepValue* name = param(si, 1);
        if (!name || name->kind != StepValue::Kind::kEnum) return std::nullopt;
        if (name->text != "METRE" && name->text != "RADIAN") return std::nullopt;
        return si_prefix(param(si, 0));
    }
    const StepRecord* conversion = unit->record("CONVERSION_BASED_UNIT");
    const StepValue* factor_ref = param(conversion, 1);
    if (!factor_ref || factor_ref->kind != StepValue::Kind::kReference) return std::nullopt;
    const StepInstance* measure = file.find(factor_ref->integer);
    if (!measure || measure->records.empty()) return std::nullopt;
    // LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4), #mm) and its plane-angle twin, or
    // the complex (MEASURE_WITH_UNIT(...) ...) form.
    const StepRecord& m = measure->records.front().type == "MEASURE_REPRESENTATION_ITEM" && measure->records.size() > 1
                              ? measure->records[1]
                              : measure->records.front();
    const StepValue* value = param(&m, 0);
    const StepValue* base = param(&m, 1);
    if (value && value->kind == StepValue::Kind::kTyped && !value->items.empty()) value = &value->items.front();
    if (!value || (value->kind != StepValue::Kind::kReal && value->kind != StepValue::Kind::kInteger)) return std::nullopt;
    if (!base || base->kind != StepValue::Kind::kReference) return std::nullopt;
    const std::optional<double> base_size = unit_size(file, base->integer, depth + 1);
    if (!base_size) return std::nullopt;
    const double size = value->real * *base_size;
    if (!(size > 0.0) || !std::isfinite(size)) return std::nullopt;
    return size;
}

bool same(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); }

std::string length_name(double metres) {
    static const std::pair<const char*, double> names[] = {
        {"mm", 1e-3}, {"m", 1.0}, {"cm", 1e-2}, {"um", 1e-6}, {"km", 1e3}, {"in", 0.0254}, {"ft", 0.3048}};
    for (const auto& [name, size] : names)
        if (same(metres, size)) return name;
    return "unit of " + std::to_string(metres) + " m";
}

}  // namespace

StepUnits step_units(const StepPart21& file) {
    std::optional<double> length, angle;
    for (const StepInstance* context : file.of_type("GLOBAL_UNIT_ASSIGNED_CONTEXT")) {
        const StepValue* units = param(context->record("GLOBAL_UNIT_ASSIGNED_CONTEXT"), 0);
        if (!units || units->kind != StepValue::Kind::kList) unsupported_step_entity(file, *context, "units are not a list");
        for (const StepValue& u : units->items) {
            if (u.kind != StepValue::Kind::kReference) continue;
            const StepInstance* unit = file.find(u.integer);
            if (!unit) unsupported_step_entity(file, *context, "unit #" + std::to_string(u.integer) + " is not defined");
            const bool is_length = unit->record("LENGTH_UNIT") != nullptr;
            const bool is_angle = unit->record("PLANE_ANGLE_UNIT") != nullptr;
            if (!is_length && !is_angle) continue;
            const std::optional<double> size = unit_size(file, u.integer, 0);
            if (!size) unsupported_step_entity(file, *unit, "a unit this reader does not understand");
            std::optional<double>& slot = is_length ? length : angle;
            if (slot && !same(*slot, *size)) unsupported_step_entity(file, *unit, "representation contexts with different units");
            slot = size;
        }
    }
    StepUnits out;
    if (length) out.metres_per_length = *length, out.length_name = length_name(*length);
    if (angle) out.radians_per_angle = *angle;
    return out;
}

}  // namespace trimkit::io
