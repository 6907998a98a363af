#include "io/step_assembly.h"

#include <algorithm>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "geom/error.h"

namespace trimkit::io {
namespace {

using Eigen::Affine3d;

const char* const kSolidTypes[] = {"MANIFOLD_SOLID_BREP", "BREP_WITH_VOIDS", "SHELL_BASED_SURFACE_MODEL"};

// A string parameter with surrounding blanks removed ("" for anything else): OCCT names
// an occurrence ' ' by its id, as an empty name.
std::string trimmed_text(const StepRecord& r, std::size_t i) {
    if (i >= r.params.size() || r.params[i].kind != StepValue::Kind::kString) return {};
    const std::string& s = r.params[i].text;
    const std::size_t start = s.find_first_not_of(" \t\r\n");
    if (start == std::string::npos) return {};
    return s.substr(start, s.find_last_not_of(" \t\r\n") - start + 1);
}

// The first record of `inst` whose type starts with `prefix` (a supertype's name covers
// its subtypes: PRODUCT_DEFINITION_FORMATION_WITH_SPECIFIED_SOURCE), or nullptr.
const StepRecord* record_prefixed(const StepInstance& inst, const std::string& prefix) {
    for (const StepRecord& r : inst.records)
        if (r.type.compare(0, prefix.size(), prefix) == 0) return &r;
    return nullptr;
}

bool is_solid(const StepInstance& inst) {
    for (const char* type : kSolidTypes)
        if (inst.record(type)) return true;
    return false;
}

// The product structure's links, indexed once (ISO 10303-41 product_definition_schema,
// product_property_definition_schema, product_property_representation_schema; ISO
// 10303-43 representation_schema; ISO 10303-44 product_structure_schema).
class ProductStructure {
public:
    ProductStructure(const StepPart21& file, const StepGeometry& geometry) : file_(file), geometry_(geometry) {
        index_shapes();
        index_relationships();
        index_components();
        check_acyclic();
    }

    std::vector<StepOccurrence> walk();

private:
    [[noreturn]] void fail(const StepInstance& at, const std::string& reason) const {
        throw geom::ReadError(file_.name(), at.line, "#" + std::to_string(at.id) + " " + reason);
    }
    const StepInstance& ref(const StepInstance& from, const StepRecord& r, std::size_t i, const char* what) const;
    const StepRecord& representation_record(const StepInstance& rep) const;
    std::string product_name(long long definition) const;

    void index_shapes();
    void index_relationships();
    void index_components();
    void check_acyclic() const;

    std::set<long long> representations(long long definition) const;
    std::set<long long> linked_closure(std::vector<long long> todo) const;
    void count(const StepInstance& at);
    void definition(long long pd, const Affine3d& placement, const std::vector<std::string>& path,
                    const std::string& occurrence_name, std::vector<long long>& on_path);
    void solids(long long pd, const Affine3d& placement, const std::string& name,
                const std::vector<std::string>& path);
    void items(long long rep, const Affine3d& placement, std::vector<std::pair<long long, Affine3d>>& out,
               std::vector<long long>& on_path);
    Affine3d mapped_item(const StepInstance& item, long long& mapped);
    Affine3d component_placement(const StepInstance& nauo, long long parent, long long child);
    Affine3d item_defined_transformation(const StepInstance& idt, const StepInstance& rep1,
                                         const StepInstance& rep2) const;
    bool holds_item(const StepInstance& rep, long long item) const;

    const StepPart21& file_;
    const StepGeometry& geometry_;
    // PRODUCT_DEFINITION or NEXT_ASSEMBLY_USAGE_OCCURRENCE -> its PRODUCT_DEFINITION_SHAPEs.
    std::unordered_map<long long, std::vector<long long>> shapes_;
    // PRODUCT_DEFINITION_SHAPE -> representations (SHAPE_DEFINITION_REPRESENTATION).
    std::unordered_map<long long, std::vector<long long>> used_;
    // Representation -> representations related to it without transformation.
    std::unordered_map<long long, std::vector<long long>> linked_;
    // PRODUCT_DEFINITION_SHAPE -> CONTEXT_DEPENDENT_SHAPE_REPRESENTATIONs placing it.
    std::unordered_map<long long, std::vector<long long>> placed_by_;
    // PRODUCT_DEFINITION -> its NEXT_ASSEMBLY_USAGE_OCCURRENCEs, file order.
    std::unordered_map<long long, std::vector<const StepInstance*>> components_;
    std::unordered_set<long long> is_component_;
    std::vector<StepOccurrence> occurrences_;
    std::unordered_set<long long> reached_;
    std::size_t steps_ = 0;
};

const StepInstance& ProductStructure::ref(const StepInstance& from, const StepRecord& r, std::size_t i,
                                          const char* what) const {
    if (i >= r.params.size()) fail(from, r.type + " has no " + what);
    const StepValue& v = r.params[i];
    if (v.kind != StepValue::Kind::kReference) fail(from, std::string(what) + " is not a reference");
    const StepInstance* target = file_.find(v.integer);
    if (!target) fail(from, std::string(what) + " #" + std::to_string(v.integer) + " is not defined");
    return *target;
}

// REPRESENTATION(name, items, context_of_items), or a subtype's record of the same
// attributes (ISO 10303-43 representation_schema).
const StepRecord& ProductStructure::representation_record(const StepInstance& rep) const {
    for (const StepRecord& r : rep.records) {
        const std::string& t = r.type;
        const bool representation = t.size() >= 14 && t.compare(t.size() - 14, 14, "REPRESENTATION") == 0;
        if (representation && r.params.size() >= 3 && r.params[1].kind == StepValue::Kind::kList) return r;
    }
    unsupported_step_entity(file_, rep, "a representation of this kind");
}

// PRODUCT_DEFINITION -> PRODUCT_DEFINITION_FORMATION -> PRODUCT: its name, else its id.
std::string ProductStructure::product_name(long long definition) const {
    const StepInstance* pd = file_.find(definition);
    const StepRecord* r = pd ? record_prefixed(*pd, "PRODUCT_DEFINITION") : nullptr;
    if (!r || r->params.size() < 3 || r->params[2].kind != StepValue::Kind::kReference) return {};
    const StepInstance* formation = file_.find(r->params[2].integer);
    const StepRecord* f = formation ? record_prefixed(*formation, "PRODUCT_DEFINITION_FORMATION") : nullptr;
    if (!f || f->params.size() < 3 || f->params[2].kind != StepValue::Kind::kReference) return {};
    const StepInstance* product = file_.find(f->params[2].integer);
    const StepRecord* p = product ? product->record("PRODUCT") : nullptr;
    if (!p) return {};
    const std::string name = trimmed_text(*p, 1);
    return name.empty() ? trimmed_text(*p, 0) : name;
}

// PRODUCT_DEFINITION_SHAPE(name, description, definition) and
// SHAPE_DEFINITION_REPRESENTATION(definition, used_representation).
void ProductStructure::index_shapes() {
    for (const StepInstance* pds : file_.of_type("PRODUCT_DEFINITION_SHAPE")) {
        const StepRecord& r = *pds->record("PRODUCT_DEFINITION_SHAPE");
        shapes_[ref(*pds, r, 2, "definition").id].push_back(pds->id);
    }
    for (const StepInstance* sdr : file_.of_type("SHAPE_DEFINITION_REPRESENTATION")) {
        const StepRecord& r = *sdr->record("SHAPE_DEFINITION_REPRESENTATION");
        used_[ref(*sdr, r, 0, "definition").id].push_back(ref(*sdr, r, 1, "used representation").id);
    }
}

// REPRESENTATION_RELATIONSHIP(name, description, rep_1, rep_2): without transformation a
// link between two representations of one shape (a part's SHAPE_REPRESENTATION and its
// ADVANCED_BREP_SHAPE_REPRESENTATION); with one (REPRESENTATION_RELATIONSHIP_WITH_
// TRANSFORMATION), only as a CONTEXT_DEPENDENT_SHAPE_REPRESENTATION's placement.
void ProductStructure::index_relationships() {
    std::unordered_set<long long> placements;
    for (const StepInstance* cdsr : file_.of_type("CONTEXT_DEPENDENT_SHAPE_REPRESENTATION")) {
        const StepRecord& r = *cdsr->record("CONTEXT_DEPENDENT_SHAPE_REPRESENTATION");
        placements.insert(ref(*cdsr, r, 0, "representation relation").id);
        placed_by_[ref(*cdsr, r, 1, "represented product relation").id].push_back(cdsr->id);
    }
    std::set<const StepInstance*> relationships;
    for (const char* type : {"REPRESENTATION_RELATIONSHIP", "SHAPE_REPRESENTATION_RELATIONSHIP"})
        for (const StepInstance* rr : file_.of_type(type)) relationships.insert(rr);
    for (const StepInstance* rr : relationships) {
        if (rr->record("REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION")) {
            // A geometric assembly without product structure (Part 43 placements alone).
            if (!placements.count(rr->id)) unsupported_step_entity(file_, *rr, "a placement outside an assembly");
            continue;
        }
        if (placements.count(rr->id)) continue;  // a component placed unmoved
        const StepRecord* r = rr->record("REPRESENTATION_RELATIONSHIP");
        if (!r) r = rr->record("SHAPE_REPRESENTATION_RELATIONSHIP");
        const long long rep1 = ref(*rr, *r, 2, "rep_1").id, rep2 = ref(*rr, *r, 3, "rep_2").id;
        linked_[rep1].push_back(rep2);
        linked_[rep2].push_back(rep1);
    }
}

// NEXT_ASSEMBLY_USAGE_OCCURRENCE(id, name, description, relating_product_definition,
// related_product_definition, reference_designator): the related definition is a
// component of the relating one (ISO 10303-44 assembly_component_usage).
void ProductStructure::index_components() {
    for (const StepInstance* nauo : file_.of_type("NEXT_ASSEMBLY_USAGE_OCCURRENCE")) {
        const StepRecord& r = *nauo->record("NEXT_ASSEMBLY_USAGE_OCCURRENCE");
        const StepInstance& parent = ref(*nauo, r, 3, "relating product definition");
        const StepInstance& child = ref(*nauo, r, 4, "related product definition");
        if (!record_prefixed(parent, "PRODUCT_DEFINITION") || !record_prefixed(child, "PRODUCT_DEFINITION"))
            unsupported_step_entity(file_, *nauo, "a component usage not between product definitions");
        components_[parent.id].push_back(nauo);
        is_component_.insert(child.id);
    }
}

// Throws a ReadError naming the NEXT_ASSEMBLY_USAGE_OCCURRENCE that closes a cycle (a
// product definition that is its own component, however far down): depth first,
// iteratively (a hostile file may chain thousands), before any walk from the roots,
// which a cycle without root would escape.
void ProductStructure::check_acyclic() const {
    enum State { kNew, kOnPath, kDone };
    std::unordered_map<long long, State> state;
    for (const StepInstance* first : file_.of_type("NEXT_ASSEMBLY_USAGE_OCCURRENCE")) {  // file order
        const long long start = first->record("NEXT_ASSEMBLY_USAGE_OCCURRENCE")->params[3].integer;
        if (state[start] != kNew) continue;
        std::vector<std::pair<long long, std::size_t>> stack{{start, 0}};
        state[start] = kOnPath;
        while (!stack.empty()) {
            const long long node = stack.back().first;
            const auto found = components_.find(node);
            if (found == components_.end() || stack.back().second >= found->second.size()) {
                state[node] = kDone;
                stack.pop_back();
                continue;
            }
            const StepInstance& nauo = *found->second[stack.back().second++];
            const long long child = nauo.record("NEXT_ASSEMBLY_USAGE_OCCURRENCE")->params[4].integer;
            if (state[child] == kOnPath)
                throw geom::ReadError(file_.name(), nauo.line,
                                      "the assembly contains itself: product definition #" + std::to_string(child) +
                                          " is its own component (NEXT_ASSEMBLY_USAGE_OCCURRENCE #" +
                                          std::to_string(nauo.id) + ")");
            if (state[child] == kDone) continue;
            state[child] = kOnPath;
            stack.emplace_back(child, 0);
        }
    }
}

// The representations of a product definition's shape, with those linked to them.
std::set<long long> ProductStructure::representations(long long definition) const {
    std::vector<long long> todo;
    if (const auto s = shapes_.find(definition); s != shapes_.end())
        for (long long pds : s->second)
            if (const auto u = used_.find(pds); u != used_.end()) todo.insert(todo.end(), u->second.begin(), u->second.end());
    return linked_closure(std::move(todo));
}

// The representations `todo` and those linked to them, directly or not.
std::set<long long> ProductStructure::linked_closure(std::vector<long long> todo) const {
    std::set<long long> reps;
    while (!todo.empty()) {
        const long long rep = todo.back();
        todo.pop_back();
        if (!reps.insert(rep).second) continue;
        if (const auto l = linked_.find(rep); l != linked_.end()) todo.insert(todo.end(), l->second.begin(), l->second.end());
    }
    return reps;
}

void ProductStructure::count(const StepInstance& at) {
    if (++steps_ > kMaxStepOccurrences)
        throw geom::ReadError(file_.name(), at.line,
                              "the assembly places more than " + std::to_string(kMaxStepOccurrences) +
                                  " part occurrences (assemblies holding the same parts many times over)");
}

std::vector<StepOccurrence> ProductStructure::walk() {
    for (const StepInstance* pd : file_.of_type("PRODUCT_DEFINITION")) {
        if (is_component_.count(pd->id)) continue;
        std::vector<long long> on_path;
        definition(pd->id, Affine3d::Identity(), {}, product_name(pd->id), on_path);
    }
    for (const char* type : kSolidTypes)
        for (const StepInstance* s : file_.of_type(type))
            if (!reached_.count(s->id)) unsupported_step_entity(file_, *s, "a solid outside the product structure");
    return std::move(occurrences_);
}

// One occurrence of a product definition placed by `placement`; an assembly's
// components below it, named as read_step_occt's AssemblyWalker names them.
void ProductStructure::definition(long long pd, const Affine3d& placement, const std::vector<std::string>& path,
                                  const std::string& occurrence_name, std::vector<long long>& on_path) {
    const StepInstance& at = *file_.find(pd);
    count(at);
    const auto found = components_.find(pd);
    if (found == components_.end()) return solids(pd, placement, occurrence_name, path);
    if (static_cast<int>(on_path.size()) >= kMaxStepAssemblyDepth)
        throw geom::ReadError(file_.name(), at.line,
                              "assembly nesting deeper than " + std::to_string(kMaxStepAssemblyDepth) +
                                  " levels (NEXT_ASSEMBLY_USAGE_OCCURRENCE chain)");
    std::vector<std::string> below = path;
    below.push_back(occurrence_name.empty() ? product_name(pd) : occurrence_name);
    solids(pd, placement, product_name(pd), below);  // an assembly's own geometry, if any
    on_path.push_back(pd);
    for (const StepInstance* nauo : found->second) {
        const StepRecord& r = *nauo->record("NEXT_ASSEMBLY_USAGE_OCCURRENCE");
        const long long child = ref(*nauo, r, 4, "related product definition").id;
        if (std::find(on_path.begin(), on_path.end(), child) != on_path.end())
            throw geom::ReadError(file_.name(), nauo->line,
                                  "the assembly contains itself: product definition #" + std::to_string(child) +
                                      " is its own component (NEXT_ASSEMBLY_USAGE_OCCURRENCE #" +
                                      std::to_string(nauo->id) + ")");
        std::string name = trimmed_text(r, 1);
        if (name.empty()) name = trimmed_text(r, 0);
        if (name.empty()) name = product_name(child);
        definition(child, placement * component_placement(*nauo, pd, child), below, name, on_path);
    }
    on_path.pop_back();
}

// The solids of a product definition's own shape, each an occurrence.
void ProductStructure::solids(long long pd, const Affine3d& placement, const std::string& name,
                              const std::vector<std::string>& path) {
    std::vector<std::pair<long long, Affine3d>> found;
    for (long long rep : representations(pd)) {
        std::vector<long long> on_path;
        items(rep, Affine3d::Identity(), found, on_path);
    }
    const std::string part = product_name(pd);
    std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t i = 0; i < found.size(); ++i) {
        const auto& solid = found[i];
        // A representation both linked and mapped unmoved is read twice: keep it once.
        bool repeated = false;
        for (std::size_t k = i; k > 0 && found[k - 1].first == solid.first && !repeated; --k)
            repeated = found[k - 1].second.isApprox(solid.second);
        if (repeated) continue;
        count(*file_.find(solid.first));
        reached_.insert(solid.first);
        StepOccurrence o;
        o.solid = solid.first;
        o.transform = placement * solid.second;
        o.name = name;
        o.path = path;
        o.part = part;
        occurrences_.push_back(std::move(o));
    }
}

// The solids among a representation's items (placed by `placement`), those of
// MAPPED_ITEMs' representations placed by their maps. Placements (AXIS2_PLACEMENT_3D)
// are frames, not shapes; any other item is not read here.
void ProductStructure::items(long long rep_id, const Affine3d& placement,
                             std::vector<std::pair<long long, Affine3d>>& out, std::vector<long long>& on_path) {
    const StepInstance& rep = *file_.find(rep_id);
    if (std::find(on_path.begin(), on_path.end(), rep_id) != on_path.end())
        fail(rep, "maps itself (a MAPPED_ITEM cycle)");
    if (static_cast<int>(on_path.size()) >= kMaxStepAssemblyDepth)
        fail(rep, "MAPPED_ITEMs nest deeper than " + std::to_string(kMaxStepAssemblyDepth) + " levels");
    on_path.push_back(rep_id);
    const StepRecord& r = representation_record(rep);
    for (std::size_t i = 0; i < r.params[1].items.size(); ++i) {
        const StepValue& v = r.params[1].items[i];
        if (v.kind != StepValue::Kind::kReference || !file_.find(v.integer)) fail(rep, "has an undefined item");
        const StepInstance& item = *file_.find(v.integer);
        if (is_solid(item)) {
            out.emplace_back(item.id, placement);
        } else if (item.record("MAPPED_ITEM")) {
            count(item);
            long long mapped = 0;
            const Affine3d map = mapped_item(item, mapped);
            for (long long linked : linked_closure({mapped})) items(linked, placement * map, out, on_path);
        } else if (!item.record("AXIS2_PLACEMENT_3D")) {
            unsupported_step_entity(file_, item, "a shape representation item of this kind");
        }
    }
    on_path.pop_back();
}

// MAPPED_ITEM(name, mapping_source, mapping_target) with REPRESENTATION_MAP(mapping_origin,
// mapped_representation): the mapped representation's items placed so that its
// mapping_origin lands on mapping_target (ISO 10303-43 Sec. 4.4.3 mapped_item), i.e.
// by P(target) * P(origin)^-1. `mapped`: the mapped representation.
Affine3d ProductStructure::mapped_item(const StepInstance& item, long long& mapped) {
    const StepRecord& r = *item.record("MAPPED_ITEM");
    const StepInstance& map = ref(item, r, 1, "mapping source");
    const StepRecord* m = map.record("REPRESENTATION_MAP");
    if (!m) unsupported_step_entity(file_, map, "a mapping source of this kind");
    const StepInstance& origin = ref(map, *m, 0, "mapping origin");
    mapped = ref(map, *m, 1, "mapped representation").id;
    const StepInstance& target = ref(item, r, 2, "mapping target");
    if (!origin.record("AXIS2_PLACEMENT_3D")) unsupported_step_entity(file_, origin, "a mapping origin of this kind");
    if (!target.record("AXIS2_PLACEMENT_3D")) unsupported_step_entity(file_, target, "a mapping target of this kind");
    return geometry_.placement(target.id) * geometry_.placement(origin.id).inverse();
}

bool ProductStructure::holds_item(const StepInstance& rep, long long item) const {
    const StepRecord& r = representation_record(rep);
    for (const StepValue& v : r.params[1].items)
        if (v.kind == StepValue::Kind::kReference && v.integer == item) return true;
    return false;
}

// Where an assembly places one component (AP214/AP242 recommended practice for
// assemblies, "context dependent shape representation"): the NAUO's
// PRODUCT_DEFINITION_SHAPE is the represented_product_relation of one
// CONTEXT_DEPENDENT_SHAPE_REPRESENTATION, whose representation_relation relates the
// component's representation (rep_1) to the assembly's (rep_2), as a complex instance
// with REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION. A relation written the other
// way round (rep_1 the assembly's) is taken the NAUO's way, its transform inverted
// (as OCCT's STEPControl_ActorRead does).
Affine3d ProductStructure::component_placement(const StepInstance& nauo, long long parent, long long child) {
    const StepInstance* cdsr = nullptr;
    if (const auto s = shapes_.find(nauo.id); s != shapes_.end())
        for (long long pds : s->second)
            if (const auto p = placed_by_.find(pds); p != placed_by_.end())
                for (long long c : p->second) {
                    if (cdsr && cdsr->id != c) unsupported_step_entity(file_, nauo, "a component placed twice");
                    cdsr = file_.find(c);
                }
    if (!cdsr) unsupported_step_entity(file_, nauo, "a component without CONTEXT_DEPENDENT_SHAPE_REPRESENTATION");
    const StepInstance& rr = ref(*cdsr, *cdsr->record("CONTEXT_DEPENDENT_SHAPE_REPRESENTATION"), 0,
                                 "representation relation");
    const StepRecord* r = rr.record("REPRESENTATION_RELATIONSHIP");
    if (!r) r = rr.record("SHAPE_REPRESENTATION_RELATIONSHIP");
    if (!r) unsupported_step_entity(file_, rr, "a representation relation of this kind");
    const StepInstance& rep1 = ref(rr, *r, 2, "rep_1");
    const StepInstance& rep2 = ref(rr, *r, 3, "rep_2");
    const std::set<long long> child_reps = representations(child), parent_reps = representations(parent);
    bool reversed = false;
    if (!child_reps.count(rep1.id) || !parent_reps.count(rep2.id)) {
        reversed = child_reps.count(rep2.id) && parent_reps.count(rep1.id);
        if (!reversed) unsupported_step_entity(file_, rr, "relates representations of neither product definition");
    }
    const StepRecord* with = rr.record("REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION");
    if (!with) return Affine3d::Identity();  // a component placed unmoved
    const StepInstance& op = ref(rr, *with, 0, "transformation operator");
    if (!op.record("ITEM_DEFINED_TRANSFORMATION"))
        unsupported_step_entity(file_, op, "a transformation operator of this kind");
    const Affine3d t = item_defined_transformation(op, rep1, rep2);
    return reversed ? t.inverse() : t;
}

// ITEM_DEFINED_TRANSFORMATION(name, description, transform_item_1, transform_item_2):
// the map taking placement item 1 (a frame of rep_1) onto item 2 (a frame of rep_2),
// P(item2) * P(item1)^-1 (ISO 10303-43 item_defined_transformation; the recommended
// practice for assemblies). Items written in each other's representation are swapped
// back (as OCCT's ComputeTransformation does).
Affine3d ProductStructure::item_defined_transformation(const StepInstance& idt, const StepInstance& rep1,
                                                       const StepInstance& rep2) const {
    const StepRecord& r = *idt.record("ITEM_DEFINED_TRANSFORMATION");
    const StepInstance* item1 = &ref(idt, r, 2, "transform item 1");
    const StepInstance* item2 = &ref(idt, r, 3, "transform item 2");
    for (const StepInstance* item : {item1, item2})
        if (!item->record("AXIS2_PLACEMENT_3D")) unsupported_step_entity(file_, *item, "a transform item of this kind");
    const bool in_place = holds_item(rep1, item1->id) && holds_item(rep2, item2->id);
    if (!in_place && holds_item(rep2, item1->id) && holds_item(rep1, item2->id)) std::swap(item1, item2);
    return geometry_.placement(item2->id) * geometry_.placement(item1->id).inverse();
}

}  // namespace

bool step_has_assembly(const StepPart21& file) {
    for (const char* type : {"NEXT_ASSEMBLY_USAGE_OCCURRENCE", "MAPPED_ITEM", "ITEM_DEFINED_TRANSFORMATION"})
        if (!file.of_type(type).empty()) return true;
    return false;
}

std::vector<StepOccurrence> step_occurrences(const StepPart21& file, const StepGeometry& geometry) {
    return ProductStructure(file, geometry).walk();
}

namespace {

// True when the instances only repeat the bodies: each body placed once, unmoved.
bool trivial_instances(const geom::Model& model) {
    std::vector<int> uses(model.bodies.size(), 0);
    for (const geom::Instance& i : model.instances) {
        if (!i.transform.matrix().isIdentity(1e-12)) return false;
        if (++uses[static_cast<std::size_t>(i.body)] > 1) return false;
    }
    return std::all_of(uses.begin(), uses.end(), [](int u) { return u == 1; });
}

}  // namespace

void place_step_occurrences(const std::vector<StepOccurrence>& occurrences,
                            const std::multimap<long long, int>& bodies, geom::Model& model,
                            const std::string& file_name) {
    for (const StepOccurrence& o : occurrences) {
        const auto range = bodies.equal_range(o.solid);
        for (auto b = range.first; b != range.second; ++b) {
            geom::Body& body = model.bodies[static_cast<std::size_t>(b->second)];
            if (body.name.empty() || body.name == "NONE") body.name = o.part;
            if (model.instances.size() >= kMaxStepOccurrences)
                throw geom::ReadError(file_name, 0, "more than " + std::to_string(kMaxStepOccurrences) +
                                                     " placed bodies (shells of placed solids)");
            geom::Instance instance;
            instance.body = b->second;
            instance.transform = o.transform;
            instance.name = o.name.empty() ? body.name : o.name;
            instance.path = o.path;
            model.instances.push_back(std::move(instance));
        }
    }
    if (trivial_instances(model)) model.instances.clear();
}

}  // namespace trimkit::io
