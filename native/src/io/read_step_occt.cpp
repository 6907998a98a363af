// read_step through Open CASCADE (built only with TRIMKIT_WITH_OCCT): STEPCAFControl_Reader
// reads the file into an XCAF document (names, colours, the assembly tree; OCCT's own
// ShapeFix runs during the transfer). Each part definition is translated once
// (add_shape, occt_shape.h) and placed by an Instance per occurrence in the tree,
// with the path of assembly names above it; a file without assemblies gives its
// bodies once, unplaced. OCCT's memory faults on broken files become read errors.
#include "io/read_step.h"

#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Quantity_Color.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <StepBasic_ProductDefinition.hxx>
#include <StepRepr_NextAssemblyUsageOccurrence.hxx>
#include <Interface_InterfaceModel.hxx>
#include <StepData_StepModel.hxx>
#include <Standard_ErrorHandler.hxx>
#include <TCollection_AsciiString.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDF_Tool.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopLoc_Location.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XSControl_WorkSession.hxx>

#include <array>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "geom/error.h"
#include "io/occt_progress.h"
#include "io/occt_shape.h"
#include "io/occt_support.h"
#include "io/step_geometry.h"
#include "io/step_instance_names.h"

namespace trimkit::io {

namespace {

// Assembly nesting followed at most (real files nest a few levels; a cyclic reference
// in a hostile file stops here).
constexpr int kMaxAssemblyDepth = 64;
// Part occurrences (placed instances) one file may make. Depth alone does not bound
// them: assemblies that each hold the one below twice make 2^depth occurrences. The
// largest shared assembly (as1-oc-214-mat.stp) has 18.
constexpr std::size_t kMaxOccurrences = 200'000;

std::string label_name(const TDF_Label& label) {
    Handle(TDataStd_Name) name;
    if (!occt_guarded([&] { return label.FindAttribute(TDataStd_Name::GetID(), name); })) return {};
    return TCollection_AsciiString(name->Get()).ToCString();  // UTF-8
}

// Names and colours of the document's shapes (XCAF), colours turned into Model::colors.
class StepStyles {
public:
    explicit StepStyles(const Handle(TDocStd_Document)& doc)
        : shapes_(XCAFDoc_DocumentTool::ShapeTool(doc->Main())),
          colors_(XCAFDoc_DocumentTool::ColorTool(doc->Main())) {}

    const Handle(XCAFDoc_ShapeTool)& shapes() const { return shapes_; }

    // The name of the shape's label (an instance's own name, else its part's); "" if none.
    std::string name(const TopoDS_Shape& shape) const {
        TDF_Label label;
        if (!shapes_->Search(shape, label)) return {};
        std::string own = label_name(label);
        TDF_Label part;
        if (own.empty() && XCAFDoc_ShapeTool::GetReferredShape(label, part)) own = label_name(part);
        return own;
    }

    // Index into model.colors of the shape's surface (or generic) colour, -1 if none;
    // equal colours share one entry.
    int color(const TopoDS_Shape& shape, geom::Model& model) {
        Quantity_Color c;
        if (!colors_->GetColor(shape, XCAFDoc_ColorSurf, c) && !colors_->GetColor(shape, XCAFDoc_ColorGen, c))
            return -1;
        double r = 0, g = 0, b = 0;
        c.Values(r, g, b, Quantity_TOC_sRGB);  // the file's own numbers
        const std::array<double, 3> rgb{r, g, b};
        const auto found = index_.find(rgb);
        if (found != index_.end()) return found->second;
        geom::Color color;
        color.rgb = rgb;
        model.colors.push_back(color);
        return index_[rgb] = static_cast<int>(model.colors.size()) - 1;
    }

    ShapeStyle style() {
        ShapeStyle s;
        s.color = [this](const TopoDS_Shape& shape, geom::Model& model) { return color(shape, model); };
        s.name = [this](const TopoDS_Shape& shape) { return name(shape); };
        return s;
    }

private:
    Handle(XCAFDoc_ShapeTool) shapes_;
    Handle(XCAFDoc_ColorTool) colors_;
    std::map<std::array<double, 3>, int> index_;
};

// Walks the XCAF tree: each part label translated once, each occurrence an Instance.
class AssemblyWalker {
public:
    AssemblyWalker(geom::Model& model, StepStyles& styles, ReadMonitor& monitor)
        : model_(model), styles_(styles), monitor_(monitor) {}

    void walk(const TDF_Label& label, const Eigen::Affine3d& placement, const std::vector<std::string>& path,
              const std::string& occurrence_name, int depth) {
        if (depth > kMaxAssemblyDepth) throw std::runtime_error("assembly nesting deeper than 64 levels");
        monitor_.check();
        const Handle(XCAFDoc_ShapeTool)& shapes = styles_.shapes();
        if (occt_guarded([&] { return XCAFDoc_ShapeTool::IsAssembly(label); })) {
            std::vector<std::string> below = path;
            below.push_back(occurrence_name.empty() ? label_name(label) : occurrence_name);
            TDF_LabelSequence components;
            occt_guarded([&] { XCAFDoc_ShapeTool::GetComponents(label, components, false); });
            for (int i = 1; i <= components.Length(); ++i) {
                const TDF_Label component = components.Value(i);
                TDF_Label part;
                if (!occt_guarded([&] { return XCAFDoc_ShapeTool::GetReferredShape(component, part); })) continue;
                const Eigen::Affine3d local = occt_guarded(
                    [&] { return to_eigen(XCAFDoc_ShapeTool::GetLocation(component).Transformation()); });
                std::string name = label_name(component);
                if (name.empty()) name = label_name(part);
                walk(part, placement * local, below, name, depth + 1);
            }
            return;
        }
        const std::vector<int>& bodies = part_bodies(label, shapes);
        for (int body : bodies) {
            if (model_.instances.size() >= kMaxOccurrences)
                throw std::runtime_error("the assembly places more than " + std::to_string(kMaxOccurrences) +
                                         " part occurrences (assemblies holding the same parts many times over)");
            geom::Instance instance;
            instance.body = body;
            instance.transform = placement;
            instance.name = occurrence_name.empty() ? model_.bodies[body].name : occurrence_name;
            instance.path = path;
            model_.instances.push_back(std::move(instance));
        }
    }

private:
    const std::vector<int>& part_bodies(const TDF_Label& label, const Handle(XCAFDoc_ShapeTool)& shapes) {
        const std::string key = label_key(label);
        const auto found = parts_.find(key);
        if (found != parts_.end()) return found->second;
        const TopoDS_Shape shape = occt_guarded([&] { return XCAFDoc_ShapeTool::GetShape(label); });
        std::vector<int> bodies;
        if (!shape.IsNull())
            bodies = add_shape(model_, shape, styles_.style(), label_name(label), face_number_, &monitor_);
        (void)shapes;
        return parts_[key] = std::move(bodies);
    }

    static std::string label_key(const TDF_Label& label) {
        TCollection_AsciiString entry;
        occt_guarded([&] { TDF_Tool::Entry(label, entry); });
        return entry.ToCString();
    }

    geom::Model& model_;
    StepStyles& styles_;
    ReadMonitor& monitor_;
    std::map<std::string, std::vector<int>> parts_;
    int face_number_ = 0;
};

// Instances that only repeat what the bodies say (every body once, unmoved) are dropped.
void drop_trivial_instances(geom::Model& model) {
    std::vector<int> uses(model.bodies.size(), 0);
    for (const geom::Instance& i : model.instances) {
        if (!i.transform.matrix().isIdentity(1e-12)) return;
        if (++uses[i.body] > 1) return;
    }
    for (int u : uses)
        if (u != 1) return;
    model.instances.clear();
}

// The reader's first failure messages, for a file OCCT cannot read.
std::string read_failures(STEPCAFControl_Reader& reader) {
    const Interface_CheckIterator checks = reader.ChangeReader().WS()->ModelCheckList();
    std::string text;
    int count = 0;
    for (Interface_CheckIterator it = checks; it.More() && count < 3; it.Next()) {
        const Handle(Interface_Check)& check = it.Value();
        for (int i = 1; i <= check->NbFails() && count < 3; ++i) {
            const std::string fail = check->CFail(i);
            if (fail.find("DATA NOT AVAILABLE") != std::string::npos) continue;  // no check was run
            text += (text.empty() ? "" : "; ") + fail +
                    (it.Number() > 0 ? " (entity " + std::to_string(it.Number()) + ")" : "");
            ++count;
        }
    }
    return text;
}

// OCCT gives no face of the file: trimkit's own reader may still take it. OCCT parsed
// the file but transferred no face (ADVANCED_BREP_REPRESENTATION without product
// structure: NIST's switcharm.step), or cannot parse it at all (a UTF-8 byte order mark).
struct OcctLeavesFile : geom::ReadError {
    using geom::ReadError::ReadError;
};

// Bytes of the file's head searched for its first token.
constexpr size_t kHeaderProbeBytes = 4096;

// Throws a ReadError unless the file opens and starts with the ISO 10303-21 header.
void check_step_header(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw geom::ReadError(path, 0, "cannot open the file");
    std::string head(kHeaderProbeBytes, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<size_t>(in.gcount()));
    // Blanks and comments may come first (Part 21 allows a comment wherever blanks
    // are; OCCT's parser skips them). A UTF-8 byte order mark (a file saved by a text
    // editor) stops OCCT's parser but not the own reader.
    const bool bom = head.compare(0, 3, "\xEF\xBB\xBF") == 0;
    size_t start = head.find_first_not_of(" \t\r\n", bom ? 3 : 0);
    while (start != std::string::npos && head.compare(start, 2, "/*") == 0) {
        const size_t end = head.find("*/", start + 2);
        start = end == std::string::npos ? end : head.find_first_not_of(" \t\r\n", end + 2);
    }
    if (start == std::string::npos || head.compare(start, 12, "ISO-10303-21") != 0)
        throw geom::ReadError(path, 1, "not a STEP file (it does not start with 'ISO-10303-21;')");
    if (bom)
        throw OcctLeavesFile(path, 1, "Open CASCADE does not read a STEP file that starts with a byte order mark");
}

// Throws a ReadError if the file's assembly structure (NEXT_ASSEMBLY_USAGE_OCCURRENCE:
// relating product definition -> related one) refers to a missing entity, has a cycle,
// or nests deeper than kMaxAssemblyDepth. OCCT 7.6's transfer follows it recursively without a check
// (STEPControl_ActorRead::TransferEntity): a product that contains itself overflows
// the stack, which no signal catcher survives (the process, Blender, is killed).
// Found by fuzz_step: tests/fuzz/regressions/step/assembly_missing_component.stp.
void check_assembly_graph(const std::string& path, const Handle(Interface_InterfaceModel)& model) {
    if (model.IsNull()) return;
    // The entity's #number in the file.
    const Handle(StepData_StepModel) step = Handle(StepData_StepModel)::DownCast(model);
    const auto label = [&](const Handle(Standard_Transient)& e) { return step.IsNull() ? model->Number(e) : step->IdentLabel(e); };
    std::map<const Standard_Transient*, std::vector<const Standard_Transient*>> below;
    std::map<const Standard_Transient*, int> number;
    for (int i = 1; i <= model->NbEntities(); ++i) {
        const auto nauo = Handle(StepRepr_NextAssemblyUsageOccurrence)::DownCast(model->Value(i));
        if (nauo.IsNull()) continue;
        // A reference to a missing entity: OCCT's transfer then recurses without end too.
        if (nauo->RelatingProductDefinitionAP242().Value().IsNull() ||
            nauo->RelatedProductDefinitionAP242().Value().IsNull())
            throw geom::ReadError(path, 0, "NEXT_ASSEMBLY_USAGE_OCCURRENCE #" + std::to_string(label(nauo)) +
                                               " refers to a product definition the file does not have");
        const Handle(StepBasic_ProductDefinition) relating = nauo->RelatingProductDefinition();
        const Handle(StepBasic_ProductDefinition) related = nauo->RelatedProductDefinition();
        if (relating.IsNull() || related.IsNull()) continue;  // a PRODUCT_DEFINITION_REFERENCE (AP242)
        below[relating.get()].push_back(related.get());
        number.emplace(relating.get(), label(relating));
        number.emplace(related.get(), label(related));
    }
    // Depth-first, iteratively (a hostile file may chain thousands): 1 on the path, 2 done.
    std::map<const Standard_Transient*, int> state;
    for (const auto& start : below) {
        if (state[start.first] != 0) continue;
        std::vector<std::pair<const Standard_Transient*, size_t>> stack{{start.first, 0}};
        state[start.first] = 1;
        while (!stack.empty()) {
            auto& [node, next] = stack.back();
            const auto found = below.find(node);
            if (found == below.end() || next >= found->second.size()) {
                state[node] = 2;
                stack.pop_back();
                continue;
            }
            const Standard_Transient* child = found->second[next++];
            if (state[child] == 1)
                throw geom::ReadError(path, 0, "the assembly contains itself: product definition #" +
                                                   std::to_string(number[child]) +
                                                   " is its own component (NEXT_ASSEMBLY_USAGE_OCCURRENCE cycle)");
            if (state[child] == 2) continue;
            if (static_cast<int>(stack.size()) >= kMaxAssemblyDepth)
                throw geom::ReadError(path, 0, "assembly nesting deeper than " + std::to_string(kMaxAssemblyDepth) +
                                                   " levels (NEXT_ASSEMBLY_USAGE_OCCURRENCE chain)");
            state[child] = 1;
            stack.emplace_back(child, 0);
        }
    }
}

// The XCAF document of one read. NewDocument registers it with the application,
// which keeps every document it made until Close: without this, each STEP read
// left its whole document (every shape) allocated for the life of the process.
class ScratchDocument {
public:
    ScratchDocument() { XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc_); }
    ~ScratchDocument() {
        try {
            if (!doc_.IsNull() && doc_->IsOpened()) XCAFApp_Application::GetApplication()->Close(doc_);
        } catch (...) {  // Standard_Failure from a damaged document: nothing more to free
        }
    }
    ScratchDocument(const ScratchDocument&) = delete;
    ScratchDocument& operator=(const ScratchDocument&) = delete;
    Handle(TDocStd_Document)& get() { return doc_; }

private:
    Handle(TDocStd_Document) doc_;
};

// Progress: parsing (ReadFile reports nothing) up to kParseShare, the transfer (with
// OCCT's healing) up to kTransferShare, the translation after it.
constexpr double kParseShare = 0.3;
constexpr double kTransferShare = 0.85;

// Each stage of OCCT's work runs in a signal-catching scope of its own (occt_guarded):
// the parse (ReadFile), the transfer (with its shape healing) and the walk of the
// document; each face's translation and healing have theirs (occt_shape.cpp). A
// memory fault in any of them is thrown as a Standard_Failure from that scope, and
// everything made out here (the XCAF document, closed by ScratchDocument; the reader;
// the progress indicator; the model) is destroyed as after any exception. A single
// scope around the whole read (as before) skipped all of it: the longjmp passes over
// destructors, which left the document registered with the application (leaked).
geom::Model read_step_unguarded(const std::string& path, const ReadOptions& options) {
    ReadMonitor monitor(path, options);
    monitor.stage(0.0, kParseShare);
    monitor.report(0.0);
    check_step_header(path);
    {
        std::ifstream text(path, std::ios::binary);
        check_step_instance_names(text, path);
    }
    ScratchDocument scratch;
    Handle(TDocStd_Document)& doc = scratch.get();
    STEPCAFControl_Reader reader;
    reader.SetColorMode(true);
    reader.SetNameMode(true);
    const IFSelect_ReturnStatus read = occt_guarded([&] { return reader.ReadFile(path.c_str()); });
    if (read != IFSelect_RetDone) {
        const std::string why = occt_guarded([&] { return read_failures(reader); });
        throw geom::ReadError(path, 0, "Open CASCADE cannot read this file as STEP" +
                                           (why.empty() ? std::string() : ": " + why));
    }
    occt_guarded([&] { check_assembly_graph(path, reader.ChangeReader().WS()->Model()); });
    monitor.report(1.0);
    monitor.check();
    monitor.stage(kParseShare, kTransferShare);
    Handle(OcctProgress) progress = new OcctProgress(monitor);
    const bool transferred = occt_guarded([&] { return reader.Transfer(doc, progress->Start()); });
    monitor.check();  // a user break ends the transfer early, with or without shapes
    if (!transferred) {
        const std::string why = occt_guarded([&] { return read_failures(reader); });
        throw OcctLeavesFile(path, 0, "Open CASCADE transfers no shape from the STEP file" +
                                          (why.empty() ? std::string() : ": " + why));
    }
    StepStyles styles(doc);

    geom::Model model;
    model.units = "mm";  // OCCT converts lengths to xstep.cad.unit, millimetres by default
    model.scale_to_metres = 1e-3;
    TDF_LabelSequence roots;
    occt_guarded([&] { styles.shapes()->GetFreeShapes(roots); });
    monitor.stage(kTransferShare, 1.0);
    AssemblyWalker walker(model, styles, monitor);
    for (int i = 1; i <= roots.Length(); ++i) {
        monitor.report(static_cast<double>(i - 1) / roots.Length());
        const TDF_Label root = roots.Value(i);
        const Eigen::Affine3d placement =
            occt_guarded([&] { return to_eigen(XCAFDoc_ShapeTool::GetLocation(root).Transformation()); });
        walker.walk(root, placement, {}, label_name(root), 0);
    }
    monitor.report(1.0);
    drop_trivial_instances(model);
    if (model.faces.empty()) {
        for (const std::string& w : model.warnings)
            if (w.rfind("face ", 0) == 0) throw geom::ReadError(path, 0, "no face of the STEP file converts (" + w + ")");
        throw OcctLeavesFile(path, 0, "the STEP file has no exact faces (B-rep surfaces); tessellated-only or "
                                      "wireframe STEP is not supported");
    }
    return model;
}

}  // namespace

bool step_supported() { return true; }

geom::Model read_step(const std::string& path, const ReadOptions& options) {
    std::string not_own;  // why trimkit's own reader left the file to OCCT (kAuto)
    if (options.step_reader != StepReader::kOcct) {
        try {
            return read_step_own(path, options);
        } catch (const UnsupportedStepEntity& e) {
            if (options.step_reader == StepReader::kOwn)
                throw geom::ReadError(path, 0, std::string("trimkit's own STEP reader does not take this file: ") + e.what());
            not_own = e.what();
        }
    }
    try {
        geom::Model model = read_step_occt(path, options);
        if (!not_own.empty()) model.warnings.push_back("read through Open CASCADE: " + not_own);
        return model;
    } catch (const OcctLeavesFile& occt) {
        if (options.step_reader != StepReader::kOcct) throw;
        try {
            geom::Model model = read_step_own(path, options);
            model.warnings.insert(model.warnings.begin(), occt.reason() + "; read by trimkit's own STEP reader");
            return model;
        } catch (const ReadStopped&) {
            throw;
        } catch (const std::exception&) {
            throw occt;  // the own reader's reason would hide OCCT's
        }
    }
}

geom::Model read_step_occt(const std::string& path, const ReadOptions& options) {
    silence_occt_stdout();
    try {
        OcctSignalGuard guard;
        // The last resort, for a fault in an OCCT call outside the scopes of
        // read_step_unguarded (constructors, destructors): caught, without their cleanup.
        OCC_CATCH_SIGNALS
        return read_step_unguarded(path, options);
    } catch (const Standard_Failure& e) {
        throw geom::ReadError(path, 0, "Open CASCADE failed (a damaged file?): " + failure_text(e));
    } catch (const geom::ReadError&) {
        throw;
    } catch (const ReadStopped&) {
        throw;
    } catch (const std::runtime_error& e) {
        throw geom::ReadError(path, 0, e.what());
    }
}

}  // namespace trimkit::io
