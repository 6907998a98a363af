// trimkit check MODEL MESH: the two-sided deviation between a mesh (read back from
// .obj .ply .stl .glb) and the exact trimmed faces of the model, the area ratio
// and the open edges (tess::measure_deviation).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "arguments.h"
#include "commands.h"
#include "fit/model_deviation.h"
#include "io/json_writer.h"
#include "io/read_mesh.h"
#include "geom/flatten_instances.h"
#include "io/read_model.h"
#include "read_options.h"
#include "tess/measure_deviation.h"

namespace trimkit::cli {
namespace {

const char* const kCheckUsage = "trimkit check MODEL MESH [--json] [--samples N] [--threads N] [--read-timeout SECONDS] [--step-reader occt|own|auto] | trimkit check MODEL_A MODEL_B";

int count_option(const Arguments& args, const std::string& name, int fallback, int minimum) {
    const double x = args.number(name, fallback);
    if (x != std::floor(x) || x < minimum || x > 1e6)
        throw UsageError("option " + name + " = " + args.value(name, "") + "; expected an integer >= " +
                         std::to_string(minimum));
    return static_cast<int>(x);
}

std::string json_point(const Eigen::Vector3d& p) {
    return "[" + io::json_number(p.x()) + "," + io::json_number(p.y()) + "," + io::json_number(p.z()) + "]";
}

std::string json_direction(const tess::DirectionDeviation& d, const std::string& extra) {
    return "{\"max\":" + io::json_number(d.max) + ",\"mean\":" + io::json_number(d.mean) + extra +
           ",\"samples\":" + std::to_string(d.samples) + ",\"worst\":{\"face\":" +
           std::to_string(d.worst.face) + ",\"point\":" + json_point(d.worst.point) + "}}";
}

std::string json_list(const std::vector<double>& x) {
    std::string s = "[";
    for (std::size_t i = 0; i < x.size(); ++i) s += (i ? "," : "") + io::json_number(x[i]);
    return s + "]";
}

std::string to_json(const tess::DeviationReport& r, double seconds) {
    std::string s = "{";
    s += "\"mesh_to_surface\":" + json_direction(r.mesh_to_surface, ",\"max_uv\":" + io::json_number(r.mesh_to_surface_max_uv));
    s += ",\"surface_to_mesh\":" + json_direction(r.surface_to_mesh, "");
    s += ",\"area_mesh\":" + io::json_number(r.area_mesh);
    s += ",\"area_exact\":" + io::json_number(r.area_exact);
    s += ",\"area_ratio\":" + io::json_number(r.area_ratio);
    s += ",\"open_edges\":" + std::to_string(r.open_edges);
    s += ",\"faces\":" + std::to_string(r.faces);
    s += ",\"triangles\":" + std::to_string(r.triangles);
    s += ",\"face_mesh_to_surface\":" + json_list(r.face_mesh_to_surface);
    s += ",\"face_surface_to_mesh\":" + json_list(r.face_surface_to_mesh);
    s += ",\"face_area_exact\":" + json_list(r.face_area_exact);
    s += ",\"warnings\":[";
    for (std::size_t i = 0; i < r.warnings.size(); ++i) s += (i ? "," : "") + io::json_string(r.warnings[i]);
    s += "],\"seconds\":" + io::json_number(seconds) + "}";
    return s;
}

std::string to_text(const tess::DeviationReport& r, double seconds) {
    char buf[1024];
    std::string s;
    const auto where = [](const tess::DeviationLocation& w) {
        char b[256];
        std::snprintf(b, sizeof b, "face %d at (%.6g, %.6g, %.6g)", w.face, w.point.x(), w.point.y(), w.point.z());
        return std::string(b);
    };
    std::snprintf(buf, sizeof buf, "faces %d, triangles %zu\n", r.faces, r.triangles);
    s += buf;
    std::snprintf(buf, sizeof buf, "mesh -> surface: max %.6g, mean %.6g (%zu samples), worst %s\n",
                  r.mesh_to_surface.max, r.mesh_to_surface.mean, r.mesh_to_surface.samples,
                  where(r.mesh_to_surface.worst).c_str());
    s += buf;
    if (!std::isnan(r.mesh_to_surface_max_uv)) {
        std::snprintf(buf, sizeof buf, "                 max at the mesh's (u,v): %.6g\n", r.mesh_to_surface_max_uv);
        s += buf;
    }
    std::snprintf(buf, sizeof buf, "surface -> mesh: max %.6g, mean %.6g (%zu samples), worst %s\n",
                  r.surface_to_mesh.max, r.surface_to_mesh.mean, r.surface_to_mesh.samples,
                  where(r.surface_to_mesh.worst).c_str());
    s += buf;
    std::snprintf(buf, sizeof buf, "area: mesh %.10g, exact %.10g, ratio %.6f\nopen edges: %zu\n", r.area_mesh,
                  r.area_exact, r.area_ratio, r.open_edges);
    s += buf;
    for (const auto& w : r.warnings) s += "warning: " + w + "\n";
    std::snprintf(buf, sizeof buf, "seconds: %.3f\n", seconds);
    return s + buf;
}

bool is_model_path(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".igs" || ext == ".iges" || ext == ".stp" || ext == ".step" || ext == ".brep" || ext == ".tkz";
}

// trimkit check A B with two models: the two-sided surface deviation per face.
int check_models(const std::string& a_path, const std::string& b_path) {
    // Every placed face on both sides (extend writes IGES with instances flattened).
    const geom::Model a = geom::flatten_instances(io::read_model(a_path));
    const geom::Model b = geom::flatten_instances(io::read_model(b_path));
    const std::vector<fit::FaceDeviation> d = fit::model_deviation(a, b);
    double worst = 0;
    int worst_face = -1;
    for (std::size_t f = 0; f < d.size(); ++f) {
        std::printf("face %zu: A->B avg %.4g max %.4g, B->A avg %.4g max %.4g\n", f, d[f].a_to_b_avg, d[f].a_to_b_max,
                    d[f].b_to_a_avg, d[f].b_to_a_max);
        if (d[f].max() >= worst) worst = d[f].max(), worst_face = static_cast<int>(f);
    }
    std::printf("faces %zu, two-sided surface deviation max %.6g (face %d)\n", d.size(), worst, worst_face);
    return 0;
}

}  // namespace

int run_check(const std::vector<std::string>& argv) {
    const Arguments args(argv, {"--json"}, {"--samples", "--threads", "--read-timeout", "--step-reader"});
    args.expect_positionals(2, kCheckUsage);
    if (is_model_path(args.positionals()[1])) return check_models(args.positionals()[0], args.positionals()[1]);
    tess::DeviationOptions options;
    options.samples = count_option(args, "--samples", options.samples, 1);
    options.threads = count_option(args, "--threads", options.threads, 0);
    const auto start = std::chrono::steady_clock::now();
    const geom::Model model = geom::flatten_instances(io::read_model(args.positionals()[0], read_options(args)));
    const mesh::Mesh mesh = io::read_mesh(args.positionals()[1]);
    const tess::DeviationReport report = tess::measure_deviation(model, mesh, options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << (args.flag("--json") ? to_json(report, seconds) + "\n" : to_text(report, seconds));
    return 0;
}

}  // namespace trimkit::cli
