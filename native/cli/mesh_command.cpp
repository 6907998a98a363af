// trimkit mesh MODEL -o OUT --tolerance T [--relative] [--angle A]
//   [--mode guaranteed|approximate] [--trim-method bezier3d|yang|param] [--threads N]
//   [--face-timeout SECONDS] [--read-timeout SECONDS] [--json] [--strict]
// Each face left out of the mesh (failed_faces) gets one stderr line,
// "trimkit: MODEL: face N: reason"; the mesh of the other faces is still written.
// The reader's own warnings (a face it could not translate: "face 32 skipped: ...")
// get one stderr line each too, the first kListedWarnings of them; --json lists the
// faces the reader left out under "unread_faces".
// --strict: exit status 3 when any face failed or was left out by the reader.
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "arguments.h"
#include "commands.h"
#include "io/json_writer.h"
#include "geom/flatten_instances.h"
#include "io/read_model.h"
#include "io/write_mesh.h"
#include "read_options.h"
#include "tess/tessellate_model.h"

namespace trimkit::cli {
namespace {

const char* const kMeshUsage =
    "trimkit mesh MODEL -o OUT --tolerance T [--relative] [--angle DEGREES] "
    "[--mode guaranteed|approximate] [--trim-method bezier3d|yang|param] [--threads N] "
    "[--face-timeout SECONDS] [--read-timeout SECONDS] [--step-reader occt|own|auto] [--json] [--strict]";

// Exit status of --strict when a face failed (0 success, 1 internal, 2 bad input).
constexpr int kFailedFacesStatus = 3;
// Warnings listed one per stderr line before the rest are counted.
constexpr size_t kListedWarnings = 10;

using Clock = std::chrono::steady_clock;

// The first kListedWarnings of `warnings` on stderr, one per line, then how many
// `more` there are.
void print_warnings(const std::string& path, const std::vector<std::string>& warnings, const std::string& more) {
    for (size_t k = 0; k < warnings.size() && k < kListedWarnings; ++k)
        std::cerr << "trimkit: " << path << ": warning: " << warnings[k] << "\n";
    if (warnings.size() > kListedWarnings)
        std::cerr << "trimkit: " << path << ": warning: " << warnings.size() - kListedWarnings << " more " << more
                  << "\n";
}

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

int run_mesh(const std::vector<std::string>& argv) {
    const Arguments args(argv, {"--json", "--relative", "--strict"},
                         {"-o", "--output", "--tolerance", "--angle", "--mode", "--trim-method", "--threads",
                          "--face-timeout", "--read-timeout", "--step-reader"});
    args.expect_positionals(1, kMeshUsage);
    const std::string& path = args.positionals()[0];
    const std::string out = args.has("-o") ? args.value("-o", "") : args.value("--output", "");
    if (out.empty()) throw UsageError(std::string("missing -o OUT; usage: ") + kMeshUsage);
    if (!args.has("--tolerance")) throw UsageError(std::string("missing --tolerance; usage: ") + kMeshUsage);

    tess::TessellationOptions options;
    const double tolerance = args.number("--tolerance", 0.0);
    if (!(tolerance > 0.0)) throw UsageError("--tolerance must be > 0");
    options.angle = args.number("--angle", 30.0) * M_PI / 180.0;
    const std::string mode = args.value("--mode", "guaranteed");
    if (mode == "guaranteed")
        options.mode = tess::ErrorMode::kGuaranteed;
    else if (mode == "approximate")
        options.mode = tess::ErrorMode::kApproximate;
    else
        throw UsageError("--mode '" + mode + "'; expected guaranteed or approximate");
    const std::string method = args.value("--trim-method", "bezier3d");
    if (method == "bezier3d")
        options.trim_method = tess::TrimMethod::kBezier3d;
    else if (method == "yang")
        options.trim_method = tess::TrimMethod::kYang;
    else if (method == "param")
        options.trim_method = tess::TrimMethod::kParam;
    else
        throw UsageError("--trim-method '" + method + "'; expected bezier3d, yang or param");
    const double threads = args.number("--threads", 0.0);
    if (threads < 0 || threads != std::floor(threads)) throw UsageError("--threads must be an integer >= 0");
    options.threads = static_cast<int>(threads);
    options.face_timeout = args.number("--face-timeout", tess::kDefaultFaceTimeout);
    if (!(options.face_timeout >= 0.0)) throw UsageError("--face-timeout must be seconds >= 0 (0 = no limit)");

    const auto start_all = Clock::now();
    auto start = Clock::now();
    const geom::Model model = geom::flatten_instances(io::read_model(path, read_options(args)));
    const double read_seconds = seconds_since(start);
    options.tolerance = tolerance;
    if (args.flag("--relative")) {
        const double diagonal = tess::model_diagonal(model, options.threads);
        if (!(diagonal > 0.0)) throw UsageError(path + ": --relative needs a model with faces");
        options.tolerance = tolerance * diagonal;
    }
    const tess::TessellationResult result = tess::tessellate_model(model, options);
    start = Clock::now();
    io::write_mesh(out, result.mesh);
    const double write_seconds = seconds_since(start);
    const double total = seconds_since(start_all);

    if (args.flag("--json")) {
        using io::json_number;
        using io::json_string;
        std::ostringstream json;
        json << "{\"faces\": " << result.faces << ", \"faces_meshed\": " << result.faces_meshed
             << ", \"failed_faces\": [";
        for (size_t k = 0; k < result.failed_faces.size(); ++k) {
            const tess::FailedFace& failed = result.failed_faces[k];
            json << (k ? ", " : "") << "{\"face\": " << failed.face << ", \"reason\": " << json_string(failed.reason)
                 << ", \"defect\": " << json_string(failed.defect)
                 << ", \"area_mesh\": " << json_number(failed.area_mesh)
                 << ", \"area_exact\": " << json_number(failed.area_exact)
                 << ", \"area_bound\": " << json_number(failed.area_bound)
                 << ", \"boundary_gap\": " << json_number(failed.boundary_gap)
                 << ", \"boundary_bound\": " << json_number(failed.boundary_bound)
                 << ", \"seconds\": " << json_number(failed.seconds) << "}";
        }
        json << "], \"triangles\": " << result.mesh.triangle_count()
             << ", \"vertices\": " << result.mesh.vertex_count() << ", \"open_edges\": " << result.open_edges
             << ", \"tolerance\": " << json_number(result.tolerance) << ", \"warnings\": [";
        for (size_t k = 0; k < result.warnings.size(); ++k) json << (k ? ", " : "") << json_string(result.warnings[k]);
        json << "], \"read_warnings\": [";
        for (size_t k = 0; k < model.warnings.size(); ++k) json << (k ? ", " : "") << json_string(model.warnings[k]);
        json << "], \"unread_faces\": [";
        for (size_t k = 0; k < model.unread_faces.size(); ++k)
            json << (k ? ", " : "") << json_string(model.unread_faces[k]);
        json << "]"
             << ", \"seconds\": {\"read\": " << json_number(read_seconds)
             << ", \"trim\": " << json_number(result.seconds.trim)
             << ", \"surface\": " << json_number(result.seconds.surface)
             << ", \"triangulate\": " << json_number(result.seconds.triangulate)
             << ", \"weld\": " << json_number(result.seconds.weld)
             << ", \"verify\": " << json_number(result.seconds.verify) << ", \"write\": " << json_number(write_seconds)
             << ", \"total\": " << json_number(total) << "}}";
        std::cout << json.str() << "\n";
    } else {
        std::cout << out << ": " << result.mesh.triangle_count() << " triangles, " << result.mesh.vertex_count()
                  << " vertices, " << result.faces_meshed << "/" << result.faces << " faces meshed, "
                  << result.open_edges << " open edges, tolerance " << result.tolerance << ", "
                  << total << " s\n";
    }
    print_warnings(path, model.warnings, "warnings from reading the file (trimkit info lists them)");
    // Edges farther from a face than the tolerance: the mesh is within the file's own
    // edge gap there, not within T; say so, however the output is asked for.
    std::vector<std::string> off_face_edges;
    for (const std::string& warning : result.warnings)
        if (warning.find("(more than the tolerance") != std::string::npos) off_face_edges.push_back(warning);
    print_warnings(path, off_face_edges, "edges lie farther than the tolerance from a face (--json lists them)");
    for (const tess::FailedFace& failed : result.failed_faces) {
        const std::string prefix = "face " + std::to_string(failed.face) + ": ";
        std::cerr << "trimkit: " << path << ": " << (failed.reason.rfind(prefix, 0) == 0 ? "" : prefix)
                  << failed.reason << "\n";
    }
    const bool faces_missing = !result.failed_faces.empty() || !model.unread_faces.empty();
    return args.flag("--strict") && faces_missing ? kFailedFacesStatus : 0;
}

}  // namespace trimkit::cli
