// trimkit tbp mesh|intersect|trim|inside|from-mesh: TBP solids ([Garcia]) from
// the command line. Solids are .tbp files (io/tbp_format.h); meshes are
// written by extension (.obj .ply .stl .glb).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "arguments.h"
#include "commands.h"
#include "geom/error.h"
#include "io/json_writer.h"
#include "io/read_mesh.h"
#include "io/tbp_format.h"
#include "io/write_mesh.h"
#include "mesh/open_edges.h"
#include "mesh/weld_vertices.h"
#include "tbp/from_mesh.h"
#include "tbp/intersect_patches.h"
#include "tbp/point_in_solid.h"
#include "tbp/polygonize.h"
#include "tbp/trim_patch.h"

namespace trimkit::cli {
namespace {

// f() with a geom::InvalidInput from the solid or mesh read from `path` (a patch
// without area, a vertex without a normal) turned into ReadError(path, ...), so the
// error line names the input file: "trimkit: FILE: pn_triangles: vertex 0 ...".
template <class F>
auto naming_input(const std::string& path, F&& f) {
    try {
        return f();
    } catch (const geom::InvalidInput& e) {
        throw geom::ReadError(path, 0, e.what());
    }
}

const char* const kTbpUsage =
    "trimkit tbp mesh SOLID.tbp -o OUT [--levels L] [--lod K] [--json]\n"
    "       trimkit tbp intersect A.tbp B.tbp [--levels L] [--lod K] [--json] [--no-hierarchy]\n"
    "       trimkit tbp trim TARGET.tbp TOOL.tbp --keep outside|inside -o OUT [--levels L] [--lod K] [--json]\n"
    "       trimkit tbp inside SOLID.tbp X Y Z | --points FILE [--levels L] [--lod K]\n"
    "       trimkit tbp from-mesh IN.obj -o OUT.tbp [--scheme pn|loop] [--sharp-angle DEG]";

int count_option(const Arguments& args, const std::string& name, int fallback, int minimum, int maximum) {
    const double x = args.number(name, fallback);
    if (x != std::floor(x) || x < minimum || x > maximum)
        throw UsageError("option " + name + " = " + args.value(name, "") + "; expected an integer from " +
                         std::to_string(minimum) + " to " + std::to_string(maximum));
    return static_cast<int>(x);
}

std::string json_point(const Eigen::Vector3d& p) {
    return "[" + io::json_number(p.x()) + "," + io::json_number(p.y()) + "," + io::json_number(p.z()) + "]";
}

std::string output_path(const Arguments& args) {
    if (!args.has("--output")) throw UsageError("missing -o OUT\nusage: " + std::string(kTbpUsage));
    return args.value("--output", "");
}

int run_mesh_tbp(const std::vector<std::string>& argv) {
    const Arguments args(argv, {"--json"}, {"--output", "--levels", "--lod"});
    args.expect_positionals(1, kTbpUsage);
    const tbp::TbpSolid solid = io::read_tbp(args.positionals()[0]);
    tbp::PolygonizeOptions o;
    o.level = count_option(args, "--levels", 2, 0, 12);
    o.lod = count_option(args, "--lod", 3, 0, 63);
    o.keep_split_normals = true;
    const mesh::Mesh m = naming_input(args.positionals()[0], [&] { return tbp::polygonize(solid, o); });
    io::write_mesh(output_path(args), m);
    mesh::WeldOptions weld;  // open edges counted on positions only (split normals are not cracks)
    mesh::Mesh positions_only;
    positions_only.positions = m.positions;
    positions_only.triangles = m.triangles;
    weld.tolerance = tbp::kWeldRelativeTolerance * mesh::bounding_box(m).diagonal().norm();
    mesh::weld_vertices(positions_only, weld);
    const std::size_t open = mesh::count_open_edges(positions_only);
    if (args.flag("--json"))
        std::cout << "{\"patches\":" << solid.patches.size() << ",\"vertices\":" << m.vertex_count()
                  << ",\"triangles\":" << m.triangle_count() << ",\"open_edges\":" << open << "}\n";
    else
        std::cout << solid.patches.size() << " patches -> " << m.triangle_count() << " triangles, " << open
                  << " open edges\n";
    return 0;
}

int run_intersect(const std::vector<std::string>& argv) {
    const Arguments args(argv, {"--json", "--no-hierarchy"}, {"--levels", "--lod"});
    args.expect_positionals(2, kTbpUsage);
    const tbp::TbpSolid a = io::read_tbp(args.positionals()[0]);
    const tbp::TbpSolid b = io::read_tbp(args.positionals()[1]);
    const int levels = count_option(args, "--levels", 2, 0, 8), lod = count_option(args, "--lod", 3, 0, 31);
    const auto start = std::chrono::steady_clock::now();
    const auto ha = tbp::build_hierarchies(a, levels, lod), hb = tbp::build_hierarchies(b, levels, lod);
    const tbp::PatchIntersection all = tbp::intersect_solids(ha, hb, !args.flag("--no-hierarchy"));
    const tbp::IntersectionStats& total = all.stats;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const int components = static_cast<int>(all.components.size()), junctions = static_cast<int>(all.junctions.size());
    int closed = 0;
    std::size_t points = 0;
    for (const auto& c : all.components) closed += c.closed, points += c.points.size();
    if (args.flag("--json")) {
        std::ostringstream s;
        s << "{\"components\":[";
        for (std::size_t n = 0; n < all.components.size(); ++n) {
            const auto& c = all.components[n];
            s << (n ? "," : "") << "{\"closed\":" << (c.closed ? "true" : "false") << ",\"points\":[";
            for (std::size_t k = 0; k < c.points.size(); ++k) s << (k ? "," : "") << json_point(c.points[k].position);
            s << "]}";
        }
        s << "],\"junction_points\":[";
        for (std::size_t n = 0; n < all.junctions.size(); ++n) s << (n ? "," : "") << json_point(all.junctions[n]);
        s << "],\"closed\":" << closed << ",\"open\":" << components - closed << ",\"junctions\":" << junctions
          << ",\"points\":" << points << ",\"box_tests\":" << total.box_tests
          << ",\"triangle_tests\":" << total.triangle_tests << ",\"segments\":" << total.segments
          << ",\"seconds\":" << io::json_number(seconds) << "}";
        std::cout << s.str() << "\n";
    } else {
        std::printf("%d components (%d closed, %d open), %d Y junctions, %zu points\n", components, closed,
                    components - closed, junctions, points);
        std::printf("%lld box tests, %lld triangle tests, %lld segments, %.3f s\n", total.box_tests,
                    total.triangle_tests, total.segments, seconds);
    }
    return 0;
}

int run_trim(const std::vector<std::string>& argv) {
    const Arguments args(argv, {"--json"}, {"--output", "--keep", "--levels", "--lod"});
    args.expect_positionals(2, kTbpUsage);
    tbp::TrimOptions o;
    const std::string keep = args.value("--keep", "outside");
    if (keep != "outside" && keep != "inside")
        throw UsageError("option --keep = " + keep + "; expected outside or inside");
    o.keep = keep == "outside" ? tbp::Keep::kOutside : tbp::Keep::kInside;
    o.levels = count_option(args, "--levels", 2, 0, 8);
    o.lod = count_option(args, "--lod", 3, 0, 31);
    const std::string out = output_path(args);
    const tbp::TbpSolid target = io::read_tbp(args.positionals()[0]);
    const tbp::TbpSolid tool = io::read_tbp(args.positionals()[1]);
    std::vector<tbp::TrimResult> parts;
    const mesh::Mesh m = tbp::trim_solid(target, tool, o, &parts);
    io::write_mesh(out, m);
    long long tri = 0, boxes = 0, segments = 0;
    double seconds = 0;
    std::size_t loops = 0, sub = 0;
    for (const auto& p : parts) {
        tri += p.stats.intersection.triangle_tests;
        boxes += p.stats.intersection.box_tests;
        segments += p.stats.boundary_segments;
        seconds += p.stats.seconds;
        loops += p.boundaries.size();
        sub += p.untrimmed.size();
    }
    if (args.flag("--json"))
        std::cout << "{\"patches\":" << target.patches.size() << ",\"triangles\":" << m.triangle_count()
                  << ",\"area\":" << io::json_number(mesh::surface_area(m)) << ",\"boundary_loops\":" << loops
                  << ",\"boundary_segments\":" << segments << ",\"untrimmed_subpatches\":" << sub
                  << ",\"box_tests\":" << boxes << ",\"triangle_tests\":" << tri
                  << ",\"seconds\":" << io::json_number(seconds) << "}\n";
    else
        std::printf("%zu patches -> %zu triangles, area %.9g, %zu boundary loops (%lld segments on cuts), "
                    "%zu untrimmed sub-TBPs; %lld triangle tests, %.3f s\n",
                    target.patches.size(), m.triangle_count(), mesh::surface_area(m), loops, segments, sub, tri, seconds);
    return 0;
}

int run_inside(const std::vector<std::string>& argv) {
    const Arguments args(argv, {}, {"--points", "--levels", "--lod"});
    const bool file = args.has("--points");
    args.expect_positionals(file ? 1 : 4, kTbpUsage);
    const tbp::TbpSolid solid = io::read_tbp(args.positionals()[0]);
    const auto h = tbp::build_hierarchies(solid, count_option(args, "--levels", 2, 0, 8),
                                          count_option(args, "--lod", 3, 0, 31));
    auto name = [](tbp::Containment c) {
        return c == tbp::Containment::kInside ? "inside" : c == tbp::Containment::kOutside ? "outside" : "boundary";
    };
    auto parse = [](const std::string& s, const std::string& where) {
        char* end = nullptr;
        const double x = std::strtod(s.c_str(), &end);
        if (s.empty() || *end != '\0' || !std::isfinite(x)) throw geom::ReadError(where, 0, "'" + s + "' is not a number");
        return x;
    };
    if (!file) {
        Eigen::Vector3d p;
        for (int a = 0; a < 3; ++a) {
            const std::string& s = args.positionals()[1 + a];
            char* end = nullptr;
            p[a] = std::strtod(s.c_str(), &end);
            if (s.empty() || *end != '\0' || !std::isfinite(p[a])) throw UsageError("coordinate '" + s + "' is not a number");
        }
        std::cout << name(tbp::point_in_solid(h, p)) << "\n";
        return 0;
    }
    const std::string path = args.value("--points", "");
    std::ifstream in(path);
    if (!in) throw geom::ReadError(path, 0, "cannot open the file");
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        std::istringstream words(line);
        std::vector<std::string> w;
        for (std::string x; words >> x;) w.push_back(x);
        if (w.empty()) continue;
        const std::string where = path + ":" + std::to_string(number);
        if (w.size() != 3) throw geom::ReadError(path, number, "expected three coordinates, found " + std::to_string(w.size()));
        const Eigen::Vector3d p(parse(w[0], where), parse(w[1], where), parse(w[2], where));
        std::cout << name(tbp::point_in_solid(h, p)) << "\n";
    }
    return 0;
}

// tbp from-mesh's default crease angle, as Blender's auto smooth.
constexpr double kSharpAngleDegrees = 30.0;

int run_from_mesh(const std::vector<std::string>& argv) {
    const Arguments args(argv, {}, {"--output", "--scheme", "--sharp-angle"});
    args.expect_positionals(1, kTbpUsage);
    const std::string scheme = args.value("--scheme", "pn");
    // pn: sides whose faces meet at more than this stay creases (a cube stays a cube).
    const double sharp_degrees = args.number("--sharp-angle", kSharpAngleDegrees);
    if (!(sharp_degrees >= 0.0 && sharp_degrees <= 180.0))
        throw UsageError("option --sharp-angle = " + geom::format_value(sharp_degrees) + "; expected 0 to 180 degrees");
    if (scheme != "pn" && scheme != "loop") throw UsageError("option --scheme = " + scheme + "; expected pn or loop");
    const std::string out = output_path(args);
    const mesh::Mesh cage = io::read_mesh(args.positionals()[0]);
    // The solid is named after its mesh file ("bracket" from bracket.obj), as importers name objects.
    const std::string name = std::filesystem::path(args.positionals()[0]).stem().string();
    if (scheme == "pn") {
        const double sharp = sharp_degrees >= 180.0 ? tbp::kNoSharpEdges : sharp_degrees * M_PI / 180.0;
        tbp::TbpSolid solid = naming_input(args.positionals()[0], [&] { return tbp::pn_triangles(cage, sharp); });
        solid.name = name;
        io::write_tbp(solid, out);
        std::cout << solid.patches.size() << " cubic PN patches -> " << out << "\n";
    } else {
        tbp::LoopConversion c = naming_input(args.positionals()[0], [&] { return tbp::loop_quartics(cage); });
        c.solid.name = name;
        io::write_tbp(c.solid, out);
        std::printf("%zu quartic Loop patches -> %s; %d irregular patches approximated, max error %.6g\n",
                    c.solid.patches.size(), out.c_str(), c.approximated, c.max_error);
    }
    return 0;
}

}  // namespace

int run_tbp(const std::vector<std::string>& args) {
    if (args.empty()) throw UsageError(std::string("usage: ") + kTbpUsage);
    const std::string sub = args[0];
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (sub == "mesh") return run_mesh_tbp(rest);
    if (sub == "intersect") return run_intersect(rest);
    if (sub == "trim") return run_trim(rest);
    if (sub == "inside") return run_inside(rest);
    if (sub == "from-mesh") return run_from_mesh(rest);
    throw UsageError("unknown tbp command '" + sub + "'\nusage: " + kTbpUsage);
}

}  // namespace trimkit::cli
